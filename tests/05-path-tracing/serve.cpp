// The candidate's side of task 5's calls: the linked path_tracing.cpp.
#include "serve_trace.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::SampleDiffuseDirection>(&sampleDiffuseDirection);
  server.serve<calls::DiffuseDirectionPdf>(&diffuseDirectionPdf);
  serveTraceCalls(server);
}

}  // namespace pathlab::remote
