// libFuzzer target for the NFF reader: any bytes either parse into a scene that keeps the
// contract of common/nff.hpp or throw InputError with a well-formed one-line message. Anything
// else -- a crash, a sanitizer report, another exception, a broken contract, a hang -- is a finding.
// How to build and run it: tests/fuzz/README.md.
#include "tests/fuzz/nff_contract.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::string name = "fuzz.nff";
    std::istringstream in(input);
    std::string broken;
    try {
        broken = rt::nff_contract::scene_broken(rt::parse_nff(in, name));
    } catch (const rt::InputError& e) {
        broken = rt::nff_contract::message_broken(e.what(), name, input);
        if (!broken.empty())
            broken += ": " + std::string(e.what());
    }
    if (!broken.empty()) {
        std::fprintf(stderr, "NFF contract broken: %s\n", broken.c_str());
        std::abort();
    }
    return 0;
}
