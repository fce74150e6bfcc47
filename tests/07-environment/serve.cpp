// The candidate's side of task 7's calls: the linked environment.cpp.
#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::DirectionToEquirect>(&directionToEquirect);
  server.serve<calls::EquirectToDirection>(&equirectToDirection);
  server.serve<calls::LookupEnvironment>(&lookupEnvironment);
  server.serve<calls::SampleUniformSphere>(&sampleUniformSphere);
  server.serve<calls::BuildEnvironmentDistribution>(&buildEnvironmentDistribution);
  server.serve<calls::SampleEnvironment>([](const EnvironmentDistribution& d, const std::vector<Vec2>& us) {
    std::vector<std::optional<EnvironmentSample>> samples;
    for (const Vec2& u : us) samples.push_back(sampleEnvironment(d, u));
    return samples;
  });
  server.serve<calls::EnvironmentPdf>([](const EnvironmentDistribution& d, const std::vector<Vec3>& directions) {
    std::vector<float> pdfs;
    for (const Vec3& w : directions) pdfs.push_back(environmentPdf(d, w));
    return pdfs;
  });
}

}  // namespace pathlab::remote
