// libFuzzer target: the scene file loader. Any bytes must give a Scene or an InputError.
#include "common/input_error.h"
#include "scene/scene_json.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        chaplygin::Scene s = chaplygin::sceneFromJson(text);
        // what loads must save and load back to the same scene
        if (!(chaplygin::sceneFromJson(chaplygin::sceneToJson(s)) == s))
            __builtin_trap();
    } catch (const chaplygin::InputError&) {
    }
    return 0;
}
