#include "render/tuning.h"

namespace penumbra {
namespace {

RenderTuning& store() {
    static RenderTuning tuning;
    return tuning;
}

}  // namespace

const RenderTuning& renderTuning() { return store(); }

void setRenderTuning(const RenderTuning& tuning) { store() = tuning; }

}  // namespace penumbra
