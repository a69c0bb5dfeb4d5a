// Polygon triangulation (common/polygon.hpp): the triangles cover exactly the polygon, concave or
// not, and nothing outside it; bad polygons are refused with the reason.
#include "common/error.hpp"
#include "common/polygon.hpp"
#include "common/random.hpp"
#include "tests/grader/graded.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

using namespace rt;

namespace {

using dvec2 = glm::dvec2;

// A polygon drawn in the xy plane and placed in space by an orthonormal frame, so the same outline
// can be tested lying in any plane.
struct Frame {
    dvec3 origin{0.0}, u{1, 0, 0}, v{0, 1, 0};
    point3 place(const dvec2& q) const { return point3(origin + q.x * u + q.y * v); }
};

Frame tilted_frame()
{
    Frame f;
    f.origin = dvec3(3.0, -2.0, 7.5);
    f.u = glm::normalize(dvec3(1.0, 2.0, -0.5));
    f.v = glm::normalize(glm::cross(dvec3(0.3, -0.2, 1.0), f.u));
    return f;
}

double shoelace(const std::vector<dvec2>& q)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < q.size(); ++i)
        sum += q[i].x * q[(i + 1) % q.size()].y - q[(i + 1) % q.size()].x * q[i].y;
    return 0.5 * sum;
}

// Even-odd rule.
bool inside_polygon(const std::vector<dvec2>& q, const dvec2& p)
{
    bool inside = false;
    for (std::size_t i = 0, j = q.size() - 1; i < q.size(); j = i++)
        if ((q[i].y > p.y) != (q[j].y > p.y) &&
            p.x < (q[j].x - q[i].x) * (p.y - q[i].y) / (q[j].y - q[i].y) + q[i].x)
            inside = !inside;
    return inside;
}

double distance_to_segment(const dvec2& p, const dvec2& a, const dvec2& b)
{
    const dvec2 ab = b - a;
    const double s = glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(p - (a + s * ab));
}

bool strictly_inside_triangle(const dvec2& p, const dvec2& a, const dvec2& b, const dvec2& c)
{
    const auto cross2 = [](const dvec2& x, const dvec2& y) { return x.x * y.y - x.y * y.x; };
    const double d1 = cross2(b - a, p - a), d2 = cross2(c - b, p - b), d3 = cross2(a - c, p - c);
    return (d1 > 0 && d2 > 0 && d3 > 0) || (d1 < 0 && d2 < 0 && d3 < 0);
}

// Triangulates the outline placed by `frame` and checks the contract: the triangles' areas add up
// to the polygon's; every random point of the polygon's box away from its edges lies in exactly one
// triangle if it is inside the polygon and in none if outside; every triangle is wound like the
// polygon; every vertex is a corner of some triangle (no T-junctions).
void check_covers_exactly(const std::vector<dvec2>& outline, const Frame& frame, std::uint64_t seed)
{
    std::vector<point3> vertices;
    for (const dvec2& q : outline)
        vertices.push_back(frame.place(q));
    const PolygonTriangles cut = triangulate_polygon(vertices);
    // Back to the plane's coordinates, from the float vertices the triangles really use.
    std::vector<dvec2> flat;
    for (const point3& p : vertices)
        flat.push_back({glm::dot(dvec3(p) - frame.origin, frame.u), glm::dot(dvec3(p) - frame.origin, frame.v)});
    const double area = std::abs(shoelace(flat));
    const double orientation = shoelace(flat) > 0.0 ? 1.0 : -1.0;

    INFO(outline.size() << " vertices, area " << area << ", " << cut.triangles.size() << " triangles");
    CHECK(cut.area == Approx(area).epsilon(1e-9));
    CHECK(glm::dot(cut.normal, glm::cross(frame.u, frame.v)) == Approx(orientation));
    double sum = 0.0;
    std::vector<bool> used(outline.size(), false);
    for (const TriangleIndices& t : cut.triangles) {
        const double signed_area = 0.5 * ((flat[t[1]].x - flat[t[0]].x) * (flat[t[2]].y - flat[t[0]].y) -
                                          (flat[t[2]].x - flat[t[0]].x) * (flat[t[1]].y - flat[t[0]].y));
        CHECK(signed_area * orientation > 0.0);  // wound like the polygon, never degenerate
        sum += std::abs(signed_area);
        for (const std::size_t k : t)
            used[k] = true;
    }
    CHECK(sum == Approx(area).epsilon(1e-9));
    CHECK(std::count(used.begin(), used.end(), false) == 0);

    dvec2 lo = flat[0], hi = flat[0];
    for (const dvec2& q : flat) {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    const double margin = 1e-6 * glm::length(hi - lo);
    Rng rng(seed, 0);
    int wrong = 0, tested = 0;
    for (int k = 0; k < 4000; ++k) {
        const dvec2 p = lo + dvec2(rng.next_float(), rng.next_float()) * (hi - lo);
        bool near_edge = false;
        for (std::size_t i = 0; i < flat.size() && !near_edge; ++i)
            near_edge = distance_to_segment(p, flat[i], flat[(i + 1) % flat.size()]) < margin;
        if (near_edge)
            continue;
        int covering = 0;
        for (const TriangleIndices& t : cut.triangles)
            covering += strictly_inside_triangle(p, flat[t[0]], flat[t[1]], flat[t[2]]) ? 1 : 0;
        ++tested;
        if (covering != (inside_polygon(flat, p) ? 1 : 0)) {
            if (wrong == 0)
                UNSCOPED_INFO("point (" << p.x << ", " << p.y << ") is covered by " << covering << " triangles");
            ++wrong;
        }
    }
    CHECK(wrong == 0);
    CHECK(tested > 3000);
}

std::vector<dvec2> star(int points, double outer, double inner)
{
    std::vector<dvec2> q;
    for (int k = 0; k < 2 * points; ++k) {
        const double a = grader::pi * k / points;
        const double r = k % 2 == 0 ? outer : inner;
        q.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return q;
}

// A bar with `teeth` thin teeth standing on it: many reflex vertices, ears only at the ends.
std::vector<dvec2> comb(int teeth)
{
    std::vector<dvec2> q = {{0.0, 0.0}, {2.0 * teeth - 1.0, 0.0}};
    for (int k = teeth - 1; k >= 0; --k) {
        const double x = 2.0 * k;
        q.push_back({x + 1.0, 5.0});
        q.push_back({x, 5.0});
        if (k > 0) {
            q.push_back({x, 1.0});
            q.push_back({x - 1.0, 1.0});
        }
    }
    return q;
}

// A square spiral corridor: every turn concave, long thin ears.
std::vector<dvec2> spiral(int turns)
{
    std::vector<dvec2> outer, inner;
    for (int k = 0; k < turns; ++k) {
        const double r = 1.0 + k;
        const double a = grader::pi / 2.0 * k;
        outer.push_back({(r + 0.5) * std::cos(a), (r + 0.5) * std::sin(a)});
        inner.push_back({r * std::cos(a), r * std::sin(a)});
    }
    std::vector<dvec2> q(outer.begin(), outer.end());
    q.insert(q.end(), inner.rbegin(), inner.rend());
    if (shoelace(q) < 0.0)
        std::reverse(q.begin(), q.end());
    return q;
}

// Random radii at increasing angles: star-shaped about the origin, often deeply concave.
std::vector<dvec2> random_star_shaped(Rng& rng, int n)
{
    std::vector<dvec2> q;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * grader::pi * (k + 0.8 * rng.next_float()) / n;
        const double r = 0.05 + rng.next_float();
        q.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return q;
}

}  // namespace

TEST_CASE("concave polygons are cut into triangles that cover exactly their area", "[common]")
{
    const std::vector<std::pair<const char*, std::vector<dvec2>>> shapes = {
        {"a triangle", {{0, 0}, {1, 0}, {0, 1}}},
        {"a convex hexagon", star(3, 1.0, 1.0)},
        {"an L", {{0, 0}, {2, 0}, {2, 0.5}, {0.5, 0.5}, {0.5, 2}, {0, 2}}},
        {"a five-pointed star", star(5, 1.0, 0.38)},
        {"a forty-pointed star", star(40, 1.0, 0.1)},
        {"a comb of 30 teeth", comb(30)},
        // Once its teeth are cut, a long thin strip whose ears are slivers along its edge.
        {"a comb of 1000 teeth", comb(1000)},
        {"a square spiral of 24 turns", spiral(24)},
        {"a U with vertices on its straight edges",
         {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {1, 3}, {0, 3}, {0, 1.5}}},
    };
    for (const auto& [name, outline] : shapes) {
        INFO(name);
        check_covers_exactly(outline, Frame{}, 1);
        INFO("tilted in space");
        check_covers_exactly(outline, tilted_frame(), 2);
        INFO("clockwise, so facing the other way");
        check_covers_exactly(std::vector<dvec2>(outline.rbegin(), outline.rend()), tilted_frame(), 3);
    }
}

TEST_CASE("random star-shaped polygons are cut into triangles that cover exactly their area", "[common]")
{
    Rng rng(2024, 7);
    for (int trial = 0; trial < 40; ++trial) {
        const int n = 3 + static_cast<int>(rng.next_u32() % 60);
        INFO("trial " << trial);
        check_covers_exactly(random_star_shaped(rng, n), trial % 2 ? tilted_frame() : Frame{}, trial);
    }
}

TEST_CASE("polygons far from the origin and at tiny and huge scales are cut exactly", "[common]")
{
    for (const double scale : {1e-4, 1.0, 1e6}) {
        // An outline 11 units wide (times the scale), a hundred times its size from the origin.
        Frame frame = tilted_frame();
        frame.origin *= 100.0 * scale;
        std::vector<dvec2> outline = comb(6);
        for (dvec2& q : outline)
            q *= scale;
        INFO("scale " << scale);
        check_covers_exactly(outline, frame, 5);
    }
}

TEST_CASE("a repeated closing vertex and repeated vertices are one vertex", "[common]")
{
    const std::vector<point3> closed = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 0}};
    const PolygonTriangles cut = triangulate_polygon(closed);
    CHECK(cut.triangles.size() == 2);
    CHECK(cut.area == Approx(4.0));
}

TEST_CASE("a polygon of thousands of vertices is cut without trouble", "[common]")
{
    const std::vector<dvec2> outline = star(2500, 1.0, 0.5);
    std::vector<point3> vertices;
    for (const dvec2& q : outline)
        vertices.push_back(point3(q.x, q.y, 0.0));
    const PolygonTriangles cut = triangulate_polygon(vertices);
    CHECK(cut.triangles.size() == vertices.size() - 2);
    CHECK(cut.area == Approx(std::abs(shoelace(outline))));
}

TEST_CASE("polygons that are not polygons are refused with the reason", "[common]")
{
    struct Case {
        std::vector<point3> vertices;
        const char* message;
    };
    const std::vector<Case> cases = {
        {{{0, 0, 0}, {1, 0, 0}}, "needs at least 3 vertices, got 2"},
        {{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-1, -1, -1}}, "its vertices all lie on one line (no area)"},
        {{{5, 5, 5}, {5, 5, 5}, {5, 5, 5}}, "has fewer than 3 distinct vertices (its corners coincide)"},
        {{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}, "has fewer than 3 distinct vertices (its corners coincide)"},
        {{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 1, 0}}, "edges 1 and 3 cross (NFF polygons are simple)"},
        {{{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {5, 1, 0}, {3, 1, 0}, {3, 4, 0}, {0, 4, 0}},
         "edges 2 and 4 cross (NFF polygons are simple)"},
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 2}}, "vertex 1 lies 0.288675 off the plane of the others (NFF polygons are planar)"},
        // A square with a square hole, joined by a cut run twice (a keyhole): the outline touches
        // itself, which a polygon of NFF may not.
        {{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 2, 0}, {1, 2, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0},
          {1, 1, 0}, {1, 2, 0}, {0, 2, 0}},
         "edges 4 and 11 touch (NFF polygons are simple)"},
        // A vertex on another edge.
        {{{0, 0, 0}, {4, 0, 0}, {2, 2, 0}, {2, 0, 0}, {1, -1, 0}}, "edges 1 and 3 touch (NFF polygons are simple)"},
    };
    for (const Case& c : cases) {
        INFO(c.vertices.size() << " vertices");
        CHECK_THROWS_WITH(triangulate_polygon(c.vertices), c.message);
    }
    CHECK_THROWS_WITH(triangulate_polygon(std::vector<point3>(polygon_max_vertices + 1, point3(0.0f))),
                      "has 10001 vertices; the reader takes at most 10000");
}

TEST_CASE("triangles far finer than float's steps at their distance from the origin are all kept", "[common]")
{
    // 2,000 triangles 1e-5 across at coordinates up to 10, where floats are 1e-6 apart: a tolerance
    // of 16 float steps of the farthest corner, once used as a width, called 1,993 of them lines.
    Rng rng(52, 0);
    int lost = 0;
    std::string first;
    for (int k = 0; k < 2000; ++k) {
        const point3 at(20 * rng.next_float() - 10, 20 * rng.next_float() - 10, 20 * rng.next_float() - 10);
        std::vector<point3> corners;
        for (int c = 0; c < 3; ++c)
            corners.push_back(at + 1e-5f * vec3(rng.next_float(), rng.next_float(), rng.next_float()));
        // Float corners that are distinct and not on one line, in double: a triangle with area.
        const dvec3 area_vector = glm::cross(dvec3(corners[1]) - dvec3(corners[0]), dvec3(corners[2]) - dvec3(corners[0]));
        if (glm::length(area_vector) == 0.0)
            continue;
        try {
            const PolygonTriangles cut = triangulate_polygon(corners);
            if (cut.triangles.size() != 1 && lost++ == 0)
                first = "cut into " + std::to_string(cut.triangles.size()) + " triangles";
        } catch (const InputError& e) {
            if (lost++ == 0)
                first = "(" + grader::show(corners[0]) + ", " + grader::show(corners[1]) + ", " +
                        grader::show(corners[2]) + ") " + e.what();
        }
    }
    INFO(lost << " of 2000 triangles lost; the first: " << first);
    CHECK(lost == 0);
}

TEST_CASE("a fine polygon far from the origin is cut as the same polygon at the origin is", "[common]")
{
    // The comb 1.1e-3 across (its teeth 1e-4 wide), at the origin and 1e2 and 1e3 out along x: at
    // 1e3 floats are 6e-5 apart, more than half a tooth, and a tolerance of 16 of them made every
    // corner one. (At 1e4, where they are 1e-3 apart, the float teeth do touch.)
    for (const double out : {0.0, 1e2, 1e3}) {
        Frame frame;
        frame.origin = dvec3(out, 0.0, 0.0);
        std::vector<dvec2> outline = comb(6);
        for (dvec2& q : outline)
            q *= 1e-4;
        INFO("the comb 1.1e-3 across at x = " << out);
        check_covers_exactly(outline, frame, 6);
    }
}

TEST_CASE("a polygon of no area is skipped with its cause: coincident corners, one line, a bowtie", "[common]")
{
    CHECK_THROWS_WITH(triangulate_polygon({{1e3f, 2, 3}, {1e3f, 2, 3}, {1e3f, 2, 3}}),
                      "has fewer than 3 distinct vertices (its corners coincide)");
    CHECK_THROWS_WITH(triangulate_polygon({{1e3f, 2, 3}, {1e3f + 0.25f, 2.5f, 3}, {1e3f + 0.5f, 3, 3}}),
                      "its vertices all lie on one line (no area)");
    // A bowtie whose two halves wind opposite ways and cancel: refused as no area, not as a line.
    CHECK_THROWS_WITH(triangulate_polygon({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}}),
                      "its parts wind opposite ways and their areas cancel (a bowtie: no area)");
    CHECK_THROWS_AS(triangulate_polygon({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}}), DegeneratePolygon);
}
