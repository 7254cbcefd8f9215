// The server's frame loop, headless: what the desktop viewer's loop does with a window, done for
// the browsers' merged input. Each frame it applies what the browsers sent (keys, looks, clicks,
// drags, settings), moves the camera and the selected instance, renders the frame into the
// interactive renderer, copies it for the encoder when one is wanted, and every quarter second
// sends stats. It renders only while a browser is connected.
#pragma once

#include <functional>
#include <memory>

#include "gpu/context.h"
#include "scene/scene.h"
#include "serve/client_hub.h"
#include "serve/frame_encoder.h"
#include "serve/frame_readback.h"
#include "serve/serve_options.h"

namespace penumbra::serve {

class ServeLoop {
public:
    // Uploads the scene and makes the renderer's kernels, and gives the hub its hello: all before
    // the server listens, so the first browser finds everything ready.
    ServeLoop(const gpu::Context& ctx, Scene& scene, const ServeOptions& options, ClientHub& hub);
    ~ServeLoop();
    // Runs until stopRequested() says so (polled every frame, and every 0.1 s while nobody watches).
    void run(FrameReadback& readback, FrameEncoder& encoder, const std::function<bool()>& stopRequested);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace penumbra::serve
