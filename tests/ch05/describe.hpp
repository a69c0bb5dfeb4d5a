// Chapter 05's tests in words: lights, samples and estimates, so that a failure names what went in,
// what was expected and what came back.
#pragma once

#include "05_soft_shadows/05_soft_shadows.hpp"
#include "tests/grader/graded.hpp"

#include <sstream>
#include <string>

namespace rt::grader {

inline std::string show(const AreaLight& light)
{
    std::ostringstream s;
    s.precision(9);
    s << (light.shape == LightShape::rectangle ? "the rectangle light" : "the disc light") << " at "
      << show(light.centre) << " with half-axes " << show(light.axis_u) << " and " << show(light.axis_v)
      << " (area " << light_area(light) << ", facing " << show(light_normal(light)) << ", radiance "
      << show(light.radiance) << ")";
    return s.str();
}

inline std::string show(sample2 u)
{
    std::ostringstream s;
    s.precision(9);
    s << "u = (" << u.x << ", " << u.y << ')';
    return s.str();
}

inline std::string show(const LightSampling& sampling)
{
    std::ostringstream s;
    s << sampling.samples << (sampling.scheme == SampleScheme::stratified ? " stratified" : " random")
      << " samples per call";
    return s.str();
}

// u and v, the light's half-axes made unit, and n its normal: the light's own frame.
struct LightFrame {
    dvec3 u, v, n;
    double radius_u, radius_v;
};

inline LightFrame frame_of(const AreaLight& light)
{
    const dvec3 u(light.axis_u), v(light.axis_v);
    return {glm::normalize(u), glm::normalize(v), glm::normalize(glm::cross(u, v)), glm::length(u), glm::length(v)};
}

// A point's coordinates in the light's frame, in units of the half-axes: (x, y) on the light
// itself, and its distance from the light's plane.
struct OnLight {
    double x, y, off_plane;
};

inline OnLight on_light(const AreaLight& light, const point3& p)
{
    const LightFrame f = frame_of(light);
    const dvec3 d = dvec3(p) - dvec3(light.centre);
    return {glm::dot(d, f.u) / f.radius_u, glm::dot(d, f.v) / f.radius_v, glm::dot(d, f.n)};
}

}  // namespace rt::grader
