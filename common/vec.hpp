// Vectors for the kit: GLM's types under names that say what a value means.
// A point, a direction and a colour are all three floats; the alias tells the reader which.
#pragma once

#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

namespace rt {

using vec3 = glm::vec3;    // a direction or an offset
using point3 = glm::vec3;  // a position in the scene
using color = glm::vec3;   // linear RGB radiance, not yet tone mapped

// Double precision twins, for the tests and sweeps that measure what float costs.
using dvec3 = glm::dvec3;
using dpoint3 = glm::dvec3;

// A vector over the scalar type T (float or double), for formulas written once for both.
template <class T>
using vec3_t = glm::vec<3, T>;

// v made unit, also when v is so short (1e-29) that its squared length underflows in float, where
// glm::normalize would divide by 0: then in double. Zero stays zero. The float path is glm's own, so
// a vector of ordinary length gives glm::normalize's bits.
inline vec3 unit_or_zero(const vec3& v)
{
    if (glm::dot(v, v) > 0.0f)
        return glm::normalize(v);
    if (v == vec3(0.0f))
        return v;
    return vec3(glm::normalize(dvec3(v)));
}

}  // namespace rt
