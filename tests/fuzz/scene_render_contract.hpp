// The render side's contract for scene files, as a check shared by the fuzz target
// (scene_render_fuzz.cpp) and the normal test run (tests/scenes/scene_pictures_test.cpp, over the
// fuzz corpus): a scene the reader accepts renders in chapters 02, 03, 04 and 04's classic mode,
// 3 x 3 pixels through its own view, with no NaN or infinite pixel. Empty when it holds, else what
// broke.
#pragma once

#include "02_spheres_triangles/figure.hpp"
#include "02_spheres_triangles/nff_scene.hpp"
#include "03_reflection_refraction/figure.hpp"
#include "03_reflection_refraction/nff_scene.hpp"
#include "04_shadow_feelers/classic.hpp"
#include "04_shadow_feelers/figure.hpp"
#include "common/scene_file.hpp"

#include <string>

namespace rt::scene_render_contract {

constexpr int side = 3;

inline std::string render_broken(const NffScene& nff)
{
    const SceneRender file{nff, nff_camera(nff.view, side, side), quiet_render(side, side)};
    const auto eye = [&](float x, float y) { return file.eye_ray(primary_ray(file.camera, x, y)); };
    const auto broken = [](const Image& image, const char* chapter) {
        const int bad = count_non_finite(image);
        return bad > 0 ? std::string(chapter) + ": " + std::to_string(bad) + " of 9 pixels are NaN or infinite"
                       : std::string();
    };
    const ShapeScene shapes = shape_scene(nff);
    std::string what = broken(render(file.settings, [&](float x, float y, Rng&) {
                                  return ch02::radiance(shapes, eye(x, y), ShapeTests{});
                              }),
                              "chapter 02");
    const WhittedScene whitted = whitted_scene(nff);
    if (what.empty())
        what = broken(render(file.settings, [&](float x, float y, Rng&) {
                          return ch03::radiance(whitted, eye(x, y), TraceSettings{});
                      }),
                      "chapter 03");
    const LitScene lit = lit_scene(nff);
    if (what.empty())
        what = broken(render(file.settings, [&](float x, float y, Rng&) {
                          return ch04::radiance(lit, eye(x, y), FeelerSettings{});
                      }),
                      "chapter 04");
    if (what.empty())
        what = broken(classic::render_classic(file, classic::classic_scene(nff)), "chapter 04, --classic");
    return what;
}

}  // namespace rt::scene_render_contract
