// Sets the renderer's tuning (render/tuning.h: the kernel design, wavefront switches, generic
// kernels) for a scope, then puts back what was there: how tests steer the kernels.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "render/tuning.h"

namespace penumbra::test {

class ScopedTuning {
public:
    ScopedTuning() : saved_(renderTuning()) {}
    ~ScopedTuning() { setRenderTuning(saved_); }
    ScopedTuning(const ScopedTuning&) = delete;
    ScopedTuning& operator=(const ScopedTuning&) = delete;

    // "mega", "wavefront" or "auto", as tests name their parameters.
    ScopedTuning& kernel(const std::string& name) {
        return edit([&](RenderTuning& t) {
            if (name == "mega")
                t.traceKernel = TraceKernel::Megakernel;
            else if (name == "wavefront")
                t.traceKernel = TraceKernel::Wavefront;
            else if (name == "auto")
                t.traceKernel = TraceKernel::Auto;
            else
                throw std::invalid_argument("no trace kernel named " + name);
        });
    }
    ScopedTuning& tailPaths(std::uint32_t paths) {
        return edit([&](RenderTuning& t) { t.waveTailPaths = paths; });
    }
    ScopedTuning& stageTimes(bool on) {
        return edit([&](RenderTuning& t) { t.waveStageTimes = on; });
    }
    ScopedTuning& genericKernel(bool on) {
        return edit([&](RenderTuning& t) { t.genericKernel = on; });
    }
    ScopedTuning& restTree(bool on) {
        return edit([&](RenderTuning& t) { t.restTree = on; });
    }

private:
    template <typename Edit>
    ScopedTuning& edit(Edit&& change) {
        RenderTuning t = renderTuning();
        change(t);
        setRenderTuning(t);
        return *this;
    }
    RenderTuning saved_;
};

}  // namespace penumbra::test
