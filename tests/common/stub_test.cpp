// The stubs' record: which exercises ran from stubs, by name "NN.k", in chapter and number order.
#include "common/stub.hpp"

#include "tests/grader/graded.hpp"

#include <string>
#include <vector>

using rt::forget_stubs;
using rt::note_stub;
using rt::stubs_that_ran;

TEST_CASE("stubs that ran are listed once each, in chapter and exercise order", "[stub]")
{
    forget_stubs();
    note_stub("10.12");
    note_stub("07.2");
    note_stub("07.2");
    note_stub("01.1");
    CHECK(stubs_that_ran() == std::vector<std::string>{"01.1", "07.2", "10.12"});
    forget_stubs();
    CHECK(stubs_that_ran().empty());
}

TEST_CASE("a stub whose name is not NN.k with k below 16 is not recorded", "[stub]")
{
    forget_stubs();
    for (const char* bad : {"", "7.1", "07", "07.", "07.x", "07.1x", "07.16", "07.123", "a7.1", "07-1"}) {
        note_stub(bad);
        INFO("name \"" << bad << "\"");
        CHECK(stubs_that_ran().empty());
    }
    note_stub("07.15");
    CHECK(stubs_that_ran() == std::vector<std::string>{"07.15"});
    forget_stubs();
}
