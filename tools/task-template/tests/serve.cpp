// The candidate's side of task @N@'s calls: the linked @STEM@.cpp.
#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::SampleTriangle>([](const std::vector<Vec2>& us) {
    std::vector<Point2> points;
    for (const Vec2& u : us) points.push_back(@STEM@::sampleTriangle(u));
    return points;
  });
}

}  // namespace pathlab::remote
