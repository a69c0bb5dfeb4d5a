// A scene file (NFF, common/nff.hpp) as chapter 04's scene: its shapes, its materials as Phong's
// (k_d = Kd times the fill colour, a white highlight of weight Ks and exponent Shine), and its
// lights as point lights with shadow feelers. Chapters 05 and 06 build on the same scene.
//
// A patch (`pp`) is shaded smooth with its vertex normals, as chapter 02 teaches (EXERCISE 02.6);
// its feelers leave along its face normal. Mirror and glass (Ks and T) need chapter 03's
// recursion: the classic mode (classic.hpp) has it.
#pragma once

#include "02_spheres_triangles/nff_scene.hpp"
#include "04_shadow_feelers/scene.hpp"
#include "common/notice.hpp"
#include "common/scene_file.hpp"

#include <string>

namespace rt {

inline PhongMaterial phong_material(const NffMaterial& m)
{
    return {m.kd * m.rgb, color(m.ks), m.shine};
}

// The distance at which an NFF light shines with its own colour: from the point the view looks at
// (nff_light_offset). A point light falls off as 1 / d^2 (chapter 04's lesson) where NFF's does not
// fall off at all: so the scene's centre of interest is lit as NFF lights it, nearer surfaces
// brighter and farther ones darker.
inline float nff_light_distance(const NffScene& nff, const NffLight& light)
{
    return glm::length(nff_light_offset(nff, light));
}

// Chapters 04-06 (and 07 on, outside --classic) shade every surface opaque: a mirror's Ks becomes
// its highlight only, and glass (T > 0) is not seen through. Said once, as a notice
// (common/notice.hpp), so that a dark glass sphere is not taken for a bug; `chapter` names the program.
inline void note_unmodelled_materials(const NffScene& nff, const std::string& chapter)
{
    int mirrors = 0, glass = 0;
    for (const NffMaterial& m : nff.materials) {
        mirrors += m.ks > 0.0f;
        glass += m.t > 0.0f;
    }
    if (mirrors + glass > 0)
        notice(chapter + ": note: " + nff.name + ": " + std::to_string(mirrors) + " mirror (Ks > 0) and " +
               std::to_string(glass) +
               " glass (T > 0) materials are shaded opaque here, Ks as a highlight only; chapter 03 and "
               "chapter 04's --classic render reflections and refractions");
}

inline LitScene lit_scene(const NffScene& nff)
{
    LitScene scene;
    scene.background = nff.background;
    scene.ambient = color(nff_ambient);
    for (const NffMaterial& m : nff.materials)
        scene.add_material(phong_material(m));
    for (const NffSphere& s : nff.spheres)
        scene.add_sphere({s.center, s.radius}, s.material);
    for (const NffTriangle& t : nff.triangles) {
        if (t.smooth)
            scene.add_smooth_triangle(triangle_of(t), CornerNormals{t.n[0], t.n[1], t.n[2]}, t.material);
        else
            scene.add_triangle(triangle_of(t), t.material);
    }
    for (const NffCone& c : nff.cones)
        scene.add_cone(cone_of(c), c.material);
    for (const NffLight& light : nff.lights) {
        const float d = nff_light_distance(nff, light);
        scene.lights.push_back({light.position, nff_light_colour(nff, light) * d * d});
    }
    return scene;
}

}  // namespace rt
