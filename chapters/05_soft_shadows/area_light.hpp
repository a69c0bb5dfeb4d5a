// An area light: the slides' "wide light source", a flat shape that glows. Chapter 04's point light
// sends all its light from one point, so each point of the scene either sees it or not, and shadows
// are hard; a light with an area can be partly hidden, and the shadow gets a soft edge (the
// penumbra), as real shadows have.
//
// Two shapes, described alike by a centre and two half-axes, axis_u and axis_v, perpendicular:
//   rectangle: centre + s axis_u + t axis_v for s, t in [-1, 1]: sides 2|axis_u| by 2|axis_v|;
//   disc:      centre + x axis_u + y axis_v for x^2 + y^2 <= 1, with |axis_u| = |axis_v| its radius.
// One struct with a shape tag, not a class per shape with a virtual call: the kit keeps its scenes
// as plain structs in flat arrays.
//
// The light glows on one side only, the side its normal n = normalize(axis_u x axis_v) faces (a
// ceiling panel lights the room, not the attic), with the same radiance L_e in every direction on
// that side: a Lambertian emitter. A small patch dA of it, seen at the angle theta_light from n,
// sends L_e cos(theta_light) dA of intensity that way.
#pragma once

#include "common/vec.hpp"

#include <cassert>
#include <cmath>

namespace rt {

enum class LightShape { rectangle, disc };

struct AreaLight {
    LightShape shape = LightShape::rectangle;
    point3 centre{0.0f};
    vec3 axis_u{0.0f};    // half-axes: the rectangle reaches +-axis_u and +-axis_v from its centre,
    vec3 axis_v{0.0f};    // the disc's rim is |axis_u| = |axis_v| away
    color radiance{0.0f}; // L_e, the same in every direction on the lit side
};

// The side the light glows toward.
inline vec3 light_normal(const AreaLight& light)
{
    return glm::normalize(glm::cross(light.axis_u, light.axis_v));
}

// The light's area A: the pdf of a point drawn uniformly on it is 1 / A.
inline float light_area(const AreaLight& light)
{
    constexpr float pi = 3.14159265358979f;
    const float parallelogram = glm::length(glm::cross(light.axis_u, light.axis_v));  // |u||v| when perpendicular
    return light.shape == LightShape::rectangle ? 4.0f * parallelogram : pi * parallelogram;
}

// A rectangle 2|axis_u| by 2|axis_v| around `centre`, glowing toward axis_u x axis_v.
inline AreaLight rectangle_light(const point3& centre, const vec3& axis_u, const vec3& axis_v, const color& radiance)
{
    assert(std::abs(glm::dot(axis_u, axis_v)) <= 1e-5f * glm::length(axis_u) * glm::length(axis_v));
    return {LightShape::rectangle, centre, axis_u, axis_v, radiance};
}

// A disc of `radius` around `centre`, glowing toward the unit vector `normal`. Its axes come from
// Duff et al.'s branchless orthonormal basis ("Building an Orthonormal Basis, Revisited", JCGT
// 2017), which is right-handed, so axis_u x axis_v points along `normal`.
inline AreaLight disc_light(const point3& centre, const vec3& normal, float radius, const color& radiance)
{
    const float sign = std::copysign(1.0f, normal.z);
    const float a = -1.0f / (sign + normal.z);
    const float b = normal.x * normal.y * a;
    const vec3 u{1.0f + sign * normal.x * normal.x * a, sign * b, -sign * normal.x};
    const vec3 v{b, sign + normal.y * normal.y * a, -normal.y};
    return {LightShape::disc, centre, radius * u, radius * v, radiance};
}

}  // namespace rt
