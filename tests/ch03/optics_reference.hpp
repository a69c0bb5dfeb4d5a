// Chapter 03's answers computed another way, in double, to judge the exercises' float answers by:
// refraction from the angles (theta_t = asin(n1 sin(theta_i) / n2), then the direction rebuilt
// from the part of v along the surface), Fresnel's reflectance from his sine and tangent laws
// rather than the cosine form the exercise uses, and the rays and words the failures print.
#pragma once

#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "tests/grader/graded.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace rt::grader::optics {

inline double radians(double degrees) { return degrees * pi / 180.0; }
inline double degrees(double radians) { return radians * 180.0 / pi; }

// The critical angle of leaving a medium of index ior > 1 for one of index 1: sin(theta_c) = 1 / ior.
inline double critical_degrees(double ior) { return degrees(std::asin(1.0 / ior)); }

// A unit direction at `theta` radians from the normal n, in the plane of n and the unit tangent s
// (s perpendicular to n): arriving from outside (pointing against n) or from inside (along n).
inline vec3 incident(const vec3& n, const vec3& s, double theta, bool from_inside)
{
    const dvec3 v = std::sin(theta) * dvec3(s) + (from_inside ? 1.0 : -1.0) * std::cos(theta) * dvec3(n);
    return vec3(glm::normalize(v));
}

struct Refracted {
    bool total_internal_reflection = false;
    double sin_t = 0.0;  // sin(theta_t), n1 sin(theta_i) / n2: above 1 under total internal reflection
    dvec3 t{0.0};        // the transmitted direction, when there is one
};

// Snell's law by angles: the part of v along the surface has length sin(theta_i); the transmitted
// ray keeps its direction, with length sin(theta_t), and goes on through the surface by cos(theta_t).
inline Refracted refract_reference(const vec3& v_in, const vec3& n_in, double ior)
{
    const dvec3 v = glm::normalize(dvec3(v_in)), outward = glm::normalize(dvec3(n_in));
    const bool from_inside = glm::dot(v, outward) > 0.0;
    const dvec3 facing = from_inside ? -outward : outward;  // the normal on the ray's side
    const double n1 = from_inside ? ior : 1.0, n2 = from_inside ? 1.0 : ior;
    const dvec3 along = v - glm::dot(v, facing) * facing;
    const double sin_i = glm::length(along);
    Refracted r;
    r.sin_t = n1 * sin_i / n2;
    if (r.sin_t >= 1.0) {
        r.total_internal_reflection = true;
        return r;
    }
    const dvec3 s = sin_i > 0.0 ? along / sin_i : dvec3(0.0);
    r.t = r.sin_t * s - std::sqrt(1.0 - r.sin_t * r.sin_t) * facing;
    return r;
}

// The indices on the ray's side and the other side, for cos_i = -v.n and an object of index ior.
inline std::pair<double, double> sides(double cos_i, double ior)
{
    return cos_i < 0.0 ? std::pair<double, double>{ior, 1.0} : std::pair<double, double>{1.0, ior};
}

// Fresnel's sine and tangent laws: r_s = -sin(theta_i - theta_t) / sin(theta_i + theta_t),
// r_p = tan(theta_i - theta_t) / tan(theta_i + theta_t), R their squares' mean; at normal
// incidence (where both are 0 / 0) their limit, (n1 - n2) / (n1 + n2).
inline double fresnel_reference(double cos_i, double ior)
{
    const auto [n1, n2] = sides(cos_i, ior);
    const double theta_i = std::acos(std::min(1.0, std::abs(cos_i)));
    const double sin_t = n1 * std::sin(theta_i) / n2;
    if (sin_t >= 1.0)
        return 1.0;
    if (theta_i < 1e-9) {
        const double r0 = (n1 - n2) / (n1 + n2);
        return r0 * r0;
    }
    const double theta_t = std::asin(sin_t);
    const double rs = std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
    const double rp = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
    return 0.5 * (rs * rs + rp * rp);
}

// Schlick's curve of the cosine on the less dense side (the larger angle).
inline double schlick_reference(double cos_i, double ior)
{
    const auto [n1, n2] = sides(cos_i, ior);
    const double r0 = (n1 - n2) / (n1 + n2);
    const double theta_i = std::acos(std::min(1.0, std::abs(cos_i)));
    const double sin_t = n1 * std::sin(theta_i) / n2;
    if (sin_t >= 1.0)
        return 1.0;
    const double larger = std::max(theta_i, std::asin(sin_t));
    return r0 * r0 + (1.0 - r0 * r0) * std::pow(1.0 - std::cos(larger), 5.0);
}

// --- Words for the failures ---

inline std::string show(const std::optional<vec3>& dir)
{
    return dir ? grader::show(*dir) : std::string("no direction (total internal reflection)");
}

inline std::string show(const Refracted& r)
{
    return r.total_internal_reflection ? std::string("no direction (total internal reflection)")
                                       : grader::show(vec3(r.t));
}

// "(leaving at 41.8 degrees)" for a ray whose -v.n is cos_i.
inline std::string side_and_angle(float cos_i)
{
    std::ostringstream s;
    s.precision(9);
    s << "(" << (cos_i < 0.0f ? "leaving" : "entering") << " at "
      << degrees(std::acos(std::min(1.0, std::abs(static_cast<double>(cos_i))))) << " degrees)";
    return s.str();
}

inline std::string query(const vec3& v, const vec3& n, float ior)
{
    std::ostringstream s;
    s.precision(9);
    s << "v = " << grader::show(v) << ", n = " << grader::show(n) << ", ior = " << ior << " "
      << side_and_angle(-glm::dot(v, n));
    return s.str();
}

// "fresnel_schlick(cos_i = -0.5, ior = 1.5) (leaving at 60 degrees)".
inline std::string call(const std::string& function, float cos_i, float ior)
{
    std::ostringstream s;
    s.precision(9);
    s << function << "(cos_i = " << cos_i << ", ior = " << ior << ") " << side_and_angle(cos_i);
    return s.str();
}

// |a - b| for a float direction against a double one.
inline double distance(const vec3& a, const dvec3& b) { return glm::length(dvec3(a) - b); }

}  // namespace rt::grader::optics
