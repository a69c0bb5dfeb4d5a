#include "common/lesson_table.hpp"

#include "tests/grader/graded.hpp"

#include <sstream>

using namespace rt;

TEST_CASE("a lesson's numbers read as a lesson writes them", "[common]")
{
    CHECK(scientific(0.0206894, 3) == "2.07e-2");
    CHECK(scientific(1.5e12, 2) == "1.5e12");
    CHECK(scientific(0.0, 3) == "0");
    CHECK(grouped(0) == "0");
    CHECK(grouped(999) == "999");
    CHECK(grouped(1000) == "1,000");
    CHECK(grouped(101185778) == "101,185,778");
    CHECK(fixed(146.66, 1) == "146.7");
    CHECK(fixed(-0.4, 0) == "0");
    CHECK(fixed(-2.4, 0) == "-2");
    CHECK(significant(0.0104321, 3) == "0.0104");
    CHECK(significant(0.9, 3) == "0.900");
    CHECK(significant(146.66, 2) == "147");
    CHECK(significant(0.0, 3) == "0");
}

TEST_CASE("a time's spread is its farthest run from the median, and a single run has none", "[common]")
{
    CHECK(spread(timing_of({1.0, 1.1, 0.8})) == " ±20%");
    CHECK(spread(timing_of({2.0})).empty());
    CHECK(spread(Timing{}).empty());
    const Timing t = timing_of({3.0, 1.0, 2.0, 10.0});
    CHECK(t.median == 2.5);
    CHECK(t.min == 1.0);
    CHECK(t.max == 10.0);
    CHECK(t.runs == 4);
}

TEST_CASE("a lesson table names its timed columns in its marker and ends with its end marker", "[common]")
{
    LessonTable t{"07.lambda", {{"lambda"}, {"render ms", true}, {"tests/ray"}, {"build ms", true}}, {}, "How."};
    t.row({"1", "2.0 ±3%", "4.5", "0.1"});
    std::ostringstream out;
    write_lesson_table(out, t);
    const std::string text = out.str();
    INFO(text);
    CHECK(text.rfind("<!-- table 07.lambda timed: render ms; build ms -->\n| lambda | render ms | tests/ray | build ms |\n", 0) == 0);
    CHECK(text.find("| 1 | 2.0 ±3% | 4.5 | 0.1 |\n") != std::string::npos);
    CHECK(text.find("\nHow. Timed on ") != std::string::npos);
    CHECK(text.size() >= 19);
    CHECK(text.compare(text.size() - 19, 19, "<!-- end table -->\n") == 0);
}
