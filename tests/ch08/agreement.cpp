// The grid with mailboxes as a whole (EXERCISES 08.1-08.3 with chapter 07's grid and walk):
// brute force's answers on every ray; the grid's own answers with each object tested at most once
// per ray; right across the signature counter's wrap.
#include "07_uniform_grid/figure.hpp"
#include "08_mailboxing/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch08/mailbox_suspect.hpp"

#include <limits>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

// A failing case replays the query on the first ray that differs, exercise by exercise (mailbox_suspect.hpp).
const Build mailboxed{"the grid with mailboxes",
                      [](const Objects& objects, float lambda) { return std::make_unique<MailboxGrid>(objects, lambda); },
                      [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                          return suspect::diagnose_mailboxed(dynamic_cast<const MailboxGrid&>(built), ray, range, objects);
                      }};


}  // namespace

GRADED_TEST("the grid with mailboxes answers every ray as brute force does, on the kit's scenes and generated ones", "08.A", 4)
{
    check_scene_files(mailboxed, RT_NFF_SCENES_DIR, 800);
    check_scene(mailboxed, generated_scene(write_sticks, 1, "sticks 1"), 800);
    check_scene(mailboxed, generated_scene(write_tree, 3, "tree 3"), 500);
    check_scene(mailboxed, generated_scene(write_mountain, 4, "mountain 4"), 500);
}

STABILITY_TEST("the grid with mailboxes answers as brute force does on ties, a huge floor and far from the origin", "08.A", 3)
{
    check_hard_cases(mailboxed);
}

GRADED_TEST("with mailboxes no object is tested twice by one ray: each ray's tests are as many as the objects it tested, and every cell reference is a test or an answer", "08.A", 4)
{
    const NffScene nff = generated_scene(write_sticks, 1, "sticks 1");
    const LitScene scene = lit_scene(nff);
    const Objects objects = objects_of(scene, lit_tests);
    const UniformGrid plain(objects, 8.0f);
    const MailboxGrid grid(objects, 8.0f);
    Rng rng(21, 2);
    int different = 0, rays = 0, twice = 0;
    std::string first_twice, first_different;
    std::uint64_t plain_tests = 0, tests = 0, answers = 0;
    for (int k = 0; k < 2000; ++k) {
        const point3 o(4 * rng.next_float() - 2, 1.5f * rng.next_float(), 4 * rng.next_float() - 2);
        const vec3 d = glm::normalize(vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1));
        ObjectHit a, b;
        reset_counters();
        plain.closest({o, d}, {0.0f, infinity}, objects, a);
        plain_tests += total_count(Counter::intersection_tests);
        reset_counters();
        const std::uint32_t before = grid.mailboxes().last_signature;
        grid.closest({o, d}, {0.0f, infinity}, objects, b);
        const std::uint64_t ray_tests = total_count(Counter::intersection_tests);
        tests += ray_tests;
        answers += total_count(Counter::mailbox_hits);
        ++rays;
        if ((a.object != b.object || a.t != b.t) && different++ == 0)
            first_different = show(Ray{o, d}) + ": without mailboxes " + show(a) + ", with them " + show(b) +
                              suspect::diagnose_mailboxed(grid, {o, d}, {0.0f, infinity}, objects);
        // Each test stores the ray's signature in its object's mailbox: the objects this ray tested
        // are those whose mailbox holds its signature, and each was tested once only if there are
        // as many of them as tests. (A ray that meets no cell takes no signature and tests nothing.)
        const std::uint32_t signature = grid.mailboxes().last_signature;
        std::uint64_t tested = 0;
        if (signature != before)
            for (const Mailbox& box : grid.mailboxes().box)
                tested += box.ray == signature;
        if (ray_tests != tested && twice++ == 0)
            first_twice = show(Ray{o, d}) + ": " + std::to_string(ray_tests) + " tests, of " + std::to_string(tested) +
                          " objects (their mailboxes hold the ray's signature " + std::to_string(signature) + ")" +
                          suspect::diagnose_mailboxed(grid, {o, d}, {0.0f, infinity}, objects);
    }
    INFO(rays << " seeded rays through the sticks at 8 cells per object: " << twice << " rays made more tests than the "
         "objects they tested (or tested objects their mailboxes do not show); the first: " << first_twice);
    CHECK(twice == 0);
    INFO("without mailboxes " << plain_tests << " tests; with them " << tests << " tests and " << answers
         << " answers from mailboxes (they must add up to " << plain_tests << ", with fewer tests); " << different
         << " rays answered differently" << (different ? "; the first: " + first_different : std::string()));
    CHECK(different == 0);
    CHECK(tests + answers == plain_tests);
    CHECK(answers > 0);
}

GRADED_TEST("the grid with mailboxes stays right across the 32-bit signature counter's wrap", "08.A", 4)
{
    const NffScene nff = generated_scene(write_sticks, 1, "sticks 1");
    const LitScene scene = lit_scene(nff);
    const Objects objects = objects_of(scene, lit_tests);
    const MailboxGrid grid(objects, 8.0f);
    // Rays 0-199 get signatures 1-200 and leave their answers in the mailboxes. Then the counter is
    // set to its last value, so rays 200-399 get 1-200 again, after the wrap: each is ray k - 200
    // moved aside a little, so it meets the same sticks at other t, and an answer left by the old
    // ray of its signature is wrong for it.
    Rng rng(4, 4);
    std::vector<Ray> rays;
    for (int k = 0; k < 200; ++k) {
        const point3 o(4 * rng.next_float() - 2, 1.5f * rng.next_float(), 4 * rng.next_float() - 2);
        rays.push_back({o, glm::normalize(vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1))});
    }
    for (int k = 0; k < 200; ++k)
        rays.push_back({rays[k].origin + 0.02f * glm::normalize(glm::cross(rays[k].dir, vec3(0, 1, 0))), rays[k].dir});
    int wrong = 0;
    std::string first;
    for (int k = 0; k < 400; ++k) {
        if (k == 200)
            grid.mailboxes().last_signature = std::numeric_limits<std::uint32_t>::max();
        ObjectHit want, got;
        const bool w = brute_force().closest(rays[k], {0.0f, infinity}, objects, want);
        const bool g = grid.closest(rays[k], {0.0f, infinity}, objects, got);
        if (w != g || (w && (want.object != got.object || want.t != got.t))) {
            if (wrong++ == 0)
                first = "ray " + std::to_string(k) + ": brute force " + (w ? show(want) : "no hit") + ", the grid " +
                        (g ? show(got) : "no hit") + suspect::diagnose_mailboxed(grid, rays[k], {0.0f, infinity}, objects, true);
        }
    }
    INFO("400 rays, the signature counter set to 2^32 - 1 after the first 200, so that rays 200-399 reuse "
         "signatures 1-200: " << wrong << " answered differently from brute force; the first: " << first);
    CHECK(wrong == 0);

    // One sphere: ray A (signature 1) passes it by, inside its cell; after the wrap ray B, signature
    // 1 again, aims at its centre. A mailbox still holding A's miss under signature 1 loses B's hit.
    const std::vector<Sphere> one = {{{0, 0, 0}, 0.5f}};
    Objects sphere;
    sphere.spheres = one.data();
    sphere.sphere_count = 1;
    const MailboxGrid single(sphere, 1.0f);
    ObjectHit hit;
    single.mailboxes().last_signature = 0;
    const bool a = single.closest({{-5, 0.45f, 0.45f}, {1, 0, 0}}, {0.0f, infinity}, sphere, hit);
    single.mailboxes().last_signature = std::numeric_limits<std::uint32_t>::max();
    const bool b = single.closest({{-5, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, sphere, hit);
    INFO("ray A passes the sphere by (signature 1): " << (a ? "hit" : "no hit") << "; the counter wraps; ray B, "
         "aimed at the sphere's centre with signature 1 again: " << (b ? show(hit) : "no hit")
         << "; expected a hit at t = 4.5" << (a || !b ? suspect::diagnose_mailboxed(single, {{-5, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, sphere, true) : ""));
    CHECK(!a);
    CHECK(b);
    // A counter that wraps on a set whose mailboxes are still empty: the signature must not be 0,
    // which every empty mailbox holds.
    const MailboxGrid fresh(sphere, 1.0f);
    fresh.mailboxes().last_signature = std::numeric_limits<std::uint32_t>::max();
    const bool c = fresh.closest({{-5, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, sphere, hit);
    INFO("a fresh grid whose counter wraps at its first ray, aimed at the sphere: " << (c ? show(hit) : "no hit")
         << " (signature " << fresh.mailboxes().last_signature << "); expected a hit"
         << (c ? "" : suspect::diagnose_mailboxed(fresh, {{-5, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, sphere, true)));
    CHECK(c);
}
