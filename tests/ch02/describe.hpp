// Chapter 02's tests in words: shapes, hits, and a score on an extreme case, so that a failure
// names the ray, the shape, what was expected and what came back.
#pragma once

#include "02_spheres_triangles/extremes.hpp"
#include "tests/grader/graded.hpp"

#include <sstream>
#include <string>

namespace rt::grader {

template <class T>
std::string show(const vec3_t<T>& v)
{
    return show(vec3(v));
}

template <class T>
std::string show(const BasicRay<T>& ray)
{
    std::ostringstream s;
    s.precision(9);
    s << "ray from (" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") along (" << ray.dir.x
      << ", " << ray.dir.y << ", " << ray.dir.z << ")";
    return s.str();
}

template <class T>
std::string show(const BasicSphere<T>& sphere)
{
    std::ostringstream s;
    s.precision(9);
    s << "the sphere at " << show(sphere.centre) << " of radius " << sphere.radius;
    return s.str();
}

template <class T>
std::string show(const BasicTriangle<T>& tri)
{
    return "the triangle a = " + show(tri.a) + ", b = " + show(tri.b) + ", c = " + show(tri.c);
}

inline std::string show(const Interval& range)
{
    std::ostringstream s;
    s << "range (" << range.min << ", " << range.max << ")";
    return s.str();
}

template <class T>
std::string show(const std::optional<TriangleHit<T>>& hit)
{
    if (!hit)
        return "no hit";
    std::ostringstream s;
    s.precision(9);
    s << "t = " << hit->t << " with beta = " << hit->beta << ", gamma = " << hit->gamma;
    return s.str();
}

inline std::string show(const exact::Answer& answer)
{
    std::ostringstream s;
    s.precision(12);
    if (answer.hit)
        s << "a hit at t = " << static_cast<double>(answer.t);
    else
        s << "no hit";
    return s.str();
}

// A score on an extreme case in words, with the first wrong answer and the worst t spelled out.
template <class T>
std::string describe(const std::string& what, const std::vector<extremes::SphereProbe<T>>& probes,
                     const std::vector<std::optional<T>>& answers, const extremes::Score& score)
{
    std::ostringstream s;
    s << what << ": " << score.wrong << " wrong hit/miss answers of " << score.answers << " ("
      << 100.0 * score.wrong_fraction() << "%), largest relative error of t " << score.max_rel_t_error;
    for (const auto& [label, k] : {std::pair<const char*, size_t>{"first wrong", score.first_wrong},
                                   std::pair<const char*, size_t>{"worst t", score.worst_t}})
        if (k != extremes::Score::npos)
            s << "\n  " << label << ": " << show(probes[k].ray) << " against " << show(probes[k].sphere) << ": got "
              << show(answers[k]) << ", exact answer "
              << show(exact::sphere(probes[k].ray, probes[k].sphere, BasicInterval<T>{}));
    return s.str();
}

template <class T>
std::string describe(const std::string& what, const extremes::TriangleProbes<T>& probes,
                     const std::vector<extremes::TriangleAnswer<T>>& answers, const extremes::Score& score)
{
    using Expect = typename extremes::TriangleProbes<T>::Expect;
    std::ostringstream s;
    s << what << ": " << score.wrong << " wrong answers of " << score.answers << " ("
      << 100.0 * score.wrong_fraction() << "%), largest relative error of t " << score.max_rel_t_error;
    if (const size_t k = score.first_wrong; k != extremes::Score::npos) {
        const std::vector<int>& targets = probes.targets[k];
        s << "\n  first wrong: " << show(probes.rays[k]) << " against ";
        if (targets.empty())
            s << "all " << probes.triangles.size() << " triangles of the mesh";
        for (const int f : targets)
            s << "\n    " << show(probes.triangles[f]);
        const bool exact_hit = probes.expect == Expect::exact &&
                               exact::triangle(probes.rays[k], probes.triangles[targets[0]], BasicInterval<T>{}).hit;
        s << "\n  hit " << answers[k].hits << " of them; expected "
          << (probes.expect == Expect::no_hit     ? "none"
              : probes.expect == Expect::some_hit ? "at least one"
              : exact_hit                         ? "a hit, as the exact answer says"
                                                  : "no hit, as the exact answer says");
    }
    return s.str();
}

}  // namespace rt::grader
