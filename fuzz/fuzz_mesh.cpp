// libFuzzer target: format sniffing (read_mesh with an unknown format) on
// arbitrary bytes, reaching every reader.
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return kappa::fuzz::check_reader(data, size, [](const char* d, size_t n) {
        return kappa::read_mesh(d, n, kappa::MeshFormat::Unknown, "fuzz.mesh");
    });
}
