// The candidate's side of image_calls.h: every suite serves it.
#pragma once

#include "image_calls.h"
#include "wire/server.h"

namespace pathlab::remote {

inline void serveImageCalls(Server& server) {
  server.serve<calls::RenderMoments>(
      [](const Scene& scene, const test::ImageOptions& options) { return test::renderMoments(scene, options); });
}

}  // namespace pathlab::remote
