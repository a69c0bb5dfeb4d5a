// libFuzzer target for the triangulation under the NFF reader (common/polygon.hpp): any outline on
// a small integer grid is either refused with InputError, or cut into triangles that keep the
// contract checked in polygon_contract.hpp. How to build and run it: tests/fuzz/README.md.
#include "common/error.hpp"
#include "tests/fuzz/polygon_contract.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::vector<rt::point3> vertices = rt::polygon_contract::grid_outline(data, size);
    std::string broken;
    try {
        broken = rt::polygon_contract::broken(vertices, rt::triangulate_polygon(vertices));
    } catch (const rt::InputError&) {
        return 0;
    }
    if (!broken.empty()) {
        std::fprintf(stderr, "polygon contract broken: %s\n", broken.c_str());
        std::abort();
    }
    return 0;
}
