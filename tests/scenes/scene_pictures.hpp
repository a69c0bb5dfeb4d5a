// The kit's own NFF scenes (common/scenes/) rendered small from their files, as the programs'
// --scene renders them (scene_renders.hpp): the pictures scene_pictures_test.cpp compares with
// tests/references/scenes/, which the `references` target renders from the solutions. The patches
// show smooth shading through the files' vertex normals, in chapter 04 too (as chapter 02 teaches).
// cones.nff holds every kind of object (spheres, polygons, cones, a mirror); spheres.nff a mirror
// and a glass sphere.
#pragma once

#include "tests/scenes/scene_renders.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rt::pictures {

// Small enough to render in a blink, large enough that every object covers many pixels.
constexpr int scene_side = 64;

// One picture: its reference's name under tests/references/, and how to render it.
struct ScenePicture {
    std::string name;
    std::function<Image()> render;
};

inline std::vector<ScenePicture> scene_pictures()
{
    std::vector<ScenePicture> pictures;
    for (const std::string scene : {"cones", "patches", "spheres"})
        for (const scene_renders::Mode mode : scene_renders::modes)
            pictures.push_back({"scenes/" + std::string(scene_renders::name(mode)) + "_" + scene, [scene, mode] {
                                    const NffScene nff = read_nff(std::string(RT_NFF_SCENES_DIR) + "/" + scene + ".nff");
                                    return scene_renders::render_as(mode, scene_renders::small(nff, scene_side));
                                }});
    return pictures;
}

}  // namespace rt::pictures
