// libFuzzer target for the render side of scene files: any bytes that the NFF reader accepts are a
// valid scene, and every chapter's program must render it without a crash, a sanitizer report, a
// hang, or a NaN or infinite pixel, however degenerate its geometry (a light on a surface, a
// pointed cone seen tip-on, an eye inside a sphere, coordinates near the reader's limit). Bytes
// the reader refuses are nff_fuzz's business and are skipped here. The checks are in
// scene_render_contract.hpp; how to build and run it is in README.md beside this file.
#include "tests/fuzz/scene_render_contract.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    rt::NffScene nff;
    try {
        nff = rt::parse_nff(in, "fuzz.nff");
    } catch (const rt::InputError&) {
        return 0;
    }
    const std::string broken = rt::scene_render_contract::render_broken(nff);
    if (!broken.empty()) {
        std::fprintf(stderr, "scene render contract broken: %s\n", broken.c_str());
        std::abort();
    }
    return 0;
}
