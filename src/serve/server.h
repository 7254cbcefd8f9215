// `penumbra serve`: the viewer's renderer, headless, streamed to browsers (docs/SERVE.md).
#pragma once

#include "scene/scene.h"
#include "serve/serve_options.h"

namespace penumbra::serve {

// Listens, prints `penumbra: serving http://ADDRESS:PORT/` on stdout, and serves until SIGINT or
// SIGTERM. Error when the GPU or the address cannot be had.
void runServer(Scene scene, const ServeOptions& options);

}  // namespace penumbra::serve
