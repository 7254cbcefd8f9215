// What `penumbra serve` is asked for (src/app/serve_command.cpp fills it).
#pragma once

#include <cstdint>
#include <string>

#include "render/view_settings.h"
#include "serve/frame_encoder.h"
#include "serve/frame_pacer.h"

namespace penumbra::serve {

struct ServeOptions {
    std::string bind = "127.0.0.1";
    unsigned short port = 8080;  // 0: any free port (printed)
    std::string token;           // "" : none
    std::string device;
    std::uint32_t width = 1280, height = 720;  // the picture at resolution scale 1
    ViewSettings view;                          // the starting settings (spp, denoise, debug, ...)
    bool fly = false;
    bool phantom = true;  // --no-phantom: the dungeon's phantom starts switched off
    EncodeOptions encode;
    PaceOptions pace;
};

}  // namespace penumbra::serve
