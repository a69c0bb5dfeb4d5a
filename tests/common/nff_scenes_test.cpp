// The kit's own NFF scenes (common/scenes/*.nff) and the generators' output read back whole.
#include "common/nff.hpp"
#include "common/scenes/nff_generators.hpp"
#include "tests/grader/graded.hpp"

#include <filesystem>
#include <map>
#include <sstream>

using namespace rt;

namespace {

struct Counts {
    std::size_t spheres, triangles, cones, lights;
};

std::string scene_path(const std::string& file) { return std::string(RT_NFF_SCENES_DIR) + "/" + file; }

NffScene generate(const NffGenerator& g, int depth)
{
    std::stringstream text;
    g.write(text, depth);
    return parse_nff(text, g.name + " --depth " + std::to_string(depth));
}

const NffGenerator& generator(const std::string& name)
{
    for (const NffGenerator& g : nff_generators())
        if (g.name == name)
            return g;
    FAIL("no generator " << name);
    throw;
}

std::size_t power(std::size_t base, int exponent)
{
    std::size_t p = 1;
    for (int k = 0; k < exponent; ++k)
        p *= base;
    return p;
}

}  // namespace

TEST_CASE("every NFF scene the kit ships reads back with the objects it was written with", "[common]")
{
    // What each scene's comments promise; a new scene must be added here, so it is looked at.
    const std::map<std::string, Counts> expected = {
        {"spheres.nff", {3, 2, 0, 2}},
        {"concave.nff", {0, 2 + 4 + 8 + 10 + 5, 0, 2}},  // floor, L, star, comb, arrow
        {"cones.nff", {2, 2, 4, 2}},
        {"patches.nff", {0, 2 + 2 * (12 * 2 + 10), 0, 2}},  // floor; two columns of 12 quads and a 12-gon lid
    };
    std::size_t found = 0;
    for (const auto& entry : std::filesystem::directory_iterator(RT_NFF_SCENES_DIR)) {
        if (entry.path().extension() != ".nff")
            continue;
        ++found;
        const std::string file = entry.path().filename().string();
        INFO(file);
        const NffScene s = read_nff(entry.path().string());
        REQUIRE(expected.count(file) == 1);
        const Counts& c = expected.at(file);
        CHECK(s.spheres.size() == c.spheres);
        CHECK(s.triangles.size() == c.triangles);
        CHECK(s.cones.size() == c.cones);
        CHECK(s.lights.size() == c.lights);
    }
    CHECK(found == expected.size());
}

TEST_CASE("the shipped scenes' polygons face the eye or the sky, as their comments say", "[common]")
{
    // A one-sided polygon seen from behind would vanish from the picture.
    for (const char* file : {"spheres.nff", "concave.nff", "cones.nff"}) {
        INFO(file);
        const NffScene s = read_nff(scene_path(file));
        for (const NffTriangle& t : s.triangles) {
            const vec3 centre = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
            INFO("the triangle of line " << t.line);
            CHECK(glm::dot(t.n[0], s.view.from - centre) > 0.0f);
        }
    }
}

TEST_CASE("the patch scene's smooth faces carry normals leaning out of the column", "[common]")
{
    const NffScene s = read_nff(scene_path("patches.nff"));
    std::size_t smooth = 0;
    for (const NffTriangle& t : s.triangles) {
        if (!t.smooth)
            continue;
        ++smooth;
        const vec3 face = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
        INFO("the patch of line " << t.line);
        for (const vec3& n : t.n)
            // Within 37 degrees of the face: the sides' normals turn 15 degrees either way, the lid's lean 27.
            CHECK(glm::dot(n, face) > 0.8f);
    }
    CHECK(smooth == 12 * 2 + 10);
}

TEST_CASE("the generated scenes read back with as many objects as their depth makes", "[common]")
{
    for (int depth = 0; depth <= 3; ++depth) {
        INFO("depth " << depth);
        const NffScene flake = generate(generator("sphereflake"), depth);
        CHECK(flake.spheres.size() == (power(9, depth + 1) - 1) / 8);
        CHECK(flake.triangles.size() == 2);  // the floor

        const NffScene pyramid = generate(generator("pyramid"), depth);
        CHECK(pyramid.triangles.size() == 4 * power(4, depth) + 2);

        const NffScene tree = generate(generator("tree"), depth);
        const std::size_t branches = (power(3, depth + 1) - 1) / 2;
        CHECK(tree.cones.size() == branches);
        CHECK(tree.spheres.size() == branches + power(3, depth));  // joints and leaves
        for (const NffScene* s : {&flake, &pyramid, &tree})
            CHECK(s->lights.size() == 3);
    }
}

TEST_CASE("the generators' deepest settings stay within the reader's limits", "[common]")
{
    // The deepest pyramid has the smallest features any generator writes, tetrahedra 2^-8 of its
    // size: written with 7 digits, each must still read as a triangle, not as a line.
    const NffGenerator& g = generator("pyramid");
    const NffScene s = generate(g, g.max_depth);
    CHECK(s.triangles.size() == 4 * power(4, g.max_depth) + 2);
}

TEST_CASE("the sphereflake's spheres rest on one another but never overlap", "[common]")
{
    const NffScene s = generate(generator("sphereflake"), 2);
    for (std::size_t i = 0; i < s.spheres.size(); ++i)
        for (std::size_t j = i + 1; j < s.spheres.size(); ++j) {
            const NffSphere &a = s.spheres[i], &b = s.spheres[j];
            const float gap = glm::length(a.center - b.center) - a.radius - b.radius;
            INFO("spheres of lines " << a.line << " and " << b.line);
            CHECK(gap > -1e-5f);  // touching within the 7 written digits
        }
}

TEST_CASE("the pyramid's triangles face out of their tetrahedra", "[common]")
{
    const NffScene s = generate(generator("pyramid"), 0);
    REQUIRE(s.triangles.size() == 6);
    vec3 centre(0.0f);
    for (std::size_t k = 2; k < 6; ++k)  // after the floor's two
        centre += (s.triangles[k].p[0] + s.triangles[k].p[1] + s.triangles[k].p[2]) / 12.0f;
    for (std::size_t k = 2; k < 6; ++k) {
        const NffTriangle& t = s.triangles[k];
        CHECK(glm::dot(t.n[0], t.p[0] - centre) > 0.0f);
    }
}
