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

}  // namespace rt
