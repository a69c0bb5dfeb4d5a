// The kit's own NFF scenes (common/scenes/*.nff) and the generators' output read back whole.
#include "common/nff.hpp"
#include "common/scenes/nff_generators.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
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
        // SPD's three below take its size factor as their measure: gears and rings depth + 1, the
        // lattice depth.
        const std::size_t n = static_cast<std::size_t>(depth) + 1;
        const NffScene gears = generate(generator("gears"), depth);
        CHECK(gears.triangles.size() == 572 * power(n, 3) + 2);  // 2 x 142 for the faces, 2 x 144 for the sides
        CHECK(gears.spheres.empty());

        const NffScene rings = generate(generator("rings"), depth);
        CHECK(rings.spheres.size() == 5 * n * (n + 1) * (2 * n + 1));
        CHECK(rings.cones.size() == rings.spheres.size());
        CHECK(rings.triangles.size() == 2);

        const NffScene lattice = generate(generator("lattice"), depth);
        CHECK(lattice.spheres.size() == power(n, 3));
        CHECK(lattice.cones.size() == 3 * static_cast<std::size_t>(depth) * n * n);
        CHECK(lattice.triangles.size() == 2);
        for (const NffScene* s : {&flake, &pyramid, &tree, &gears, &rings, &lattice})
            CHECK(s->lights.size() == 3);
    }
}

TEST_CASE("SPD's gears, rings and lattice at their default depth are about SPD's default size", "[common]")
{
    // SPD's gears at size factor 4: 64 gears, 128 faces of 144 corners and 9216 side rectangles.
    const NffScene gears = generate(generator("gears"), generator("gears").default_depth);
    CHECK(gears.triangles.size() == 64 * (2 * 142 + 144 * 2) + 2);
    // SPD's rings at size factor 7: 4200 spheres and 4200 cylinders.
    const NffScene rings = generate(generator("rings"), generator("rings").default_depth);
    CHECK(rings.spheres.size() == 4200);
    CHECK(rings.cones.size() == 4200);
    // SPD's lattice at size factor 12: 2197 spheres and 6084 cylinders.
    const NffScene lattice = generate(generator("lattice"), generator("lattice").default_depth);
    CHECK(lattice.spheres.size() == 2197);
    CHECK(lattice.cones.size() == 6084);
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

TEST_CASE("a gear's faces look up and down and its sides out of the gear", "[common]")
{
    // Depth 0 is one gear, its axis the y axis: after the floor's two triangles, the top face's 142,
    // the bottom's 142, then two for each of the 144 sides.
    const NffScene s = generate(generator("gears"), 0);
    REQUIRE(s.triangles.size() == 2 + 2 * 142 + 2 * 144);
    std::size_t up = 0, down = 0, out = 0;
    for (std::size_t k = 2; k < s.triangles.size(); ++k) {
        const NffTriangle& t = s.triangles[k];
        const vec3 centre = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        const vec3 radial = glm::normalize(vec3(centre.x, 0.0f, centre.z));
        INFO("the triangle of line " << t.line);
        if (t.n[0].y > 0.99f)
            ++up;
        else if (t.n[0].y < -0.99f)
            ++down;
        else if (std::abs(t.n[0].y) < 1e-4f && glm::dot(t.n[0], radial) > 0.0f)
            ++out;  // even a tooth's flank leans a little away from the axis
    }
    CHECK(up == 142);
    CHECK(down == 142);
    CHECK(out == 2 * 144);
}

TEST_CASE("meshing gears never reach into one another", "[common]")
{
    // The top faces' triangles cover each gear's outline exactly: no corner of one gear may lie
    // within another's at the same height (their teeth interleave, 0.01 of a radius apart).
    const NffScene s = generate(generator("gears"), 1);
    std::map<int, std::vector<const NffTriangle*>> tops;  // by the line of their face's `p`
    for (const NffTriangle& t : s.triangles)
        if (t.n[0].y > 0.99f && t.line > s.triangles[1].line)  // not the floor
            tops[t.line].push_back(&t);
    REQUIRE(tops.size() == 8);
    const auto within = [](const vec3& p, const NffTriangle& t) {
        // Inside or on the edge, seen from above: on no edge's outer side, whichever way round the
        // triangle runs in x, z.
        bool left = false, right = false;
        for (int e = 0; e < 3; ++e) {
            const vec3 &a = t.p[e], &b = t.p[(e + 1) % 3];
            const float side = (b.x - a.x) * (p.z - a.z) - (b.z - a.z) * (p.x - a.x);
            left = left || side > 0.0f;
            right = right || side < 0.0f;
        }
        return !(left && right);
    };
    std::size_t pairs = 0;
    for (const auto& [line_a, a] : tops)
        for (const auto& [line_b, b] : tops) {
            if (line_a == line_b || a[0]->p[0].y != b[0]->p[0].y)
                continue;
            ++pairs;
            INFO("the gears of lines " << line_a << " and " << line_b);
            std::size_t inside = 0;
            for (const NffTriangle* ta : a)
                for (const vec3& corner : ta->p)
                    for (const NffTriangle* tb : b)
                        inside += within(corner, *tb) ? 1 : 0;
            CHECK(inside == 0);
        }
    CHECK(pairs == 2 * 4 * 3);  // two layers of four, each against the other three
}

TEST_CASE("the rings' and the lattice's cylinders end inside a sphere, so no open end shows", "[common]")
{
    // NFF cones have no caps: each end's rim must lie within a ball (rings: a corner's joint;
    // lattice: a joint the rod starts just inside).
    for (const char* name : {"rings", "lattice"}) {
        INFO(name);
        const NffScene s = generate(generator(name), 2);
        for (const NffCone& c : s.cones) {
            INFO("the cylinder of line " << c.line);
            CHECK(c.base_radius == c.apex_radius);
            const vec3 axis = glm::normalize(c.apex - c.base);
            for (const point3& end : {c.base, c.apex}) {
                bool covered = false;
                for (const NffSphere& ball : s.spheres) {
                    // The rim's farthest point from the ball's centre: along the axis, and across it.
                    const vec3 v = end - ball.center;
                    const float along = glm::dot(v, axis);
                    const float across = glm::length(v - along * axis) + c.base_radius;
                    covered = covered || std::sqrt(along * along + across * across) <= ball.radius * 1.0001f;
                }
                CHECK(covered);
            }
        }
    }
}
