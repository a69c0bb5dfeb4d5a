// A scene file (NFF, common/nff.hpp) as chapter 05's scene: chapter 04's (nff_scene.hpp there),
// with each of the file's point lights made a disc light of the same power, so it casts soft
// shadows. NFF's lights have no size: the disc's radius is `light_size` times the light's distance
// from the point the view looks at, and the disc faces that point.
#pragma once

#include "04_shadow_feelers/nff_scene.hpp"
#include "05_soft_shadows/scene.hpp"

namespace rt {

// Why a twentieth: a disc whose radius is a twentieth of its distance from the scene's centre
// (about 6 degrees across, seen from there) casts a penumbra about a tenth as wide as an object's
// height above its shadow: plainly soft, while the shadows of small things (a sphereflake's
// smallest spheres, a tree's leaves) keep their dark cores.
constexpr float nff_light_size = 0.05f;

// Why 256: every hit sends light-samples feelers to every light, so the work grows as lights times
// samples times pixels; 256 lights at the default 16 samples is already 4096 feelers per hit (a
// 32 x 32 render of 100000 lights would take minutes). A file with more is refused, naming it.
constexpr int max_area_lights = 256;

inline AreaLitScene area_lit_scene(const NffScene& nff, float light_size = nff_light_size)
{
    if (nff.lights.size() > static_cast<size_t>(max_area_lights))
        throw InputError(nff.name + ": " + std::to_string(nff.lights.size()) + " lights; chapter 05 samples every light "
                         "at every hit and takes at most " + std::to_string(max_area_lights) +
                         " (chapter 04 renders the file with point lights)");
    AreaLitScene scene{lit_scene(nff), {}};
    scene.lit.lights.clear();
    for (const NffLight& light : nff.lights) {
        const vec3 offset = nff_light_offset(nff, light);
        const float d = glm::length(offset);
        AreaLight disc = disc_light(light.position, -offset / d, light_size * d, color(0.0f));
        // The power of chapter 04's point light for it (as_point_light turns it back): L_e A = I.
        disc.radiance = nff_light_colour(nff, light) * (d * d / light_area(disc));
        scene.area_lights.push_back(disc);
    }
    return scene;
}

}  // namespace rt
