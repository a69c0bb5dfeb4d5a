// The NFF reader (common/nff.hpp): what it reads, and its one-line answer to every kind of bad file.
#include "common/error.hpp"
#include "common/nff.hpp"
#include "tests/grader/graded.hpp"

#include <filesystem>
#include <sstream>

using namespace rt;

namespace {

NffScene parse(const std::string& text)
{
    std::istringstream in(text);
    return parse_nff(in, "t.nff");
}

// Lines 1-7: a view. Lines 8-9: a light and a material. Objects start at line 10.
const std::string view_lines = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\n";
const std::string lit = view_lines + "l 1 1 1\nf 1 0 0 1 0 0 0 0\n";

double triangles_area(const NffScene& s)
{
    double sum = 0.0;
    for (const NffTriangle& t : s.triangles)
        sum += 0.5 * glm::length(glm::cross(dvec3(t.p[1] - t.p[0]), dvec3(t.p[2] - t.p[0])));
    return sum;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to)
{
    for (std::size_t pos = 0; (pos = text.find(from, pos)) != std::string::npos; pos += to.size())
        text.replace(pos, from.size(), to);
    return text;
}

}  // namespace

TEST_CASE("the NFF reader reads every command into the scene's flat arrays", "[common]")
{
    const NffScene s = parse(
        "v\nfrom 1 2 3\nat 0 0 -1\nup 0.2 1 0\nangle 45\nhither 0.5\nresolution 640 480\n"
        "b 0.1 0.2 0.3\n"
        "l 5 6 7\n"
        "l -5 6 7 0.5 0.25 1\n"
        "f 0.9 0.8 0.7 0.6 0.3 20 0 0\n"
        "s 1 2 3 0.5\n"
        "f 1 1 1 0.1 0.2 100 0.8 1.5\n"
        "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
        "c\n0 0 0 1\n0 2 0 0.5\n");
    CHECK(s.name == "t.nff");
    CHECK(s.view.from == vec3(1, 2, 3));
    CHECK(s.view.at == vec3(0, 0, -1));
    CHECK(s.view.up == vec3(0.2f, 1, 0));
    CHECK(s.view.angle_degrees == 45.0f);
    CHECK(s.view.hither == 0.5f);
    CHECK(s.view.width == 640);
    CHECK(s.view.height == 480);
    CHECK(s.view.line == 1);
    CHECK(s.background == color(0.1f, 0.2f, 0.3f));
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].position == vec3(5, 6, 7));
    CHECK_FALSE(s.lights[0].rgb_given);
    CHECK(s.lights[0].rgb == color(1.0f));
    CHECK(s.lights[1].rgb_given);
    CHECK(s.lights[1].rgb == color(0.5f, 0.25f, 1.0f));
    CHECK(s.lights[1].line == 10);
    REQUIRE(s.materials.size() == 2);
    const NffMaterial& glass = s.materials[1];
    CHECK(glass.rgb == color(1.0f));
    CHECK(glass.kd == 0.1f);
    CHECK(glass.ks == 0.2f);
    CHECK(glass.shine == 100.0f);
    CHECK(glass.t == 0.8f);
    CHECK(glass.ior == 1.5f);
    CHECK(glass.line == 13);
    REQUIRE(s.spheres.size() == 1);
    CHECK(s.spheres[0].center == vec3(1, 2, 3));
    CHECK(s.spheres[0].radius == 0.5f);
    CHECK(s.spheres[0].material == 0);  // objects take the last `f` before them
    CHECK(s.spheres[0].line == 12);
    REQUIRE(s.triangles.size() == 2);
    CHECK(s.triangles[0].material == 1);
    CHECK(s.triangles[0].line == 14);
    CHECK(triangles_area(s) == Approx(1.0));
    REQUIRE(s.cones.size() == 1);
    CHECK(s.cones[0].base == vec3(0, 0, 0));
    CHECK(s.cones[0].base_radius == 1.0f);
    CHECK(s.cones[0].apex == vec3(0, 2, 0));
    CHECK(s.cones[0].apex_radius == 0.5f);
    CHECK(s.cones[0].material == 1);
    CHECK(s.cones[0].line == 19);
}

TEST_CASE("the NFF view's lines may come in any order, and up need not be perpendicular", "[common]")
{
    const NffScene s = parse("v\nresolution 4 2\nhither 0\nangle 90\nup 0 1 1\nat 1 1 1\nfrom -1 -1 -1\n"
                             "l 0 5 0\nf 1 1 1 1 0 0 0 0\ns 0 0 0 1\n");
    CHECK(s.view.from == vec3(-1.0f));
    CHECK(s.view.at == vec3(1.0f));
    CHECK(s.view.up == vec3(0, 1, 1));
    CHECK(s.view.width == 4);
    CHECK(s.view.height == 2);
    CHECK(s.view.angle_degrees == 90.0f);
}

TEST_CASE("a cone's numbers may stand on one line or across several lines", "[common]")
{
    const NffScene one = parse(lit + "c 0 0 0 1 0 2 0 0.5\n");
    const NffScene many = parse(lit + "c\n0\n0 0\n1 0 2\n\n0 0.5\n");
    REQUIRE(one.cones.size() == 1);
    REQUIRE(many.cones.size() == 1);
    CHECK(one.cones[0].base == many.cones[0].base);
    CHECK(one.cones[0].apex == many.cones[0].apex);
    CHECK(one.cones[0].base_radius == many.cones[0].base_radius);
    CHECK(one.cones[0].apex_radius == many.cones[0].apex_radius);
    // Any command's numbers may wrap: a sphere over two lines, a polygon on one.
    const NffScene wrapped = parse(lit + "s 1 2\n3 4 p 3 0 0 0 1 0 0 0 1 0\n");
    CHECK(wrapped.spheres.at(0).radius == 4.0f);
    CHECK(wrapped.triangles.size() == 1);
}

TEST_CASE("the NFF reader reads Windows and old Mac line endings and counts their lines alike", "[common]")
{
    const std::string unix_text = lit + "s 0 0 0 1\nc\n0 0 0 1\n0 1 0 0\n";
    const NffScene a = parse(unix_text);
    const NffScene b = parse(replace_all(unix_text, "\n", "\r\n"));
    const NffScene c = parse(replace_all(unix_text, "\n", "\r"));
    for (const NffScene* s : {&b, &c}) {
        REQUIRE(s->spheres.size() == 1);
        REQUIRE(s->cones.size() == 1);
        CHECK(s->spheres[0].line == a.spheres[0].line);
        CHECK(s->cones[0].line == a.cones[0].line);
        CHECK(s->cones[0].apex == a.cones[0].apex);
    }
    const std::string bad = lit + "s 0 0 0 -1\n";
    CHECK_THROWS_WITH(parse(replace_all(bad, "\n", "\r\n")), "t.nff:10: sphere: radius must be above 0, got '-1'");
    CHECK_THROWS_WITH(parse(replace_all(bad, "\n", "\r")), "t.nff:10: sphere: radius must be above 0, got '-1'");
    // A byte order mark, as some Windows editors write, is not a command.
    CHECK(parse("\xEF\xBB\xBF" + unix_text).spheres.size() == 1);
}

TEST_CASE("NFF comments run from # to the end of the line, wherever the # stands", "[common]")
{
    const NffScene s = parse("# a scene\n" + lit +
                             "s 0 0 0 1 # a sphere\n"
                             "#s 5 5 5 1\n"
                             "s 1 1 1 2#glued to a number\n"
                             "   # indented\n"
                             "# the last line, with no line break");
    REQUIRE(s.spheres.size() == 2);
    CHECK(s.spheres[0].line == 11);
    CHECK(s.spheres[1].radius == 2.0f);
    CHECK(s.spheres[1].line == 13);
}

TEST_CASE("NFF numbers are read in every form printf's %g writes", "[common]")
{
    const NffScene s = parse(lit + "s +1 -2.5e-1 .5 2.\n");
    REQUIRE(s.spheres.size() == 1);
    CHECK(s.spheres[0].center == vec3(1.0f, -0.25f, 0.5f));
    CHECK(s.spheres[0].radius == 2.0f);
}

TEST_CASE("NFF polygons keep their winding; patches keep their normals, normalised", "[common]")
{
    // Counterclockwise seen from +z: the front faces +z.
    const NffScene p = parse(lit + "p 3\n0 0 0\n1 0 0\n0 1 0\n");
    REQUIRE(p.triangles.size() == 1);
    const NffTriangle& t = p.triangles[0];
    CHECK_FALSE(t.smooth);
    const vec3 winding = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    CHECK(winding.z > 0.0f);
    for (const vec3& n : t.n)
        CHECK(n == vec3(0, 0, 1));

    const NffScene pp = parse(lit + "pp 4\n0 0 0 0 0 2\n1 0 0 1 0 1\n1 1 0 0 3 4\n0 1 0 0 0 1\n");
    REQUIRE(pp.triangles.size() == 2);
    bool saw_tilted = false;
    for (const NffTriangle& tri : pp.triangles) {
        CHECK(tri.smooth);
        CHECK(glm::cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]).z > 0.0f);
        for (int k = 0; k < 3; ++k) {
            CHECK(glm::length(tri.n[k]) == Approx(1.0f));
            if (tri.p[k] == vec3(1, 1, 0)) {
                CHECK(tri.n[k].y == Approx(0.6f));
                CHECK(tri.n[k].z == Approx(0.8f));
                saw_tilted = true;
            }
        }
    }
    CHECK(saw_tilted);
}

TEST_CASE("a concave NFF polygon becomes triangles covering exactly its area", "[common]")
{
    // A U, counterclockwise: area 3 x 3 minus the 1 x 2 notch = 7.
    const NffScene s = parse(lit + "p 8\n0 0 0\n3 0 0\n3 3 0\n2 3 0\n2 1 0\n1 1 0\n1 3 0\n0 3 0\n");
    CHECK(s.triangles.size() == 6);
    CHECK(triangles_area(s) == Approx(7.0));
    for (const NffTriangle& t : s.triangles) {
        // Nothing in the notch: no triangle's centre lies in (1, 2) x (1, 3).
        const vec3 centre = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        CHECK_FALSE((centre.x > 1.0f && centre.x < 2.0f && centre.y > 1.0f));
    }
}

TEST_CASE("a polygon or patch with no area is skipped with a warning naming its line; a file of nothing else is refused", "[common]")
{
    const NffScene s = parse(lit + "p 3\n0 0 0\n1 1 1\n2 2 2\n" + "pp 3\n0 0 0 0 0 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n" +
                             "s 0 0 0 1\n");
    CHECK(s.spheres.size() == 1);
    CHECK(s.triangles.empty());
    CHECK(s.skipped_polygons == 2);
    REQUIRE(s.warnings.size() == 2);
    CHECK(s.warnings[0] == "t.nff:10: polygon: its vertices all lie on one line (no area): skipped");
    CHECK(s.warnings[1] == "t.nff:14: patch: has fewer than 3 distinct vertices (its corners coincide): skipped");
    CHECK_THROWS_WITH(parse(lit + "p 3\n0 0 0\n1 1 1\n2 2 2\n"), "t.nff:13: no objects (s, p, pp or c): nothing to render");
}

TEST_CASE("a file of a thousand polygons with no area warns of the first three and counts the rest in one line", "[common]")
{
    std::string text = lit;
    for (int k = 0; k < 1000; ++k)
        text += "p 3\n0 0 0\n1 1 1\n2 2 2\n";
    const NffScene s = parse(text + "s 0 0 0 1\n");
    CHECK(s.skipped_polygons == 1000);
    REQUIRE(s.warnings.size() == 4);
    CHECK(s.warnings[0] == "t.nff:10: polygon: its vertices all lie on one line (no area): skipped");
    CHECK(s.warnings[2] == "t.nff:18: polygon: its vertices all lie on one line (no area): skipped");
    CHECK(s.warnings[3] == "t.nff: 1000 polygons and patches with no area skipped in all (the first 3 named above)");
}

TEST_CASE("a scene only a few hundred float steps across at its distance from the origin is warned of, once", "[common]")
{
    // 100 across at 1e7, where floats are 1 apart: a hundred steps across the scene.
    const NffScene far = parse(lit + "s 10000000 10000000 10000000 2\ns 10000096 10000000 10000000 2\n");
    REQUIRE(far.warnings.size() == 1);
    CHECK_THAT(far.warnings[0], rt::grader::contains_text("t.nff: the scene is 100 across but lies 1.00001e+07 from the origin, "
                                                          "where float's step is 1: only 100 steps across it"));
    // The same scene at 1e3 (floats 6e-5 apart), and a tiny one at the origin: no warning.
    CHECK(parse(lit + "s 1000 1000 1000 2\ns 1096 1000 1000 2\n").warnings.empty());
    CHECK(parse(lit + "s 0 0 0 1e-12\n").warnings.empty());
}

TEST_CASE("a scene that rounding collapses to one point is warned of", "[common]")
{
    // 0.3 across at 1e8, where floats are 8 apart: every sphere's centre and extent round to one point.
    const NffScene dot = parse(lit + "s 100000000 100000000 100000000 0.3\ns 100000001 100000002 100000000 0.3\n");
    REQUIRE(dot.warnings.size() == 1);
    CHECK_THAT(dot.warnings[0], rt::grader::contains_text("t.nff: every object rounds to one point, 1e+08 1e+08 1e+08, "
                                                          "where float's step is 8: the scene draws as one dot"));
}

TEST_CASE("every kind of bad NFF file is answered with FILE:LINE: what is wrong", "[common]")
{
    struct Case {
        std::string text;
        std::string message;
    };
    const std::string f = "f 1 1 1 1 0 0 0 0\n";
    const std::vector<Case> cases = {
        // What the whole file lacks: reported at its last line.
        {"", "t.nff:1: no view ('v'): an NFF file must give one"},
        {"# only a comment\n\n", "t.nff:2: no view ('v'): an NFF file must give one"},
        {"l 1 1 1\n" + f + "s 0 0 0 1\n", "t.nff:3: no view ('v'): an NFF file must give one"},
        {lit, "t.nff:9: no objects (s, p, pp or c): nothing to render"},
        {view_lines + f + "s 0 0 0 1\n", "t.nff:9: no lights ('l'): every object would be black"},
        // Truncated files: reported where the last token stands.
        {lit + "s 0 0 0", "t.nff:10: sphere: the file ends before radius"},
        {"v\nfrom 0 0 5\nat 0 0", "t.nff:3: view: the file ends before at z"},
        {"v\nfrom 0 0 5\n", "t.nff:2: view: the file ends before 'at', 'up', 'angle', 'hither' or 'resolution'"},
        {lit + "p 4\n0 0 0\n1 0 0\n", "t.nff:12: polygon: the file ends before vertex 3 x"},
        {lit + "c\n0 0 0 1\n0 1 0\n", "t.nff:12: cone: the file ends before apex radius"},
        {lit + "f 1 1 1 1 0", "t.nff:10: material: the file ends before Shine"},
        // Microsoft's spellings of NaN and infinity, refused where they stand, not read as 1 and a comment.
        {lit + "s 0 0 0\n-1.#QNAN\ns 1 1 1 1\n",
         "t.nff:11: sphere: radius must be a number, got '-1.#QNAN', Microsoft's spelling of NaN or infinity: what wrote the file computed no number there"},
        {lit + "s 1.#INF 0 0 1\n",
         "t.nff:10: sphere: center x must be a number, got '1.#INF', Microsoft's spelling of NaN or infinity: what wrote the file computed no number there"},
        {lit + "s 0 0 0 -1.#IND00\n",
         "t.nff:10: sphere: radius must be a number, got '-1.#IND00', Microsoft's spelling of NaN or infinity: what wrote the file computed no number there"},
        // The view.
        {"v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nresolution 8 8\nl 1 1 1\n",
         "t.nff:7: view: expected 'hither', got 'l'"},
        {"v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nyon 100\n",
         "t.nff:7: view: expected 'resolution', got 'yon'"},
        {"v\nfrom 0 0 5\nfrom 0 0 5\n", "t.nff:3: view: 'from' is given twice"},
        {lit + view_lines, "t.nff:10: a second view ('v'); the first is at line 1"},
        {replace_all(lit, "angle 40", "angle 180"),
         "t.nff:5: view: angle must lie strictly between 0 and 180 degrees, got '180'"},
        {replace_all(lit, "angle 40", "angle 0"),
         "t.nff:5: view: angle must lie strictly between 0 and 180 degrees, got '0'"},
        {replace_all(lit, "hither 1", "hither -1"), "t.nff:6: view: hither must not be negative, got '-1'"},
        {replace_all(lit, "resolution 8 8", "resolution 0 8"),
         "t.nff:7: view: resolution width must be between 1 and 16384, got '0'"},
        {replace_all(lit, "resolution 8 8", "resolution 8 99999"),
         "t.nff:7: view: resolution height must be between 1 and 16384, got '99999'"},
        {replace_all(lit, "resolution 8 8", "resolution 8 1.5"),
         "t.nff:7: view: resolution height must be a whole number, got '1.5'"},
        {replace_all(lit, "at 0 0 0", "at 0 0 5"), "t.nff:3: view: from and at are the same point (no view direction)"},
        {replace_all(lit, "up 0 1 0", "up 0 0 -3"), "t.nff:4: view: up is zero or parallel to the view direction"},
        {replace_all(lit, "up 0 1 0", "up 0 0 0"), "t.nff:4: view: up is zero or parallel to the view direction"},
        // Numbers that are not numbers, not finite, or out of range.
        {lit + "s 0 zero 0 1\n", "t.nff:10: sphere: center y must be a number, got 'zero'"},
        {lit + "s 0 0 0 nan\n", "t.nff:10: sphere: radius must be a finite number, got 'nan'"},
        {lit + "s inf 0 0 1\n", "t.nff:10: sphere: center x must be a finite number, got 'inf'"},
        {lit + "s 0 0 -infinity 1\n", "t.nff:10: sphere: center z must be a finite number, got '-infinity'"},
        {lit + "s 1e400 0 0 1\n", "t.nff:10: sphere: center x is out of range, got '1e400'"},
        {lit + "s 1e13 0 0 1\n", "t.nff:10: sphere: center x is too large (the reader takes up to 1e12), got '1e13'"},
        {lit + "s 0x10 0 0 1\n", "t.nff:10: sphere: center x must be a number, got '0x10'"},
        {lit + "s 1,5 0 0 1\n", "t.nff:10: sphere: center x must be a number, got '1,5'"},
        {lit + "s 0 0 0\n" + f, "t.nff:11: sphere: radius must be a number, got 'f' (too few numbers?)"},
        {lit + "s 0 0 0 1 2\n", "t.nff:10: unexpected number '2' where a command should start (too many numbers before it?)"},
        {lit + "s 0 0 0 \x01\xff\n", "t.nff:10: sphere: radius must be a number, got '\\x01\\xff'"},
        // Sizes.
        {lit + "s 0 0 0 -1\n", "t.nff:10: sphere: radius must be above 0, got '-1'"},
        {lit + "s 0 0 0 0\n", "t.nff:10: sphere: radius must be above 0, got '0'"},
        {lit + "c 0 0 0 1 0 0 0 0.5\n", "t.nff:10: cone: base and apex are the same point (NFF: they cannot be coincident)"},
        {lit + "c 0 0 0 -1 0 1 0 -1\n",
         "t.nff:10: cone: base radius must not be negative, got '-1' (NFF's inside-only cones are not supported)"},
        {lit + "c 0 0 0 1 0 1 0 -0.5\n",
         "t.nff:10: cone: apex radius must not be negative, got '-0.5' (NFF's inside-only cones are not supported)"},
        {lit + "c 0 0 0 0 0 1 0 0\n", "t.nff:10: cone: both radii are 0 (a line, no surface)"},
        // Polygons: wrong vertex counts, too few vertices, no area, crossing edges, not planar.
        {lit + "p 4\n0 0 0\n1 0 0\n1 1 0\ns 0 0 0 1\n",
         "t.nff:14: polygon: vertex 4 x must be a number, got 's' (fewer vertices than the 4 announced?)"},
        {lit + "p 3\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n",
         "t.nff:14: unexpected number '0' where a command should start (too many numbers before it?)"},
        {lit + "p 2\n0 0 0\n1 0 0\n", "t.nff:10: polygon: needs at least 3 vertices, got 2"},
        {lit + "p -1\n", "t.nff:10: polygon: needs at least 3 vertices, got -1"},
        {lit + "p 3.5\n", "t.nff:10: polygon: the vertex count must be a whole number, got '3.5'"},
        {lit + "p 99999999999999999999\n", "t.nff:10: polygon: the vertex count is out of range, got '99999999999999999999'"},
        {lit + "p 10001\n", "t.nff:10: polygon: has 10001 vertices; the reader takes at most 10000"},
        {lit + "p\n", "t.nff:10: polygon: the file ends before the vertex count"},
        {lit + "p 4\n0 0 0\n2 2 0\n2 0 0\n0 1 0\n", "t.nff:10: polygon: edges 1 and 3 cross (NFF polygons are simple)"},
        {lit + "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 1\n",
         "t.nff:10: polygon: vertex 1 lies 0.204124 off the plane of the others (NFF polygons are planar)"},
        {lit + "pp 3\n0 0 0 0 0 0\n1 0 0 0 0 1\n0 1 0 0 0 1\n", "t.nff:11: patch: normal 1 is zero"},
        {lit + "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n", "t.nff:12: patch: the file ends before vertex 3 x"},
        // Materials, lights and background.
        {view_lines + "l 1 1 1\ns 0 0 0 1\n",
         "t.nff:9: sphere comes before any material ('f'): NFF objects take the last 'f' before them"},
        {view_lines + "l 1 1 1\np 3 0 0 0 1 0 0 0 1 0\n",
         "t.nff:9: polygon comes before any material ('f'): NFF objects take the last 'f' before them"},
        {lit + "f 1 1 1 1 0 0 2 1.5\n", "t.nff:10: material: T must lie between 0 and 1, got '2'"},
        {lit + "f 1 1 1 1 0 0 0.5 0\n",
         "t.nff:10: material: a transmitting material (T > 0) needs an index of refraction above 0, got '0'"},
        {lit + "f 1 1 1 -1 0 0 0 0\n", "t.nff:10: material: Kd must not be negative, got '-1'"},
        {lit + "f 1 1 1 1.5 0 0 0 0\n", "t.nff:10: material: Kd must lie between 0 and 1, got '1.5'"},
        {lit + "f 1 1 1 1 0.1e12 0 0 0\n", "t.nff:10: material: Ks must lie between 0 and 1, got '0.1e12'"},
        {lit + "f 1 -1 1 1 0 0 0 0\n", "t.nff:10: material: green must not be negative, got '-1'"},
        {lit + "b -1 0 0\n", "t.nff:10: background: red must not be negative, got '-1'"},
        {view_lines + "l 1 1 1 0.5\n" + f, "t.nff:9: light: green must be a number, got 'f' (too few numbers?)"},
        {view_lines + "l 1 1 1 0.5 -1 0\n" + f, "t.nff:8: light: green must not be negative, got '-1'"},
        // Unknown commands.
        {lit + "sphere 0 0 0 1\n",
         "t.nff:10: unknown command 'sphere' (NFF has v, b, l, f, s, p, pp, c and # comments)"},
        {lit + "\x01\x02\n", "t.nff:10: unknown command '\\x01\\x02' (NFF has v, b, l, f, s, p, pp, c and # comments)"},
        {lit + std::string(100, 'x') + "\n",
         "t.nff:10: unknown command 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...' (NFF has v, b, l, f, s, p, pp, c and # comments)"},
    };
    for (const Case& c : cases) {
        INFO("the file:\n" << c.text);
        CHECK_THROWS_WITH(parse(c.text), c.message);
    }
}

TEST_CASE("a missing NFF file, or a folder, is answered with FILE:1: what is wrong", "[common]")
{
    CHECK_THROWS_WITH(read_nff("/no/such/folder/scene.nff"), "/no/such/folder/scene.nff:1: no such file");
    const std::string folder = std::filesystem::temp_directory_path().string();
    CHECK_THROWS_WITH(read_nff(folder), folder + ":1: is a folder, not an NFF file");
}

TEST_CASE("an NFF view whose from is 1e-29 from at is a view, and the same point is not", "[common]")
{
    // |from - at|^2 is 1e-58, 0 in float.
    const NffScene s = parse(replace_all(lit, "from 0 0 5", "from 0 0 1e-29") + "s 0 0 -3 1\n");
    CHECK(s.view.from != s.view.at);
    CHECK_THROWS_WITH(parse(replace_all(lit, "at 0 0 0", "at 0 0 5") + "s 0 0 -3 1\n"),
                      "t.nff:3: view: from and at are the same point (no view direction)");
}

TEST_CASE("a tessellated ball 0.1 across is read whole at the origin and 1e3 and 1e5 from it", "[common]")
{
    // 19,800 triangles 3e-3 to 6e-3 across. A tolerance of 16 float steps of the farthest corner,
    // once used as a width, skipped every one at x = 1e3. At 1e5 floats are 0.0078 apart along x,
    // more than a triangle, so a triangle is skipped only where its float corners truly have no area.
    for (const double out : {0.0, 1e3, 1e5}) {
        std::ostringstream text;
        text << view_lines << "l 1 1 1\nf 1 0 0 1 0 0 0 0\n";
        text.precision(9);
        const int around = 100, down = 100;
        const auto corner = [&](int i, int j) {
            const double theta = 3.14159265358979 * j / down, phi = 6.28318530717959 * i / around;
            return dvec3(out + 0.05 * std::sin(theta) * std::cos(phi), 0.05 * std::cos(theta),
                         0.05 * std::sin(theta) * std::sin(phi));
        };
        int written = 0, without_area = 0;
        const auto triangle = [&](const dvec3& a, const dvec3& b, const dvec3& c) {
            text << "p 3\n" << a.x << ' ' << a.y << ' ' << a.z << '\n' << b.x << ' ' << b.y << ' ' << b.z << '\n'
                 << c.x << ' ' << c.y << ' ' << c.z << '\n';
            ++written;
            // The corners as the reader's floats hold them.
            const dvec3 fa{point3(a)}, fb{point3(b)}, fc{point3(c)};
            without_area += glm::length(glm::cross(fb - fa, fc - fa)) == 0.0 ? 1 : 0;
        };
        for (int j = 0; j < down; ++j)
            for (int i = 0; i < around; ++i) {
                const dvec3 a = corner(i, j), b = corner(i + 1, j), c = corner(i + 1, j + 1), d = corner(i, j + 1);
                if (j > 0)
                    triangle(a, c, b);
                if (j < down - 1)
                    triangle(a, d, c);
            }
        const NffScene s = parse(text.str());
        INFO("the ball at x = " << out << ": " << written << " triangles written, " << without_area
                                << " without area in float, " << s.triangles.size() << " read, " << s.skipped_polygons
                                << " skipped");
        CHECK(written == 19800);
        CHECK(s.skipped_polygons == without_area);
        CHECK(s.triangles.size() == static_cast<std::size_t>(written - without_area));
        if (out < 1e4)
            CHECK(without_area == 0);
    }
}

TEST_CASE("a view or objects beyond float's reach are named once, and a scene within it is not", "[common]")
{
    // An eye 1e6 times the scene's size away, with the angle that frames it: float turns a ray by
    // more than a pixel there.
    const std::string far_eye =
        "v\nfrom 0 0 5e6\nat 0 0 0\nup 0 1 0\nangle 0.00002\nhither 1\nresolution 64 64\nl 1 1 1\nf 1 0 0 1 0 0 0 0\n"
        "s 0 0 0 1\n";
    const NffScene far = parse(far_eye);
    REQUIRE(far.warnings.size() == 1);
    CHECK(far.warnings[0].find("t.nff:1: float cannot hold this view") == 0);
    CHECK(far.warnings[0].find("the eye stands 5e+06 from what it looks at") != std::string::npos);
    // Triangles 0.02 across 1e5 from the origin, beside a floor 2e5 across: the scene is wide enough,
    // but a feeler leaves those triangles 2 off their surface, past each other's shadows.
    std::string tiny = lit + "p 3\n-1e5 0 -1e5\n0 0 1e5\n1e5 0 -1e5\n";
    for (int k = 0; k < 3; ++k)
        tiny += "p 3\n1e5 0.01 " + std::to_string(k) + "\n100000.02 0.01 " + std::to_string(k) + "\n1e5 0.02 " +
                std::to_string(k) + ".02\n";
    const NffScene fine = parse(tiny);
    REQUIRE(fine.warnings.size() == 1);
    CHECK(fine.warnings[0].find("t.nff: 3 objects are smaller than a shadow feeler's offset where they lie") == 0);
    // The same triangles near the origin: nothing to say.
    std::string near = lit;
    for (int k = 0; k < 3; ++k)
        near += "p 3\n1 0.01 " + std::to_string(k) + "\n1.02 0.01 " + std::to_string(k) + "\n1 0.02 " +
                std::to_string(k) + ".02\n";
    CHECK(parse(near).warnings.empty());
}
