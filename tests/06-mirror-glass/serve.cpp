// The candidate's side of task 6's calls: the linked mirror_glass.cpp.
#include "serve_trace.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::Reflect>(&reflect);
  server.serve<calls::Refract>(&refract);
  server.serve<calls::SchlickFresnel>(&schlickFresnel);
  server.serve<calls::SampleMirror>(&sampleMirror);
  server.serve<calls::SampleGlass>(&sampleGlass);
  serveTraceCalls(server);
}

}  // namespace pathlab::remote
