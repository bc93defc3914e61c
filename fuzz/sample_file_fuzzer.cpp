// libFuzzer target: any bytes as a sample file. The reader may refuse them with
// lucent::Error; anything else is a bug. Inputs that pass the checksum are rare,
// so the seed corpus holds valid files for the fuzzer to mutate.
#include <cstddef>
#include <cstdint>

#include "core/error.h"
#include "core/sample_set.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        lucent::parseSampleFile({reinterpret_cast<const char*>(data), size}, "fuzz.lsf");
    } catch (const lucent::Error&) {
    }
    return 0;
}
