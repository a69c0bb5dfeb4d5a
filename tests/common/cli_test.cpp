#include "common/cli.hpp"
#include "tests/grader/graded.hpp"

#include <sstream>

using namespace rt;

namespace {
void parse(std::vector<const char*> args, CommonOptions& o, float* fov = nullptr)
{
    args.insert(args.begin(), "prog");
    CommandLine cli("prog", "test");
    add_common_options(cli, o);
    float unused = 1;
    cli.option("--fov", fov ? *fov : unused, "field of view", 0.0f, 180.0f);
    std::ostringstream out;
    cli.parse(static_cast<int>(args.size()), args.data(), out);
}
}  // namespace

TEST_CASE("the command line reads the common options", "[common]")
{
    CommonOptions o;
    float fov = 1;
    parse({"--width", "64", "--height", "1", "--spp", "16", "--out", "x.png", "--stats", "--fov", "179.5", "--seed",
           "18446744073709551615"},
          o, &fov);
    CHECK(o.width == 64);
    CHECK(o.height == 1);
    CHECK(o.spp == 16);
    CHECK(o.out == "x.png");
    CHECK(o.stats);
    CHECK(fov == 179.5f);
    CHECK(o.seed == 18446744073709551615ull);
}

TEST_CASE("bad command lines are refused with one line naming the flag and the problem", "[common]")
{
    struct Case {
        std::vector<const char*> args;
        const char* message;
    };
    for (const Case& c : std::vector<Case>{
             {{"--width", "0"}, "--width must be between 1 and 16384, got 0"},
             {{"--width", "-3"}, "--width must be between 1 and 16384, got -3"},
             {{"--width", "3.5"}, "--width takes a whole number, got '3.5'"},
             {{"--width", "99999999999"}, "--width is out of range"},
             {{"--height"}, "--height needs a value"},
             {{"--fov", "0"}, "--fov must lie strictly between 0 and 180, got 0"},
             {{"--fov", "inf"}, "--fov takes a finite number, got 'inf'"},
             {{"--fov", "12deg"}, "--fov takes a finite number, got '12deg'"},
             {{"--out", ""}, "--out takes a non-empty value"},
             {{"--sppp", "4"}, "unknown option '--sppp'"},
             {{"stray"}, "unknown option 'stray'"},
         }) {
        CommonOptions o;
        INFO("arguments: " << c.args.front() << (c.args.size() > 1 ? std::string(" ") + c.args[1] : ""));
        CHECK_THROWS_WITH(parse(c.args, o), rt::grader::contains_text(c.message));
    }
}

TEST_CASE("run_program turns bad input into exit status 2", "[common]")
{
    CHECK(run_program("p", [] { return 0; }) == 0);
    CHECK(run_program("p", []() -> int { throw InputError("nope"); }) == exit_bad_input);
}

TEST_CASE("the command line tells which options were given, so a scene file's size can stand", "[common]")
{
    CommonOptions o;
    CommandLine cli("prog", "test");
    add_common_options(cli, o);
    const char* args[] = {"prog", "--height", "50", "--stats"};
    std::ostringstream out;
    REQUIRE(cli.parse(4, args, out));
    CHECK(cli.given("--height"));
    CHECK(cli.given("--stats"));
    CHECK_FALSE(cli.given("--width"));
    const char* again[] = {"prog", "--width", "7"};
    REQUIRE(cli.parse(3, again, out));
    CHECK(cli.given("--width"));
    CHECK_FALSE(cli.given("--height"));  // a parse forgets the one before
}
