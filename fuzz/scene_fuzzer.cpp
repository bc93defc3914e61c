// libFuzzer target: any bytes as a scene file. Parsing may refuse them with
// lucent::Error; anything else (a crash, a sanitizer report, another exception)
// is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        lucent::parseSceneText(std::string(reinterpret_cast<const char*>(data), size), "/fuzz/scene.json");
    } catch (const lucent::Error&) {
    }
    return 0;
}
