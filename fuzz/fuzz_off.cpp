// libFuzzer target: read_off on arbitrary bytes.
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return kappa::fuzz::check_reader(
        data, size, [](const char* d, size_t n) { return kappa::read_off(d, n, "fuzz.off"); });
}
