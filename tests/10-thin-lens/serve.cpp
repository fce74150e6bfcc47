// The candidate's side of task 10's calls: the linked thin_lens.cpp.
#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::SampleUnitDisk>([](const std::vector<Vec2>& us) {
    std::vector<Point2> points;
    for (const Vec2& u : us) points.push_back(sampleUnitDisk(u));
    return points;
  });
  server.serve<calls::GenerateThinLensRays>(
      [](const Camera& camera, const CameraBasis& basis, const std::vector<calls::LensQuery>& queries) {
        std::vector<Ray> rays;
        for (const auto& [pinhole, u] : queries) rays.push_back(generateThinLensRay(camera, basis, pinhole, u));
        return rays;
      });
}

}  // namespace pathlab::remote
