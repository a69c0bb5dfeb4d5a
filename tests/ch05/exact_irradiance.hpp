// The exact answer direct_light estimates, for the tests: the light a polygon of constant radiance
// L_e sends onto a point, without any sampling.
//
// Over the light, the estimate's integral is L_e times the integral of cos(theta_surface)
// cos(theta_light) / d^2 dA, which is the polygon's *projected solid angle* seen from the point:
// the area its projection onto the unit sphere around the point covers once dropped onto the
// tangent plane. Lambert (Photometria, 1760) gave it in closed form for a polygon with corners
// c_0 .. c_{m-1}, with a_i the unit vectors from the point to the corners:
//     Omega_perp = (1/2) | sum_i  theta_i  n . normalize(a_i x a_{i+1}) |,   theta_i = angle(a_i, a_{i+1})
// (Arvo, "Applications of Irradiance Tensors to the Simulation of Non-Lambertian Phenomena",
// SIGGRAPH 1995, derives it as the flux of the edges). It holds for any polygon wholly above the
// point's horizon, at any slant: the slant of the light (cos theta_light) is inside it. A disc is a
// polygon of many corners; its answer straight above a point is the textbook pi sin^2(alpha).
#pragma once

#include "05_soft_shadows/area_light.hpp"

#include <cmath>
#include <vector>

namespace rt::grader {

inline double projected_solid_angle(const std::vector<dvec3>& corners, const dvec3& p, const dvec3& n)
{
    double sum = 0.0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const dvec3 a = glm::normalize(corners[i] - p);
        const dvec3 b = glm::normalize(corners[(i + 1) % corners.size()] - p);
        const dvec3 cross = glm::cross(a, b);
        const double sine = glm::length(cross);
        if (sine == 0.0)
            continue;
        sum += std::atan2(sine, glm::dot(a, b)) * glm::dot(n, cross / sine);
    }
    return 0.5 * std::abs(sum);
}

// The corners of the light, in order around it, in double: a rectangle's four; a disc as a regular
// polygon of 4096 corners whose area is the disc's (the corners a little outside the rim), so the
// answer differs from the disc's by far less than any test's tolerance.
inline std::vector<dvec3> corners_of(const AreaLight& light)
{
    const dvec3 c(light.centre), u(light.axis_u), v(light.axis_v);
    if (light.shape == LightShape::rectangle)
        return {c - u - v, c + u - v, c + u + v, c - u + v};
    constexpr int sides = 4096;
    constexpr double pi = 3.14159265358979323846;
    const double step = 2.0 * pi / sides;
    const double stretch = std::sqrt(step / std::sin(step));  // polygon area (sides/2) r^2 sin(step) = pi r^2
    std::vector<dvec3> corners;
    for (int k = 0; k < sides; ++k)
        corners.push_back(c + stretch * (std::cos(k * step) * u + std::sin(k * step) * v));
    return corners;
}

// What a white diffuse surface (k_d = 1, no highlight) at p with normal n reflects of an
// unoccluded light wholly above its horizon and facing it: L_e times the projected solid angle.
inline dvec3 exact_light(const AreaLight& light, const dvec3& p, const dvec3& n)
{
    return dvec3(light.radiance) * projected_solid_angle(corners_of(light), p, n);
}

}  // namespace rt::grader
