// A scene file (NFF, common/nff.hpp) as chapter 02's scene: its spheres, its polygons' triangles
// (smooth-shaded through the file's vertex normals where it gives them, `pp`), its cones, each in
// the fill colour of its material, and its background. Chapter 02 shades with the headlight of its
// figure, so the file's lights and the rest of its materials wait for chapters 03 and 04.
#pragma once

#include "02_spheres_triangles/scene.hpp"
#include "common/nff.hpp"

namespace rt {

inline Cone cone_of(const NffCone& c)
{
    return {c.base, c.base_radius, c.apex, c.apex_radius};
}

inline Triangle triangle_of(const NffTriangle& t)
{
    return {t.p[0], t.p[1], t.p[2]};
}

// Each object in colour_of(its NFF material); chapter 02's, the material's fill colour.
template <class ColourOf>
ShapeScene shape_scene(const NffScene& nff, const ColourOf& colour_of)
{
    ShapeScene scene;
    scene.background = nff.background;
    const auto rgb = [&](int material) { return colour_of(nff.materials[material]); };
    for (const NffSphere& s : nff.spheres)
        scene.add_sphere({s.center, s.radius}, rgb(s.material));
    for (const NffTriangle& t : nff.triangles)
        scene.add_triangle(triangle_of(t), CornerNormals{t.n[0], t.n[1], t.n[2]}, rgb(t.material));
    for (const NffCone& c : nff.cones)
        scene.add_cone(cone_of(c), rgb(c.material));
    return scene;
}

inline ShapeScene shape_scene(const NffScene& nff)
{
    return shape_scene(nff, [](const NffMaterial& m) { return m.rgb; });
}

}  // namespace rt
