// What a closest-hit query returns: where along the ray, where in space, which way the surface
// faces, and which object it was (an index into the scene's flat array).
#pragma once

#include "common/vec.hpp"

namespace rt {

struct Hit {
    float t = 0.0f;
    point3 p{0.0f};  // the hit point, ray.at(t)
    vec3 n{0.0f};    // unit surface normal as the object defines it (not flipped toward the ray): the
                     // shading normal, a smooth patch's corner normals interpolated
    int object = -1; // index of the object in its scene array
    vec3 ng{n};      // the geometric normal (a triangle's face normal), which rays leave along; n itself
                     // unless the surface is a smooth patch
};

}  // namespace rt
