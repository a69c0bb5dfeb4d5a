// What a graded test needs: the GRADED_TEST macro, which tags a Catch2 test case with its chapter,
// exercise number and points, and printers so a failure shows vectors and rays in plain words.
//
//   GRADED_TEST("a ray parallel to the plane misses", "01.2", 2) { ... }
//
// becomes TEST_CASE(name, "[ch01][01.2][2pt]"). A case earns all its points or none.
#pragma once

#include "common/ray.hpp"
#include "common/vec.hpp"

#include "tests/grader/catch.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <string>

#define GRADED_TEST(name, number, points) \
    TEST_CASE(name, "[ch" number "][" number "][" #points "pt]")

// The same, also run by the `stability` label: the formula pushed to its extremes.
#define STABILITY_TEST(name, number, points) \
    TEST_CASE(name, "[ch" number "][" number "][" #points "pt][stability]")

namespace rt::grader {

constexpr double pi = 3.14159265358979323846;

inline std::string show(const vec3& v)
{
    std::ostringstream s;
    s.precision(9);
    s << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return s.str();
}

inline std::string show(const Ray& ray)
{
    return "ray from " + show(ray.origin) + " along " + show(ray.dir);
}

template <class T>
std::string show(const std::optional<T>& value)
{
    if (!value)
        return "no hit";
    std::ostringstream s;
    s.precision(9);
    s << *value;
    return s.str();
}

// What a case is working on, in words, said only if the student's code crashes there: the grader
// prints it beside the signal. Cheap enough to set for every ray of a loop, since nothing is
// formatted unless the case crashes:
//   const WorkingOn on([&] { return show(ray); });
inline const std::function<std::string()>* working_on_now = nullptr;

class WorkingOn {
public:
    explicit WorkingOn(std::function<std::string()> describe) : describe_(std::move(describe)), outer_(working_on_now)
    {
        working_on_now = &describe_;
    }
    ~WorkingOn() { working_on_now = outer_; }
    WorkingOn(const WorkingOn&) = delete;
    WorkingOn& operator=(const WorkingOn&) = delete;

private:
    std::function<std::string()> describe_;
    const std::function<std::string()>* outer_;
};

// |actual - expected| / |expected|, or |actual| when expected is 0.
inline double rel_error(double actual, double expected)
{
    return expected != 0.0 ? std::abs(actual - expected) / std::abs(expected) : std::abs(actual);
}

}  // namespace rt::grader

namespace Catch {
template <>
struct StringMaker<glm::vec3> {
    static std::string convert(const glm::vec3& v) { return rt::grader::show(v); }
};
template <>
struct StringMaker<glm::vec2> {
    static std::string convert(const glm::vec2& v)
    {
        std::ostringstream s;
        s.precision(9);
        s << '(' << v.x << ", " << v.y << ')';
        return s.str();
    }
};
template <>
struct StringMaker<glm::ivec3> {
    static std::string convert(const glm::ivec3& c)
    {
        return '(' + std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z) + ')';
    }
};
template <>
struct StringMaker<rt::Ray> {
    static std::string convert(const rt::Ray& r) { return rt::grader::show(r); }
};
}  // namespace Catch
