/// The libFuzzer entry of one fuzz target, chosen at build time by MODEFLOW_FUZZ_TARGET (a
/// function of FuzzTargets.h).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tests/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    modeflow::fuzz::MODEFLOW_FUZZ_TARGET(
        std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
