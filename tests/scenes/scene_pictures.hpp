// The kit's own NFF scenes (common/scenes/) rendered small, as the programs' --scene renders them,
// by chapters 02, 03 and 04 and 04's classic mode: the pictures scene_pictures_test.cpp compares
// with tests/references/scenes/, which the `references` target renders from the solutions.
// cones.nff holds every kind of object (spheres, polygons, cones, a mirror); spheres.nff a mirror
// and a glass sphere.
#pragma once

#include "02_spheres_triangles/figure.hpp"
#include "02_spheres_triangles/nff_scene.hpp"
#include "03_reflection_refraction/figure.hpp"
#include "03_reflection_refraction/nff_scene.hpp"
#include "04_shadow_feelers/classic.hpp"
#include "04_shadow_feelers/figure.hpp"
#include "common/scene_file.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rt::pictures {

// Small enough to render in a blink, large enough that every object covers many pixels.
constexpr int scene_side = 64;

inline SceneRender kit_scene(const std::string& name)
{
    const NffScene nff = read_nff(std::string(RT_NFF_SCENES_DIR) + "/" + name + ".nff");
    return SceneRender{nff, nff_camera(nff.view, scene_side, scene_side), quiet_render(scene_side, scene_side)};
}

// One picture: its reference's name under tests/references/, and how to render it.
struct ScenePicture {
    std::string name;
    std::function<Image()> render;
};

inline std::vector<ScenePicture> scene_pictures()
{
    std::vector<ScenePicture> pictures;
    for (const std::string scene : {"cones", "spheres"}) {
        pictures.push_back({"scenes/02_" + scene, [scene] {
                                const SceneRender file = kit_scene(scene);
                                const ShapeScene shapes = shape_scene(file.scene);
                                return render(file.settings, [&](float x, float y, Rng&) {
                                    return ch02::radiance(shapes, file.eye_ray(primary_ray(file.camera, x, y)), {});
                                });
                            }});
        pictures.push_back({"scenes/03_" + scene, [scene] {
                                const SceneRender file = kit_scene(scene);
                                const WhittedScene whitted = whitted_scene(file.scene);
                                return render(file.settings, [&](float x, float y, Rng&) {
                                    return ch03::radiance(whitted, file.eye_ray(primary_ray(file.camera, x, y)),
                                                          TraceSettings{});
                                });
                            }});
        pictures.push_back({"scenes/04_" + scene, [scene] {
                                const SceneRender file = kit_scene(scene);
                                const LitScene lit = lit_scene(file.scene);
                                return render(file.settings, [&](float x, float y, Rng&) {
                                    return ch04::radiance(lit, file.eye_ray(primary_ray(file.camera, x, y)),
                                                          FeelerSettings{});
                                });
                            }});
        pictures.push_back({"scenes/04_classic_" + scene, [scene] {
                                const SceneRender file = kit_scene(scene);
                                return classic::render_classic(file, classic::classic_scene(file.scene));
                            }});
    }
    return pictures;
}

}  // namespace rt::pictures
