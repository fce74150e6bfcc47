// The candidate's side of task 8's calls: the linked microfacet.cpp.
#include "serve_trace.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::AlphaFromRoughness>(&alphaFromRoughness);
  server.serve<calls::GgxD>(&ggxD);
  server.serve<calls::SmithLambda>(&smithLambda);
  server.serve<calls::SmithG1>(&smithG1);
  server.serve<calls::SmithG2>(&smithG2);
  server.serve<calls::SchlickFresnelF0>(&schlickFresnelF0);
  server.serve<calls::ConductorFresnel>(&conductorFresnel);
  server.serve<calls::ConductorBrdf>(&conductorBrdf);
  server.serve<calls::SampleGgxNormal>(&sampleGgxNormal);
  server.serve<calls::SampleVisibleNormal>(&sampleVisibleNormal);
  server.serve<calls::VisibleNormalPdf>(&visibleNormalPdf);
  server.serve<calls::SampleConductor>(&sampleConductor);
  server.serve<calls::ConductorPdf>(&conductorPdf);
  server.serve<calls::PlasticBrdf>(&plasticBrdf);
  server.serve<calls::SamplePlastic>(&samplePlastic);
  server.serve<calls::PlasticPdf>(&plasticPdf);
  serveTraceCalls(server);
}

}  // namespace pathlab::remote
