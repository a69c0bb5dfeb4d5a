// Chapter 05's scene: chapter 04's (objects, materials, point lights, ambient light, background)
// and area lights beside it. The area lights are not objects: no ray hits them, feelers run to
// points on them, and a primary ray never sees them (the figure keeps them out of view). That is
// all soft shadows need (the kit models only what a scene requires).
//
// Chapter 04's queries (closest_hit, the shadow feeler `occluded`) take `lit`, unchanged.
#pragma once

#include "04_shadow_feelers/scene.hpp"
#include "05_soft_shadows/area_light.hpp"

#include <vector>

namespace rt {

struct AreaLitScene {
    LitScene lit;                        // chapter 04's scene; its point lights still shine, with hard shadows
    std::vector<AreaLight> area_lights;  // each shaded with soft shadows (EXERCISE 05.4)
};

// The light shrunk to a point at its centre, sending the same light straight ahead: intensity
// L_e A. Seen from far away, along its normal, the two light a point alike (the area light's
// cos(theta) / d^2 barely varies over its area); up close or at a slant they differ, and the point
// casts a hard shadow where the area light casts a soft one. The figure's left panel uses these.
inline PointLight as_point_light(const AreaLight& light)
{
    return {light.centre, light.radiance * light_area(light)};
}

}  // namespace rt
