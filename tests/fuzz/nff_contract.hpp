// The NFF reader's contract (common/nff.hpp) as checks, shared by the fuzz target and the fuzz
// regression tests: a scene it returns is whole and finite; a message it throws is one line,
// "NAME:LINE: what is wrong", with a line that exists in the input.
//
// Each check returns an empty string when the contract holds, and otherwise what broke, so a
// failure says more than "it crashed" (a fuzz test that only checks for crashes tells little).
#pragma once

#include "common/camera.hpp"
#include "common/error.hpp"
#include "common/nff.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace rt::nff_contract {

// A unit normal read back from float may be off by a few roundings.
constexpr double unit_tolerance = 1e-5;

inline bool finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
inline bool non_negative(const color& c) { return finite(c) && c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f; }

inline std::string scene_broken(const NffScene& s)
{
    const NffView& v = s.view;
    if (!finite(v.from) || !finite(v.at) || !finite(v.up))
        return "the view holds a non-finite vector";
    if (!(v.angle_degrees > 0.0f && v.angle_degrees < 180.0f) || !(v.hither >= 0.0f) || !std::isfinite(v.hither))
        return "the view's angle or hither is out of range";
    if (v.width < 1 || v.height < 1 || v.width > nff_max_resolution || v.height > nff_max_resolution)
        return "the view's resolution is out of range";
    try {
        make_camera({v.from, v.at, v.up, v.angle_degrees, v.width, v.height});
    } catch (const InputError& e) {
        return std::string("the view makes no camera: ") + e.what();
    }
    if (!non_negative(s.background))
        return "the background is negative or not finite";
    if (s.lights.empty())
        return "no lights";
    if (s.spheres.empty() && s.triangles.empty() && s.cones.empty())
        return "no objects";
    for (const NffLight& l : s.lights)
        if (!finite(l.position) || !non_negative(l.rgb) || l.line < 1)
            return "a light is not finite, negative, or has no line";
    for (const NffMaterial& m : s.materials) {
        const float weights[] = {m.kd, m.ks, m.shine, m.t, m.ior};
        for (const float w : weights)
            if (!std::isfinite(w) || w < 0.0f)
                return "a material has a negative or non-finite weight";
        if (!non_negative(m.rgb) || m.kd > 1.0f || m.ks > 1.0f || m.t > 1.0f || (m.t > 0.0f && !(m.ior > 0.0f)))
            return "a material's colour, Kd, Ks, T or ior is out of range";
    }
    const auto bad_material = [&](int index) { return index < 0 || index >= static_cast<int>(s.materials.size()); };
    for (const NffSphere& sp : s.spheres)
        if (!finite(sp.center) || !std::isfinite(sp.radius) || !(sp.radius > 0.0f) || bad_material(sp.material) ||
            sp.line < 1)
            return "a sphere is not finite, has no size, material or line";
    for (const NffTriangle& t : s.triangles) {
        if (bad_material(t.material) || t.line < 1)
            return "a triangle has no material or line";
        for (int k = 0; k < 3; ++k)
            if (!finite(t.p[k]) || !finite(t.n[k]) || std::abs(glm::length(dvec3(t.n[k])) - 1.0) > unit_tolerance)
                return "a triangle's vertex or normal is not finite, or a normal is not unit length";
        const dvec3 area = glm::cross(dvec3(t.p[1]) - dvec3(t.p[0]), dvec3(t.p[2]) - dvec3(t.p[0]));
        if (!(glm::length(area) > 0.0))
            return "a triangle has no area";
    }
    for (const NffCone& c : s.cones)
        if (!finite(c.base) || !finite(c.apex) || !(c.base_radius >= 0.0f) || !(c.apex_radius >= 0.0f) ||
            !std::isfinite(c.base_radius) || !std::isfinite(c.apex_radius) ||
            (c.base_radius == 0.0f && c.apex_radius == 0.0f) || c.base == c.apex || bad_material(c.material) ||
            c.line < 1)
            return "a cone is not finite, degenerate, or has no material or line";
    return "";
}

// The number of lines in `text` as the reader counts them (\n, \r\n or a lone \r ends one).
inline int line_count(const std::string& text)
{
    int lines = 1;
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n' || (text[i] == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n')))
            ++lines;
    return lines;
}

inline std::string message_broken(const std::string& message, const std::string& name, const std::string& input)
{
    const std::string prefix = name + ":";
    if (message.compare(0, prefix.size(), prefix) != 0)
        return "the message does not start with the file's name";
    std::size_t pos = prefix.size();
    long line = 0;
    while (pos < message.size() && message[pos] >= '0' && message[pos] <= '9' && line < 100000000)
        line = line * 10 + (message[pos++] - '0');
    if (pos == prefix.size() || message.compare(pos, 2, ": ") != 0 || pos + 2 >= message.size())
        return "the message is not NAME:LINE: what";
    if (line < 1 || line > line_count(input))
        return "the message names line " + std::to_string(line) + ", which the input does not have";
    if (std::any_of(message.begin(), message.end(), [](char c) { return c < 0x20 || c == 0x7f; }))
        return "the message is not one printable line";
    return "";
}

}  // namespace rt::nff_contract
