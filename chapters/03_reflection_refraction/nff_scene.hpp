// A scene file (NFF, common/nff.hpp) as chapter 03's scene: chapter 02's shapes, each with
// Whitted's share of mirror and of glass from its NFF material (Ks and T, and the index of
// refraction), under the file's first light as the sun: chapter 03 has one directional light and
// no shadows (those are chapter 04's). The sky is the file's background colour, without a glow.
#pragma once

#include "02_spheres_triangles/nff_scene.hpp"
#include "03_reflection_refraction/scene.hpp"
#include "common/scene_file.hpp"

namespace rt {

// NFF's "f r g b Kd Ks Shine T ior" as Whitted's k_s and k_t. An opaque material may give ior 0.
inline Material whitted_material(const NffMaterial& m)
{
    Material w;
    w.mirror = m.ks;
    w.transparency = m.t;
    w.ior = m.t > 0.0f ? m.ior : 1.0f;
    return w;
}

inline WhittedScene whitted_scene(const NffScene& nff)
{
    WhittedScene scene;
    scene.shapes = shape_scene(nff);
    const auto diffuse = [&](int material) { return nff.materials[material].kd * nff.materials[material].rgb; };
    for (size_t k = 0; k < nff.spheres.size(); ++k) {
        scene.shapes.sphere_albedo[k] = diffuse(nff.spheres[k].material);
        scene.sphere_materials.push_back(whitted_material(nff.materials[nff.spheres[k].material]));
    }
    for (size_t k = 0; k < nff.triangles.size(); ++k) {
        scene.shapes.triangle_albedo[k] = diffuse(nff.triangles[k].material);
        scene.triangle_materials.push_back(whitted_material(nff.materials[nff.triangles[k].material]));
    }
    for (size_t k = 0; k < nff.cones.size(); ++k) {
        scene.shapes.cone_albedo[k] = diffuse(nff.cones[k].material);
        scene.cone_materials.push_back(whitted_material(nff.materials[nff.cones[k].material]));
    }
    scene.zenith = nff.background;
    scene.ambient = color(nff_ambient);
    // The sun shines from where the first light stands, seen from the point the view looks at; a
    // light at that very point shines from the eye.
    const NffLight& light = nff.lights.front();
    const vec3 to_light = light.position - nff.view.at;
    scene.sun.to_sun = glm::normalize(glm::length(to_light) > 0.0f ? to_light : nff.view.from - nff.view.at);
    scene.sun.colour = light.rgb;
    return scene;
}

}  // namespace rt
