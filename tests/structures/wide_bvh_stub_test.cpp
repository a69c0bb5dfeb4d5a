// The wide tree with chapter 10's exercises as handed out: 10.6's stub (FourHits::not_tested) has it
// ask each triangle one by one, so a student who has not written 10.6 still gets brute force's
// answers through `--accel bvh4` and the benchmark, at step 5's speed.
#include "10_hierarchies/figure.hpp"
#include "10_hierarchies/wide_bvh.hpp"
#include "common/stub.hpp"
#include "tests/ch07/agreement.hpp"

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

TEST_CASE("with 10.6 still the stub, the 4-wide BVH answers every ray as brute force does", "[structures]")
{
    const Build wide{"the 4-wide BVH over chapter 10's stubs", [](const Objects& objects, float) {
                         return std::make_unique<WideBvhAccel>(objects);
                     }};
    forget_stubs();
    check_scene(wide, generated_scene(write_stadium, 2, "stadium 2"), 400);
    check_scene(wide, generated_scene(write_mountain, 3, "mountain 3"), 400);
    const std::vector<std::string> ran = stubs_that_ran();
    INFO("stubs that ran: " << ran.size());
    CHECK(std::find(ran.begin(), ran.end(), "10.6") != ran.end());
}
