// F12 / --screenshot: the display buffer (exactly what the window shows, before scaling) as a PNG.
#pragma once

#include <string>

#include "gpu/context.h"
#include "render/interactive_renderer.h"

namespace penumbra::viewer {

// The last finished frame; call only when no frame is in flight. Written atomically.
void writeScreenshot(const gpu::Context& ctx, InteractiveRenderer& renderer, const std::string& path);

}  // namespace penumbra::viewer
