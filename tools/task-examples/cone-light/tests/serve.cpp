// The candidate's side of task @N@'s calls: the linked @STEM@.cpp.
#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::ConeCosThetaMax>(&@STEM@::coneCosThetaMax);
  server.serve<calls::SampleCone>([](Vec3 axis, float cosThetaMax, const std::vector<Vec2>& us) {
    std::vector<@STEM@::ConeSample> samples;
    for (const Vec2& u : us) samples.push_back(@STEM@::sampleCone(axis, cosThetaMax, u));
    return samples;
  });
  server.serve<calls::ConePdf>([](Vec3 axis, float cosThetaMax, const std::vector<Vec3>& directions) {
    std::vector<float> pdfs;
    for (const Vec3& w : directions) pdfs.push_back(@STEM@::conePdf(axis, cosThetaMax, w));
    return pdfs;
  });
}

}  // namespace pathlab::remote
