// libFuzzer target for the viewer's input script (--script): any input must parse or throw
// penumbra::Error, and a parsed script must play through the controls.
#include <cstdint>
#include <string_view>

#include "interact/input_script.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        penumbra::viewer::ScriptPlayer player(penumbra::viewer::parseInputScript(text, "fuzz.txt"));
        penumbra::viewer::InputState input;
        for (int frame = 0; frame < 64 && !player.finished(); ++frame) {
            player.playFrame(input, 0.05);
            (void)penumbra::viewer::cameraInputFrom(input);
            penumbra::viewer::endInputFrame(input);
        }
    } catch (const penumbra::Error&) {
    }
    return 0;
}
