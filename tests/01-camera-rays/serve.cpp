// The candidate's side of task 1's calls: the linked camera_rays.cpp.
#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::PixelSamplePosition>(&pixelSamplePosition);
  server.serve<calls::CameraBasisOf>(&cameraBasis);
  server.serve<calls::GenerateCameraRay>(&generateCameraRay);
}

}  // namespace pathlab::remote
