#include "common/float_reach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace rt {

namespace {

float largest_magnitude(const point3& lo, const point3& hi)
{
    const vec3 m = glm::max(glm::abs(lo), glm::abs(hi));
    return std::max(m.x, std::max(m.y, m.z));
}

float float_step(float x) { return std::nextafter(x, std::numeric_limits<float>::infinity()) - x; }

}  // namespace

std::string scene_beyond_float(const std::vector<Box>& objects)
{
    if (objects.empty())
        return {};
    point3 lo = objects[0].lo, hi = objects[0].hi;
    for (const Box& b : objects) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    const vec3 extent = hi - lo;
    const float size = std::max(extent.x, std::max(extent.y, extent.z));
    const float far = largest_magnitude(lo, hi);
    const float step = float_step(far);
    std::ostringstream why;
    if (size == 0.0f) {
        why << "every object rounds to one point, " << lo.x << " " << lo.y << " " << lo.z << ", where float's step is "
            << step << ": the scene draws as one dot; move it toward the origin";
        return why.str();
    }
    if (size < 0x1p14f * step) {
        why << "the scene is " << size << " across but lies " << far << " from the origin, where float's step is " << step
            << ": only " << static_cast<long long>(size / step)
            << " steps across it, so its shapes are rounded visibly (facets, flickering shadows); move it toward the origin";
        return why.str();
    }
    // Objects finer than the offset where they lie: counted, the smallest against its offset named.
    long finer = 0;
    double worst = 1.0;
    Box first{};
    for (const Box& b : objects) {
        const float at = largest_magnitude(b.lo, b.hi);
        if (at < 1.0f / 32.0f)
            continue;
        const vec3 e = b.hi - b.lo;
        const double reach = offset_reach_steps * float_step(at);
        const double ratio = std::max(e.x, std::max(e.y, e.z)) / reach;
        if (ratio < 1.0 && finer++ >= 0 && ratio < worst) {
            worst = ratio;
            first = b;
        }
    }
    if (finer == 0)
        return {};
    const float at = largest_magnitude(first.lo, first.hi);
    const vec3 e = first.hi - first.lo;
    why << finer << " objects are smaller than a shadow feeler's offset where they lie (the smallest is "
        << std::max(e.x, std::max(e.y, e.z)) << " across, " << at << " from the origin, where feelers start "
        << offset_reach_steps * float_step(at) << " off a surface): shadows between them are lost; move the scene toward the origin";
    return why.str();
}

std::string view_beyond_float(const point3& from, const point3& at, float angle_degrees, int width)
{
    constexpr double u = 0x1p-24;
    constexpr double roundings = 4.0;
    const dvec3 f(from), a(at);
    const double distance = glm::length(a - f);
    const dvec3 m = glm::max(glm::abs(f), glm::abs(a));
    const double magnitude = std::max(m.x, std::max(m.y, m.z));
    const double pixel = 2.0 * distance * std::tan(0.5 * double(angle_degrees) * 3.141592653589793 / 180.0) / width;
    const double placed = roundings * u * (magnitude + distance);
    if (!(placed > pixel))
        return {};
    std::ostringstream out;
    out.precision(3);
    out << "float cannot hold this view: where the eye looks, a pixel is " << pixel << " across, but float places rays only to within "
        << placed << " there (" << (magnitude > distance ? "the view lies " : "the eye stands ")
        << (magnitude > distance ? magnitude : distance)
        << (magnitude > distance ? " from the origin; move the scene toward it" : " from what it looks at; come closer or widen the view")
        << "); expect a picture that float's rounding draws";
    return out.str();
}

}  // namespace rt
