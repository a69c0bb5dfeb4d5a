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
    scene.shapes = shape_scene(nff, [](const NffMaterial& m) { return m.kd * m.rgb; });
    const auto material = [&](int index) { return whitted_material(nff.materials[index]); };
    for (const NffSphere& s : nff.spheres)
        scene.materials[ObjectKind::sphere].push_back(material(s.material));
    for (const NffTriangle& t : nff.triangles)
        scene.materials[ObjectKind::triangle].push_back(material(t.material));
    for (const NffCone& c : nff.cones)
        scene.materials[ObjectKind::cone].push_back(material(c.material));
    scene.zenith = nff.background;
    scene.ambient = color(nff_ambient);
    // The sun shines from where the first light stands, seen from the point the view looks at, in
    // that light's own colour: it stands alone, so no share of sqrt(L) lights (nff_light_colour).
    const NffLight& light = nff.lights.front();
    scene.sun.to_sun = glm::normalize(nff_light_offset(nff, light));
    scene.sun.colour = light.rgb;
    return scene;
}

}  // namespace rt
