// A scene file as each chapter program renders it, for the tests: chapters 02 (headlight), 03
// (Whitted's recursion), 04 (feelers) and 04's classic NFF mode, each through the file's own view,
// the same calls the programs make (chapters/NN_name/main.cpp, --scene). The reference pictures
// (scene_pictures.hpp) and the render fuzzer's contract (tests/fuzz/scene_render_contract.hpp)
// both render through here.
#pragma once

#include "02_spheres_triangles/figure.hpp"
#include "02_spheres_triangles/nff_scene.hpp"
#include "03_reflection_refraction/figure.hpp"
#include "03_reflection_refraction/nff_scene.hpp"
#include "04_shadow_feelers/classic.hpp"
#include "04_shadow_feelers/figure.hpp"
#include "common/scene_file.hpp"

#include <array>

namespace rt::scene_renders {

enum class Mode { ch02, ch03, ch04, ch04_classic };

constexpr std::array<Mode, 4> modes = {Mode::ch02, Mode::ch03, Mode::ch04, Mode::ch04_classic};

// How the mode is named in reference pictures and messages.
inline const char* name(Mode mode)
{
    switch (mode) {
    case Mode::ch02:
        return "02";
    case Mode::ch03:
        return "03";
    case Mode::ch04:
        return "04";
    case Mode::ch04_classic:
        return "04_classic";
    }
    return "";  // not reached: the switch names every mode
}

inline Image render_as(Mode mode, const SceneRender& file)
{
    const auto eye = [&](float x, float y) { return file.eye_ray(primary_ray(file.camera, x, y)); };
    switch (mode) {
    case Mode::ch02: {
        const ShapeScene scene = shape_scene(file.scene);
        return render(file.settings, [&](float x, float y, Rng&) { return ch02::radiance(scene, eye(x, y), {}); });
    }
    case Mode::ch03: {
        const WhittedScene scene = whitted_scene(file.scene);
        return render(file.settings,
                      [&](float x, float y, Rng&) { return ch03::radiance(scene, eye(x, y), TraceSettings{}); });
    }
    case Mode::ch04: {
        const LitScene scene = lit_scene(file.scene);
        return render(file.settings,
                      [&](float x, float y, Rng&) { return ch04::radiance(scene, eye(x, y), FeelerSettings{}); });
    }
    case Mode::ch04_classic:
        return classic::render_classic(file, classic::classic_scene(file.scene));
    }
    return Image();  // not reached
}

// The file's view at side x side pixels.
inline SceneRender small(const NffScene& nff, int side)
{
    return SceneRender{nff, nff_camera(nff.view, side, side), quiet_render(side, side)};
}

}  // namespace rt::scene_renders
