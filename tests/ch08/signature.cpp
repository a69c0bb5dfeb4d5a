// EXERCISE 08.1: ray signatures, and what happens when the 32-bit counter runs out.
#include "08_mailboxing/08_mailboxing.hpp"
#include "tests/grader/graded.hpp"

#include <cstdint>
#include <limits>

using namespace rt;

namespace {

Mailboxes full_of(std::uint32_t signature, int objects)
{
    Mailboxes m;
    m.box.assign(static_cast<size_t>(objects), Mailbox{signature, 1.0f, 0.0f, 0.0f});
    return m;
}

}  // namespace

GRADED_TEST("next_signature: each ray gets the next number, 1 first, and it is remembered", "08.1", 3)
{
    Mailboxes m = full_of(0, 4);
    for (std::uint32_t expected = 1; expected <= 5; ++expected) {
        const std::uint32_t got = next_signature(m);
        INFO("call " << expected << " of next_signature on a fresh set: got " << got << ", expected " << expected
             << "; last_signature is " << m.last_signature);
        CHECK(got == expected);
        CHECK(m.last_signature == expected);
    }
    m.last_signature = 1000;
    m.box[2].ray = 999;  // an answer stored by an earlier ray
    const std::uint32_t got = next_signature(m);
    INFO("after last_signature = 1000: got " << got << ", expected 1001");
    CHECK(got == 1001);
    INFO("the mailboxes must be left alone while the counter has not wrapped: mailbox 2 holds ray " << m.box[2].ray
         << ", expected 999 still");
    CHECK(m.box[2].ray == 999);
}

GRADED_TEST("next_signature: when the counter wraps, every mailbox is emptied and the next signature is 1", "08.1", 4)
{
    constexpr std::uint32_t last = std::numeric_limits<std::uint32_t>::max();
    Mailboxes m = full_of(1, 6);  // answers stored by ray 1, about 4e9 rays ago
    m.box[3].ray = 2;
    m.box[5].ray = last;
    m.last_signature = last - 1;
    const std::uint32_t before = next_signature(m);
    INFO("from last_signature = 2^32 - 2: got " << before << ", expected 2^32 - 1 = " << last);
    CHECK(before == last);
    CHECK(m.box[0].ray == 1);
    const std::uint32_t after = next_signature(m);
    INFO("from last_signature = 2^32 - 1 the counter wraps: got " << after
         << ", expected 1 (0 means no ray); the mailboxes hold rays " << m.box[0].ray << ", " << m.box[3].ray << ", "
         << m.box[5].ray << ", expected all 0: ray 1's old answers must not be taken for the new ray 1's");
    CHECK(after == 1);
    CHECK(m.last_signature == 1);
    for (const Mailbox& b : m.box)
        CHECK(b.ray == 0);
}
