// libFuzzer target: read_gltf on arbitrary bytes (JSON or .glb).
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return kappa::fuzz::check_reader(
        data, size, [](const char* d, size_t n) { return kappa::read_gltf(d, n, "fuzz.gltf"); });
}
