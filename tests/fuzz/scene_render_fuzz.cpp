// libFuzzer target for the render side of scene files: any bytes that the NFF reader accepts are a
// valid scene, and every chapter's program must render it without a crash, a sanitizer report, a
// hang, or a NaN or infinite pixel, however degenerate its geometry (a light on a surface, a
// pointed cone seen tip-on, an eye inside a sphere, coordinates near the reader's limit). Bytes
// the reader refuses are nff_fuzz's business and are skipped here.
//
// Each accepted scene is rendered at 3 x 3 pixels, keeping its view, by the reference solutions of
// chapters 02 (headlight), 03 (Whitted's recursion), 04 (feelers) and 04's classic NFF mode.
// How to build and run it: README.md beside this file.
#include "02_spheres_triangles/figure.hpp"
#include "02_spheres_triangles/nff_scene.hpp"
#include "03_reflection_refraction/figure.hpp"
#include "03_reflection_refraction/nff_scene.hpp"
#include "04_shadow_feelers/classic.hpp"
#include "04_shadow_feelers/figure.hpp"
#include "common/scene_file.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace {

using namespace rt;

constexpr int side = 3;

void check(const Image& image, const char* what)
{
    if (const int bad = count_non_finite(image); bad > 0) {
        std::fprintf(stderr, "%s: %d of %d pixels are NaN or infinite\n", what, bad, side * side);
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    NffScene nff;
    try {
        nff = parse_nff(in, "fuzz.nff");
    } catch (const InputError&) {
        return 0;
    }
    const SceneRender file{nff, nff_camera(nff.view, side, side), quiet_render(side, side)};
    const RenderSettings& settings = file.settings;
    const auto eye = [&](float x, float y) { return file.eye_ray(primary_ray(file.camera, x, y)); };

    const ShapeScene shapes = shape_scene(nff);
    check(render(settings, [&](float x, float y, Rng&) { return ch02::radiance(shapes, eye(x, y), ShapeTests{}); }),
          "chapter 02");
    const WhittedScene whitted = whitted_scene(nff);
    check(render(settings, [&](float x, float y, Rng&) { return ch03::radiance(whitted, eye(x, y), TraceSettings{}); }),
          "chapter 03");
    const LitScene lit = lit_scene(nff);
    check(render(settings, [&](float x, float y, Rng&) { return ch04::radiance(lit, eye(x, y), FeelerSettings{}); }),
          "chapter 04");
    check(classic::render_classic(file, classic::classic_scene(nff)), "chapter 04, --classic");
    return 0;
}
