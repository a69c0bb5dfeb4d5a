// EXERCISE 08.4 (open): mailboxes in 1 KB. The gate first: the grid with your ray cache
// answers every ray as brute force does (closest and any hit), on the scenes 08.A uses, and your
// cache keeps to its own 1 KB. Then its cost: intersection tests per closest-hit ray on three
// generated scenes of long sticks, against the reference's, in three tiers (one case each, so the
// points add up by tier).
#include "07_uniform_grid/figure.hpp"
#include "08_mailboxing/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/grader/open_tiers.hpp"


using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;
using rt::grader::open_exercise::fixed;

namespace {

std::string said(bool found, const ObjectHit& h);

// The failing ray replayed, closest hit then any hit, on a copy of this thread's cache as the
// failing queries left it (the grid's own left alone), with the next signature: each call of your
// cached_intersect held to a fresh test of the same object in the same range. The first call that
// answers differently, or counts other than one test or one answer, in words; empty when every call
// kept its promise on the replay.
std::string first_wrong_call(const RayCacheGrid& grid, const Ray& ray, Interval range, const Objects& objects)
{
    ThreadRayCache t = grid.thread_cache();
    std::string wrong;
    const auto checked = [&](std::uint32_t signature, int k, Interval r, ObjectHit& hit) {
        ObjectHit want;
        const bool want_found = objects.intersect(k, ray, r, want);
        reset_counters();
        const bool found = cached_intersect(t.cache, signature, objects, k, ray, r, hit);
        const std::uint64_t tests = total_count(Counter::intersection_tests), answers = total_count(Counter::mailbox_hits);
        const bool same = found == want_found && (!found || (hit.object == want.object && hit.t == want.t &&
                                                             hit.beta == want.beta && hit.gamma == want.gamma));
        if (wrong.empty() && (!same || tests + answers != 1)) {
            std::ostringstream s;
            s.precision(9);
            s << "\n  replayed with signature " << signature << ": object " << k << " asked in (" << r.min << ", " << r.max
              << "): your cached_intersect gave " << said(found, hit) << " after " << tests << " tests and " << answers
              << " answers; a fresh test gives " << said(want_found, want) << " (each call: 1 test, or 0 and 1 answer)";
            wrong = s.str();
        }
        return want_found ? (hit = want, true) : false;  // the replay walks on with the right answer
    };
    ObjectHit hit;
    remembering_closest(grid.grid(), ray, range, objects, hit, [&] { return t.next(); },
                        [&](const Grid& g, const GridWalk& w, std::uint32_t signature, ObjectHit& best) {
                            return closest_in_cell_asking(g, w, range, best, [&](int k, Interval r, ObjectHit& h) {
                                return checked(signature, k, r, h);
                            });
                        });
    if (wrong.empty())
        remembering_any(grid.grid(), ray, range, objects, [&] { return t.next(); },
                        [&](std::uint32_t signature, int k, ObjectHit& h) { return checked(signature, k, range, h); });
    return wrong.empty() ? "\n  replayed, every call of your cached_intersect answered as a fresh test" : wrong;
}

const Build cached{"the grid with your ray cache (08.4)",
                   [](const Objects& objects, float lambda) { return std::make_unique<RayCacheGrid>(objects, lambda); },
                   [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                       return first_wrong_call(dynamic_cast<const RayCacheGrid&>(built), ray, range, objects);
                   }};

std::string said(bool found, const ObjectHit& h)
{
    std::ostringstream s;
    s.precision(9);
    if (found)
        s << "a hit on object " << h.object << " at t " << h.t << " (beta " << h.beta << ", gamma " << h.gamma << ")";
    else
        s << "no hit";
    return s.str();
}

// The contract's own words, called directly on objects of sticks 1 that seeded rays hit (brute
// force's closest). Each object k hit at t > 0 along a ray is missed along the reversed ray from
// the same origin. Then: cache A, signature 1, the reversed ray (a miss); cache B, signature 1, the
// ray, twice (another thread's ray with the same number: tested, a hit, then the same hit bit for
// bit, beta and gamma too, in 1 test then at most 1 answer); cache A, signature 2, the ray (a new
// ray: what signature 1 left must not answer). A cache that keeps anything outside RayCache, or
// answers another signature's entry, fails here.
bool check_calls()
{
    const NffScene nff = generated_scene(write_sticks, 1, "sticks 1");
    const LitScene scene = lit_scene(nff);
    const Objects objects = objects_of(scene, lit_tests);
    Bounds box;
    for (int k = 0; k < objects.size(); ++k)
        box.grow(objects.bounds(k));
    Rng rng(5, 3);
    int checked = 0;
    for (int n = 0; n < 400 && checked < 30; ++n) {
        const std::optional<SeededRay> r = seeded_ray(rng, nff.view, box, n);
        ObjectHit first_hit;
        if (!r || !brute_force().closest(r->ray, {0.0f, infinity}, objects, first_hit) || !(first_hit.t > 0.0f))
            continue;
        ++checked;
        const int k = first_hit.object;
        const Interval range{0.0f, infinity};
        const Ray& ray = r->ray;
        const Ray back{ray.origin, -ray.dir};
        ObjectHit want, want_back;
        const bool hits = objects.intersect(k, ray, range, want);
        const bool hits_back = objects.intersect(k, back, range, want_back);
        RayCache a, b;
        ObjectHit got_back, got, again, later;
        const bool f_back = cached_intersect(a, 1, objects, k, back, range, got_back);
        reset_counters();
        const bool f = cached_intersect(b, 1, objects, k, ray, range, got);
        const bool f_again = cached_intersect(b, 1, objects, k, ray, range, again);
        const std::uint64_t tests = total_count(Counter::intersection_tests), answers = total_count(Counter::mailbox_hits);
        const bool f_later = cached_intersect(a, 2, objects, k, ray, range, later);
        const auto same = [](bool fa, const ObjectHit& x, bool fb, const ObjectHit& y) {
            return fa == fb && (!fa || (x.object == y.object && x.t == y.t && x.beta == y.beta && x.gamma == y.gamma));
        };
        // An object this ray misses, asked first in a fresh cache: no earlier test of this ray can
        // answer for it, so it is tested (a call that answers it unasked, by a box or a guess, costs
        // nothing the cost would count).
        const int missed = (k + 1) % objects.size();
        ObjectHit unused;
        RayCache c;
        reset_counters();
        const bool f_missed = cached_intersect(c, 3, objects, missed, ray, range, unused);
        const std::uint64_t missed_tests = total_count(Counter::intersection_tests);
        const bool missed_ok = objects.intersect(missed, ray, range, unused) ? true : (!f_missed && missed_tests == 1);
        const bool ok = same(f_back, got_back, hits_back, want_back) && same(f, got, hits, want) &&
                        same(f_again, again, hits, want) && tests + answers == 2 && tests >= 1 &&
                        same(f_later, later, hits, want) && missed_ok;
        INFO("object " << k << " of sticks 1 (t in (0, inf) each time): cache A, signature 1, along " << show(back)
                       << ": your cached_intersect gave " << said(f_back, got_back) << ", a fresh test "
                       << said(hits_back, want_back) << ". Cache B (another thread), signature 1, along " << show(ray)
                       << ", twice: " << said(f, got) << ", then " << said(f_again, again) << ", after " << tests
                       << " tests and " << answers << " answers; a fresh test gives " << said(hits, want)
                       << " (1 test, then 1 test or 1 answer). Cache A, signature 2 (a new ray), along the same: "
                       << said(f_later, later) << ". Each call answers as a fresh test would, bit for bit; nothing "
                       << "is kept outside the cache, and no entry answers for another signature. Cache C, "
                       << "signature 3, object " << missed << " (which this ray misses), asked first: "
                       << (f_missed ? "a hit" : "no hit") << " after " << missed_tests
                       << " tests; a call with nothing of this ray's to answer from is tested (1 test)");
        CHECK(ok);
        if (!ok)
            return false;
    }
    return true;
}

// The gate: 08.A's scenes and rays, ties, a huge floor, far away; and the calls above. Whether
// the cache passed it.
bool check_gate()
{
    INFO("the gate of 08.4: a cache that answers a call or a ray differently from a fresh test or brute force "
         "scores 0 in every 08.4 case");
    const bool calls = check_calls();
    return open_exercise::agrees_with_brute_force(cached, 300,
                                                  {{write_sticks, 1, "sticks 1", 500},
                                                   {write_sticks, 3, "sticks 3", 300},
                                                   {write_tree, 3, "tree 3", 300}}) &&
           calls;
}

// The scenes 08.4's cost is measured on (the contract's "three of the kit's generated scenes of
// long sticks"), with the reference's tests per ray on each (grader.ch08.open_reference_costs...
// holds these to the solution's).
struct CostScene {
    const char* name;
    int depth;
    float lambda;
    double reference;  // the reference cache's tests per ray
};
const CostScene cost_scenes[] = {
    {"sticks 3 at lambda 16", 3, 16.0f, 15.742432},
    {"sticks 4 at lambda 32", 4, 32.0f, 20.493164},
    {"sticks 5 at lambda 64", 5, 64.0f, 31.910645},
};
constexpr int cost_rays = 4096;  // seeded rays per scene (seeded_ray), closest hits

// Intersection tests per closest-hit ray through the grid make(objects, lambda) builds over a scene,
// on cost_rays seeded rays.
template <class Make>
double tests_per_ray(const CostScene& c, Make&& make)
{
    return open_exercise::count_closest(generated_scene(write_sticks, c.depth, c.name), cost_rays,
                                        [&](const Objects& objects) { return make(objects, c.lambda); })
        .per_ray(Counter::intersection_tests);
}

double cache_tests_per_ray(const CostScene& c)
{
    return tests_per_ray(c, [](const Objects& o, float lambda) { return std::make_unique<RayCacheGrid>(o, lambda); });
}

}  // namespace

OPEN_EXERCISE_TIERS("cached_intersect (open): a correct cache", " tests", "08.4", 4, check_gate, cost_scenes,
                    cache_tests_per_ray, "tests per ray", "your cache's cost (intersection tests per closest-hit ray)")

// The kit's own check (not graded; grader.ch08.open_reference_costs_are_the_solutions runs it on
// the solutions): the reference costs above are what the reference cache measures now, and the
// lesson's other figures on the same rays: the per-object mailboxes and no mailboxes at all.
TEST_CASE("08.4's stored reference costs are the reference cache's", "[.][open_reference_costs]")
{
    for (const CostScene& c : cost_scenes) {
        const double reference = cache_tests_per_ray(c);
        const double mailboxes = tests_per_ray(c, [](const Objects& o, float l) { return std::make_unique<MailboxGrid>(o, l); });
        const double none = tests_per_ray(c, [](const Objects& o, float l) { return std::make_unique<UniformGrid>(o, l); });
        WARN(c.name << ": reference " << fixed(reference, 6) << ", a mailbox per object " << fixed(mailboxes, 4)
                    << " (" << fixed(mailboxes / reference, 3) << "x), no mailboxes " << fixed(none, 4) << " ("
                    << fixed(none / reference, 3) << "x)");
        CHECK(fixed(reference, 6) == fixed(c.reference, 6));
    }
}
