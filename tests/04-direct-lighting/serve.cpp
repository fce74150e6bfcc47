// The candidate's side of task 4's calls: the linked direct_lighting.cpp.
#include "serve_trace.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::LambertianBrdf>(&lambertianBrdf);
  server.serve<calls::OffsetRayOrigin>(&offsetRayOrigin);
  server.serve<calls::LightDirectionTo>(&lightDirection);
  serveTraceCalls(server);
}

}  // namespace pathlab::remote
