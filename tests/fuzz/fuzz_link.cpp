// libFuzzer target: the scene link parser. Any bytes must give a Scene or an InputError, inflate
// to no more than the link's cap, and what a link holds must make a link that reads back to it.
#include "common/input_error.h"
#include "scene/scene_link.h"

#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    // the bytes as they come, and after the scheme (where random bytes would rarely put it)
    for (const std::string& link :
         {std::string(text), std::string(chaplygin::kSceneLinkScheme) + std::string(text)}) {
        try {
            const chaplygin::Scene scene = chaplygin::sceneFromLink(link);
            if (!(chaplygin::sceneFromLink(chaplygin::sceneToLink(scene)) == scene))
                __builtin_trap();
        } catch (const chaplygin::InputError&) {
        }
    }
    return 0;
}
