// An accelerator against brute force (the tests of chapters 07 on): on seeded rays over a scene,
// at several densities, it must answer every query as brute force does: the same object at the
// same t, bit for bit, and the same any-hit answer.
#pragma once

#include "04_shadow_feelers/nff_scene.hpp"
#include "common/random.hpp"
#include "tests/ch07/describe.hpp"
#include "tests/ch07/suspect.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

namespace rt::grader::agreement {


struct Disagreement {
    int rays = 0, wrong = 0;
    std::string first;    // the first wrong answer, in words
    std::string suspect;  // the diagnosis of that ray (Build::suspect), lines that each start with a newline
};

inline std::string answer(bool found, const ObjectHit& h) { return found ? show(h) : "no hit"; }

// What a test builds from a scene's objects at a density: the accelerator under test, and how a
// failure names it ("the grid", "the BVH").
using BuildFn = std::function<std::unique_ptr<Accelerator>(const Objects&, float lambda)>;
// What a failing case says about the first ray that differs: the chapter's exercises run again on
// that ray, each held to its own contract (tests/ch07/suspect.hpp), as lines to add to the failure.
using SuspectFn = std::function<std::string(const Accelerator&, const Ray&, Interval, const Objects&)>;
struct Build {
    std::string structure;
    BuildFn make;
    SuspectFn suspect = {};
    // The same for a build that throws: what went wrong in the exercises the build uses.
    std::function<std::string(const Objects&, float lambda)> suspect_build = {};
    // The exercises the build asks ("07.1 grid_resolution, ..."), said when the build crashes.
    std::string build_asks = {};
};

struct SeededRay {
    Ray ray;
    Interval range;
};

// The k-th of a run of seeded rays (compare's, and 10.7's cost): even k from the view's eye into
// its field of view, odd k from a point in and around the scene's `box` in any direction (some
// parallel to a slab), with a range that sometimes ends early; nullopt for a direction of 0.
inline std::optional<SeededRay> seeded_ray(Rng& rng, const NffView& view, const Bounds& box, int k)
{
    const auto u = [&] { return rng.next_float(); };
    // A vector of three draws, one a statement: a constructor's arguments are evaluated in an order
    // each compiler picks (GCC right to left, clang left to right), and the rays, with the open
    // exercises' stored reference costs, must be the same under both. The draws go to z, y, x in
    // that order, the order GCC gave them when the costs were measured.
    const auto drawn = [&](float scale, float shift) {
        const float z = scale * u() + shift;
        const float y = scale * u() + shift;
        const float x = scale * u() + shift;
        return vec3(x, y, z);
    };
    const vec3 e = box.extent();
    Ray ray;
    if (k % 2 == 0) {
        const vec3 ahead = glm::normalize(view.at - view.from);
        ray = {view.from, glm::normalize(ahead + 0.6f * drawn(2.0f, -1.0f))};
    } else {
        vec3 dir = drawn(2.0f, -1.0f);
        if (u() < 0.1f)
            dir[static_cast<int>(u() * 3)] = 0.0f;  // some rays parallel to a slab
        if (dir == vec3(0.0f))
            return std::nullopt;
        ray = {box.min - 0.25f * e + 1.5f * e * drawn(1.0f, 0.0f), glm::normalize(dir)};
    }
    const Interval range{u() < 0.5f ? 0.0f : 1e-4f, u() < 0.2f ? glm::length(e) * u() : infinity};
    return SeededRay{ray, range};
}

// `rays` seeded rays (seeded_ray): half from the view's eye into its field of view, half from points in and
// around the scene's box in any direction, some with a range that ends early.
inline void compare(const Build& build, const LitScene& scene, const NffView& view, float lambda, int rays, std::uint64_t seed, Disagreement& d)
{
    const Objects objects = objects_of(scene, lit_tests);
    const std::unique_ptr<Accelerator> built = [&] {
        const WorkingOn on([&] {
            return "building " + build.structure + " over " + std::to_string(objects.size()) + " objects" +
                   (build.build_asks.empty() ? std::string()
                                             : ", which asks your " + build.build_asks + ": a crash here is in one of them (start with their own cases)");
        });
        try {
            return build.make(objects, lambda);
        } catch (const std::exception& e) {
            if (build.suspect_build)
                FAIL(e.what() << build.suspect_build(objects, lambda));
            throw;
        }
    }();
    const Accelerator& structure = *built;
    Bounds box;
    for (int k = 0; k < objects.size(); ++k)
        box.grow(objects.bounds(k));
    Rng rng(seed, 3);
    for (int k = 0; k < rays; ++k) {
        const std::optional<SeededRay> seeded = seeded_ray(rng, view, box, k);
        if (!seeded)
            continue;
        const Ray& ray = seeded->ray;
        const Interval range = seeded->range;
        // Said only when the query crashes: then the diagnosis runs on this ray, as for a wrong answer.
        const WorkingOn on([&] {
            std::ostringstream s;
            s << show(ray) << ", t in (" << range.min << ", " << range.max << "), lambda " << lambda << ", "
              << objects.size() << " objects, through " << build.structure;
            if (build.suspect)
                s << suspect::guarded([&] { return build.suspect(structure, ray, range, objects); });
            return s.str();
        });
        ObjectHit want, got;
        const bool want_found = brute_force().closest(ray, range, objects, want);
        const bool got_found = structure.closest(ray, range, objects, got);
        const bool want_any = brute_force().any(ray, range, objects);
        const bool got_any = structure.any(ray, range, objects);
        ++d.rays;
        const bool same = want_found == got_found && (!want_found || (want.object == got.object && want.t == got.t));
        if (!same || want_any != got_any) {
            if (d.wrong++ == 0) {
                std::ostringstream s;
                s << show(ray) << ", t in (" << range.min << ", " << range.max << "), lambda " << lambda
                  << ": brute force finds " << answer(want_found, want) << " (any-hit " << want_any << "), " << build.structure << ' '
                  << answer(got_found, got) << " (any-hit " << got_any << ")";
                d.first = s.str();
                if (build.suspect)
                    d.suspect = build.suspect(structure, ray, range, objects);
            }
        }
    }
}

// Whether every ray agreed (a failed check otherwise, naming the first ray that differs).
inline bool check_scene(const Build& build, const NffScene& nff, int rays_per_lambda)
{
    const LitScene scene = lit_scene(nff);
    Disagreement d;
    std::uint64_t seed = 11;
    for (const float lambda : {0.3f, 2.0f, 9.0f})
        compare(build, scene, nff.view, lambda, rays_per_lambda, ++seed, d);
    INFO(nff.name << " (" << objects_of(scene, lit_tests).size() << " objects): " << d.wrong << " of " << d.rays
         << " rays answered differently from brute force; the first: " << d.first << d.suspect);
    CHECK(d.wrong == 0);
    return d.wrong == 0;
}

// check_scene on each scene file (*.nff) in `folder`: the kit's, RT_NFF_SCENES_DIR, in the chapters' tests.
inline bool check_scene_files(const Build& build, const std::string& folder, int rays_per_lambda)
{
    bool agreed = true;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".nff")
            agreed = check_scene(build, read_nff(entry.path().string()), rays_per_lambda) && agreed;
    return agreed;
}

// Twin triangles (every tie to the lower number), a floor 1e4 across under 200 spheres of radius
// 1e-3 (the floor is in every cell of its layer), and that scene 1e5 from the origin. Whether every
// ray agreed.
inline bool check_hard_cases(const Build& build)
{
    // Two copies of each triangle (object k and k + T): every tie goes to the lower number.
    LitScene twins;
    twins.add_material({});
    Rng rng(5, 5);
    std::vector<Triangle> tris;
    for (int k = 0; k < 60; ++k) {
        const point3 c(4 * rng.next_float(), 4 * rng.next_float(), 4 * rng.next_float());
        tris.push_back({c, c + vec3(0.7f, 0.1f, 0), c + vec3(0, 0.6f, 0.5f)});
    }
    for (int copy = 0; copy < 2; ++copy)
        for (const Triangle& t : tris)
            twins.add_triangle(t, 0);
    Disagreement d;
    NffView view;
    view.from = point3(2, 2, 12);
    view.at = point3(2, 2, 2);
    for (const float lambda : {0.5f, 4.0f})
        compare(build, twins, view, lambda, 1500, 40, d);
    INFO("twin triangles: " << d.wrong << " of " << d.rays << " rays answered differently; the first: " << d.first << d.suspect);
    CHECK(d.wrong == 0);
    bool agreed = d.wrong == 0;

    // A floor 1e4 across under 200 spheres of radius 1e-3: the floor is in every cell of its layer.
    for (const float offset : {0.0f, 1e5f}) {
        LitScene mixed;
        mixed.add_material({});
        const point3 o(offset, 0, -offset);
        mixed.add_triangle({o + point3(-5e3f, 0, -5e3f), o + point3(-5e3f, 0, 5e3f), o + point3(5e3f, 0, 5e3f)}, 0);
        mixed.add_triangle({o + point3(-5e3f, 0, -5e3f), o + point3(5e3f, 0, 5e3f), o + point3(5e3f, 0, -5e3f)}, 0);
        for (int k = 0; k < 200; ++k)
            mixed.add_sphere({o + point3(rng.next_float(), 0.01f + rng.next_float(), rng.next_float()), 1e-3f}, 0);
        Disagreement m;
        NffView near;
        near.from = o + point3(0.5f, 2, 3);
        near.at = o + point3(0.5f, 0, 0.5f);
        for (const float lambda : {1.0f, 16.0f})
            compare(build, mixed, near, lambda, 2000, 50, m);
        INFO("a floor under tiny spheres, offset by " << offset << ": " << m.wrong << " of " << m.rays
             << " rays answered differently; the first: " << m.first << m.suspect);
        CHECK(m.wrong == 0);
        agreed = agreed && m.wrong == 0;
    }
    return agreed;
}

}  // namespace rt::grader::agreement

