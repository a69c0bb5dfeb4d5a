// The grid as a whole (EXERCISES 07.1-07.6 with the given build): on seeded rays over the kit's
// scene files and its generated scenes, at several densities, it must answer every query as
// brute force does: the same object at the same t, bit for bit, and the same any-hit answer.
#include "04_shadow_feelers/nff_scene.hpp"
#include "07_uniform_grid/figure.hpp"
#include "common/random.hpp"
#include "tests/ch07/describe.hpp"

#include <filesystem>

using namespace rt;
using namespace rt::grader;

namespace {

struct Disagreement {
    int rays = 0, wrong = 0;
    std::string first;  // the first wrong answer, in words
};

std::string answer(bool found, const ObjectHit& h)
{
    if (!found)
        return "no hit";
    std::ostringstream s;
    s.precision(9);
    s << "object " << h.object << " at t = " << h.t;
    return s.str();
}

// `rays` seeded rays: half from the view's eye into its field of view, half from points in and
// around the scene's box in any direction, some with a range that ends early.
void compare(const LitScene& scene, const NffView& view, float lambda, int rays, std::uint64_t seed, Disagreement& d)
{
    const Objects objects = objects_of(scene, lit_tests);
    const UniformGrid grid(objects, lambda);
    Bounds box;
    for (int k = 0; k < objects.size(); ++k)
        box.grow(objects.bounds(k));
    const vec3 e = box.extent();
    Rng rng(seed, 3);
    const auto u = [&] { return rng.next_float(); };
    for (int k = 0; k < rays; ++k) {
        Ray ray;
        if (k % 2 == 0) {
            const vec3 ahead = glm::normalize(view.at - view.from);
            ray = {view.from, glm::normalize(ahead + 0.6f * vec3(2 * u() - 1, 2 * u() - 1, 2 * u() - 1))};
        } else {
            vec3 dir(2 * u() - 1, 2 * u() - 1, 2 * u() - 1);
            if (u() < 0.1f)
                dir[static_cast<int>(u() * 3)] = 0.0f;  // some rays parallel to a slab
            if (dir == vec3(0.0f))
                continue;
            ray = {box.min - 0.25f * e + 1.5f * e * vec3(u(), u(), u()), glm::normalize(dir)};
        }
        const Interval range{u() < 0.5f ? 0.0f : 1e-4f, u() < 0.2f ? glm::length(e) * u() : infinity};
        ObjectHit want, got;
        const bool want_found = brute_force().closest(ray, range, objects, want);
        const bool got_found = grid.closest(ray, range, objects, got);
        const bool want_any = brute_force().any(ray, range, objects);
        const bool got_any = grid.any(ray, range, objects);
        ++d.rays;
        const bool same = want_found == got_found && (!want_found || (want.object == got.object && want.t == got.t));
        if (!same || want_any != got_any) {
            if (d.wrong++ == 0) {
                std::ostringstream s;
                s << show(ray) << ", t in (" << range.min << ", " << range.max << "), lambda " << lambda
                  << ": brute force finds " << answer(want_found, want) << " (any-hit " << want_any << "), the grid "
                  << answer(got_found, got) << " (any-hit " << got_any << ")";
                d.first = s.str();
            }
        }
    }
}

void check_scene(const NffScene& nff, int rays_per_lambda)
{
    const LitScene scene = lit_scene(nff);
    Disagreement d;
    std::uint64_t seed = 11;
    for (const float lambda : {0.3f, 2.0f, 9.0f})
        compare(scene, nff.view, lambda, rays_per_lambda, ++seed, d);
    INFO(nff.name << " (" << objects_of(scene, lit_tests).size() << " objects): " << d.wrong << " of " << d.rays
         << " rays answered differently from brute force; the first: " << d.first);
    CHECK(d.wrong == 0);
}

}  // namespace

GRADED_TEST("the grid answers every ray as brute force does, object and t, on the kit's scene files", "07.A", 4)
{
    for (const auto& entry : std::filesystem::directory_iterator(RT_NFF_SCENES_DIR))
        if (entry.path().extension() == ".nff")
            check_scene(read_nff(entry.path().string()), 1500);
}

GRADED_TEST("the grid answers every ray as brute force does on the generated sphereflake, pyramid, tree and mountain", "07.A", 4)
{
    check_scene(ch07::generated_scene(write_sphereflake, 2, "sphereflake 2"), 800);
    check_scene(ch07::generated_scene(write_pyramid, 3, "pyramid 3"), 800);
    check_scene(ch07::generated_scene(write_tree, 3, "tree 3"), 800);
    check_scene(ch07::generated_scene(write_mountain, 4, "mountain 4"), 800);
}

STABILITY_TEST("the grid answers as brute force does on ties, a huge floor under tiny objects, and far from the origin", "07.A", 4)
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
        compare(twins, view, lambda, 1500, 40, d);
    INFO("twin triangles: " << d.wrong << " of " << d.rays << " rays answered differently; the first: " << d.first);
    CHECK(d.wrong == 0);

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
            compare(mixed, near, lambda, 2000, 50, m);
        INFO("a floor under tiny spheres, offset by " << offset << ": " << m.wrong << " of " << m.rays
             << " rays answered differently; the first: " << m.first);
        CHECK(m.wrong == 0);
    }
}
