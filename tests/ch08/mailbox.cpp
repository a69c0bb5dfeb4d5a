// EXERCISE 08.2: one object tested through its mailbox: tested once per ray, answered from the
// mailbox after that, right as the query's range shrinks.
#include "08_mailboxing/08_mailboxing.hpp"
#include "tests/ch08/hand_mailboxes.hpp"

#include <iomanip>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::hand_grid;

namespace {

struct Asked {
    bool found;
    ObjectHit hit;
    std::uint64_t tests, answered;
};

Asked ask(Mailboxes& m, std::uint32_t signature, int k, Interval range)
{
    reset_counters();
    ObjectHit hit;
    const bool found = mailboxed_intersect(m, signature, objects(), k, ray, range, hit);
    return {found, hit, total_count(Counter::intersection_tests), total_count(Counter::mailbox_hits)};
}

std::string show_asked(const Asked& a)
{
    std::ostringstream s;
    s << (a.found ? grader::show(a.hit) : std::string("no hit")) << " after " << a.tests << " intersection tests and "
      << a.answered << " answers from the mailbox";
    return s.str();
}

}  // namespace

GRADED_TEST("mailboxed_intersect: the first time a ray meets an object it is tested and the answer is stored", "08.2", 3)
{
    Mailboxes m = fresh_mailboxes();
    const Asked a = ask(m, 7, 2, all);
    INFO("ray 7 meets sphere 2 (hit at t = 1.3) for the first time: " << show_asked(a) << "; its mailbox now holds ray "
         << m.box[2].ray << ", t = " << m.box[2].t << "; expected a hit after 1 test, the mailbox holding ray 7 and t = 1.3");
    CHECK(a.found);
    CHECK(a.hit.object == 2);
    CHECK(a.tests == 1);
    CHECK(a.answered == 0);
    CHECK(m.box[2].ray == 7);
    CHECK(m.box[2].t == a.hit.t);
    const Asked miss = ask(m, 7, 3, {0.0f, 1.5f});
    INFO("ray 7 meets the triangle (object 3, hit at t = 2) with t in (0, 1.5): " << show_asked(miss) << "; its mailbox holds ray "
         << m.box[3].ray << ", t = " << m.box[3].t << "; expected a miss after 1 test, stored as t = infinity");
    CHECK(!miss.found);
    CHECK(miss.tests == 1);
    CHECK(m.box[3].ray == 7);
    CHECK(std::isinf(m.box[3].t));
}

GRADED_TEST("mailboxed_intersect: the same ray meeting the object again is answered from the mailbox, untested", "08.2", 4)
{
    Mailboxes m = fresh_mailboxes();
    const Asked first = ask(m, 7, 1, all);
    const Asked again = ask(m, 7, 1, all);
    INFO("ray 7 meets sphere 1 twice: first " << show_asked(first) << ", then " << show_asked(again)
         << "; expected the same hit, the second time with no test and 1 answer from the mailbox");
    CHECK(again.found);
    CHECK(again.hit.object == 1);
    CHECK(again.hit.t == first.hit.t);
    CHECK(again.tests == 0);
    CHECK(again.answered == 1);
    // A triangle's answer keeps where on the triangle the ray hit.
    const Asked tri = ask(m, 7, 4, all);
    const Asked tri_again = ask(m, 7, 4, all);
    INFO("the triangle, object 4, twice: " << show_asked(tri) << " (beta " << tri.hit.beta << ", gamma " << tri.hit.gamma
         << "), then " << show_asked(tri_again) << " (beta " << tri_again.hit.beta << ", gamma " << tri_again.hit.gamma << ")");
    CHECK(tri_again.tests == 0);
    CHECK(tri_again.hit.beta == tri.hit.beta);
    CHECK(tri_again.hit.gamma == tri.hit.gamma);
    // A stored miss is a miss.
    ask(m, 7, 0, {0.0f, 2.0f});
    const Asked miss_again = ask(m, 7, 0, {0.0f, 1.8f});
    INFO("sphere 0 (hit at t = 3.3) missed in (0, 2), asked again in (0, 1.8): " << show_asked(miss_again));
    CHECK(!miss_again.found);
    CHECK(miss_again.tests == 0);
}

GRADED_TEST("mailboxed_intersect: a stored hit counts only inside the range asked now; another ray is tested again", "08.2", 4)
{
    Mailboxes m = fresh_mailboxes();
    ask(m, 7, 0, all);  // sphere 0 hit at t = 3.3 in cell 0, beyond it: stored all the same
    const Asked nearer = ask(m, 7, 0, {0.0f, 3.0f});
    INFO("sphere 0's stored hit at t = 3.3, asked for t in (0, 3) (a nearer hit found meanwhile): " << show_asked(nearer)
         << "; expected a miss, from the mailbox");
    CHECK(!nearer.found);
    CHECK(nearer.tests == 0);
    CHECK(nearer.answered == 1);
    const Asked still = ask(m, 7, 0, {0.0f, 3.5f});
    INFO("asked for t in (0, 3.5): " << show_asked(still) << "; expected the stored hit");
    CHECK(still.found);
    CHECK(still.tests == 0);
    const Asked other = ask(m, 8, 0, all);
    INFO("ray 8 meets sphere 0: " << show_asked(other) << "; expected a test (the mailbox holds ray 7's answer)");
    CHECK(other.found);
    CHECK(other.tests == 1);
    CHECK(other.answered == 0);
    CHECK(m.box[0].ray == 8);
}

namespace {

// Object k asked for `r`, a ray of its own (not hand_grid's), counting as ask() does.
Asked ask_along(Mailboxes& m, std::uint32_t signature, int k, const Ray& r, Interval range)
{
    reset_counters();
    ObjectHit hit;
    const bool found = mailboxed_intersect(m, signature, objects(), k, r, range, hit);
    return {found, hit, total_count(Counter::intersection_tests), total_count(Counter::mailbox_hits)};
}

}  // namespace

GRADED_TEST("mailboxed_intersect: a miss is stored over the previous ray's hit, and a stored miss is a miss even in a range open to infinity",
            "08.2", 3)
{
    Mailboxes m = fresh_mailboxes();
    const Asked six = ask(m, 6, 2, all);  // ray 6 hits sphere 2 at t = 1.3 and leaves that in its mailbox
    const Ray by{{-1, 1.0f, 0.5f}, {1, 0, 0}};  // passes 0.5 above sphere 2's centre: its radius is 0.2
    const Asked seven = ask_along(m, 7, 2, by, all);
    INFO("08.2: ray 6 hit sphere 2 (" << show_asked(six) << "); then ray 7, " << grader::show(by)
         << ", passes it by: " << show_asked(seven) << "; sphere 2's mailbox now holds ray " << m.box[2].ray << ", t = "
         << m.box[2].t << "; expected a miss after 1 test, the mailbox holding ray 7 and t = infinity (not ray 6's t)");
    CHECK(!seven.found);
    CHECK(seven.tests == 1);
    CHECK(m.box[2].ray == 7);
    CHECK(std::isinf(m.box[2].t));
    const Asked again = ask_along(m, 7, 2, by, all);
    INFO("08.2: ray 7 asks sphere 2 again, t in (0, infinity): " << show_asked(again)
         << "; expected a miss from the mailbox (1 answer, no test): a stored miss is t = infinity, which no range "
         "holds strictly inside it, not even one open to infinity");
    CHECK(!again.found);
    CHECK(again.tests == 0);
    CHECK(again.answered == 1);
    // A fresh mailbox, a miss, the same question again.
    Mailboxes n = fresh_mailboxes();
    ask_along(n, 1, 0, by, all);
    const Asked fresh_again = ask_along(n, 1, 0, by, all);
    INFO("08.2: on fresh mailboxes ray 1 passes sphere 0 by, twice, t in (0, infinity): the second time " << show_asked(fresh_again)
         << "; expected a miss from the mailbox");
    CHECK(!fresh_again.found);
    CHECK(fresh_again.tests == 0);
    CHECK(fresh_again.answered == 1);
}

GRADED_TEST("mailboxed_intersect: a stored hit exactly at the range's end or start is outside it; one float step inside, it counts",
            "08.2", 3)
{
    Mailboxes m = fresh_mailboxes();
    const Asked first = ask(m, 7, 0, all);  // sphere 0 hit at t = 3.3, stored
    REQUIRE(first.found);
    const float t = first.hit.t;
    const struct {
        Interval range;
        bool hit;
        const char* why;
    } cases[] = {{{0.0f, t}, false, "the range ends exactly at the stored t"},
                 {{0.0f, std::nextafter(t, infinity)}, true, "the range ends one float step beyond the stored t"},
                 {{t, infinity}, false, "the range starts exactly at the stored t"},
                 {{std::nextafter(t, 0.0f), infinity}, true, "the range starts one float step before the stored t"}};
    for (const auto& c : cases) {
        const Asked a = ask(m, 7, 0, c.range);
        INFO("08.2: sphere 0's mailbox holds ray 7's hit at t = " << std::setprecision(9) << t << "; ray 7 asks again for t in ("
             << c.range.min << ", " << c.range.max << ") (" << c.why << "): " << show_asked(a) << "; expected "
             << (c.hit ? "the stored hit" : "a miss") << " from the mailbox (1 answer, no test): a stored hit counts only "
             "strictly inside the range");
        CHECK(a.found == c.hit);
        CHECK(a.tests == 0);
        CHECK(a.answered == 1);
        if (c.hit && a.found) {
            CHECK(a.hit.t == t);
            CHECK(a.hit.object == 0);
        }
    }
}
