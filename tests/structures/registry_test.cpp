// The registry of structures (chapters/programs/structures.hpp): each chapter's list is the earlier
// chapter's and its own entries, each named once in one word; and a structure added to the list
// reaches --accel, its help, the options' check and the walk of the tests and the fuzzer, with no
// other change.
#include "10_hierarchies/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/grader/catch.hpp"

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {

struct ChapterList {
    int chapter;
    Structures list;
};

std::vector<ChapterList> chapter_lists()
{
    return {{7, ch07::structures()}, {8, ch08::structures()}, {9, ch09::structures()}, {10, ch10::structures()}};
}

std::vector<std::string> names_of(const Structures& list)
{
    std::vector<std::string> names;
    for (const Structure& s : list)
        names.push_back(s.name);
    return names;
}

// A structure made up for the test: brute force under another name, shaped by an option no real
// structure takes. What it adds to the registry is all a new structure adds.
Structure made_up()
{
    return {"made-up", "brute force under another name", 11, 0.0f, {"--made-up-knob"},
            [](const Objects&, const StructureTuning&) { return std::make_unique<BruteForce>(); }};
}

bool parses(CommandLine& cli, std::vector<const char*> argv)
{
    std::ostringstream out;
    return cli.parse(static_cast<int>(argv.size()), argv.data(), out);
}

}  // namespace

TEST_CASE("each chapter's structures are the earlier chapter's and its own, each named once in one word", "[structures]")
{
    Structures earlier;
    for (const ChapterList& c : chapter_lists()) {
        INFO("chapter " << c.chapter << "'s structures: " << structure_names(c.list));
        REQUIRE(c.list.size() > earlier.size());
        CHECK(names_of(Structures(c.list.begin(), c.list.begin() + static_cast<long>(earlier.size()))) ==
              names_of(earlier));
        for (std::size_t k = earlier.size(); k < c.list.size(); ++k) {
            INFO(c.list[k].name << " is brought by chapter " << c.list[k].chapter);
            CHECK(c.list[k].chapter <= c.chapter);
            CHECK((c.chapter == 7 || c.list[k].chapter == c.chapter));
        }
        std::set<std::string> seen;
        for (const Structure& s : c.list) {
            INFO("the name '" << s.name << "'");
            CHECK(std::regex_match(s.name, std::regex("[a-z0-9]+(-[a-z0-9]+)*")));
            CHECK(seen.insert(s.name).second);
            CHECK(!s.what.empty());
            CHECK((s.default_lambda > 0.0f) == s.takes("--lambda"));
        }
        earlier = c.list;
    }
}

TEST_CASE("every structure of the registry builds over a small scene and answers as brute force", "[structures]")
{
    LitScene scene;
    scene.add_material({});
    for (int k = 0; k < 40; ++k)
        scene.add_sphere({point3(static_cast<float>(k % 5), static_cast<float>(k / 5 % 4), static_cast<float>(k / 20)),
                          0.3f},
                         0);
    NffView view;
    view.from = point3(2.0f, 1.5f, 8.0f);
    view.at = point3(2.0f, 1.5f, 0.5f);
    for (const Structure& s : ch10::structures()) {
        agreement::Disagreement d;
        const auto build = [&s](const Objects& o, float l) -> std::unique_ptr<Accelerator> {
            if (std::unique_ptr<Accelerator> built = s.make(o, at_density(l)))
                return built;
            return std::make_unique<BruteForce>();  // brute force builds nothing
        };
        agreement::compare({s.name, build}, scene, view,
                           s.default_lambda, 300, 11, d);
        INFO(s.name << ": " << d.wrong << " of " << d.rays << " rays answered differently from brute force; the first: "
                    << d.first);
        CHECK(d.rays > 0);
        CHECK(d.wrong == 0);
    }
}

TEST_CASE("a structure added to the registry reaches --accel, its help, the options' check and the tests' walk", "[structures]")
{
    const std::vector<std::string> real = names_of(ch10::structures());
    REQUIRE(std::find(real.begin(), real.end(), made_up().name) == real.end());
    const Structures list = followed_by(ch10::structures(), {made_up()});

    // --accel finds it, and an unknown name's message lists it.
    CHECK(structure_named(list, "made-up").what == made_up().what);
    try {
        structure_named(list, "kd-tree");
        FAIL("an unknown --accel was taken");
    } catch (const InputError& e) {
        const std::string said = e.what();
        INFO(said);
        CHECK(said.find(" or made-up, got 'kd-tree'") != std::string::npos);
        for (const std::string& name : real) {
            INFO("the name " << name);
            const bool listed = said.find(" " + name + ",") != std::string::npos ||
                                said.find(" " + name + " or ") != std::string::npos;
            CHECK(listed);
        }
    }
    CHECK(accel_help(list).find("made-up (chapter 11: brute force under another name)") != std::string::npos);

    // Its option is taken with it and refused with another structure, the message naming it.
    std::string knob;
    CommandLine cli("registry_test", "the made-up structure's option");
    cli.option("--made-up-knob", knob, "shapes the made-up structure");
    cli.option("--lambda", knob, "a grid's density");
    REQUIRE(parses(cli, {"registry_test", "--made-up-knob", "3"}));
    CHECK_NOTHROW(check_structure_options(list, structure_named(list, "made-up"), cli));
    try {
        check_structure_options(list, structure_named(list, "bvh"), cli);
        FAIL("--made-up-knob was taken with --accel bvh");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) == "--made-up-knob shapes made-up; it does not apply to --accel bvh");
    }
    REQUIRE(parses(cli, {"registry_test", "--lambda", "3"}));
    CHECK_THROWS_WITH(check_structure_options(list, structure_named(list, "made-up"), cli),
                      "--lambda shapes " +
                          structure_names(list, [](const Structure& s) { return s.takes("--lambda"); }) +
                          "; it does not apply to --accel made-up");

    // The legal-scenes test, the fuzzer and the benchmark walk the list: it is there, brute force is not.
    const std::vector<std::string> walked = names_of(beside_brute_force(list));
    CHECK(std::find(walked.begin(), walked.end(), "made-up") != walked.end());
    CHECK(std::find(walked.begin(), walked.end(), brute_force_name) == walked.end());
    CHECK(walked.size() + 1 == list.size());
}
