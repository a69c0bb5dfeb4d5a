// Chapter 02's program: renders the figure (spheres and triangle meshes) with the sphere and
// triangle tests of your choice and, with --sweep, measures what each test costs and how often it
// is wrong on the extreme cases, in float and in double.
#include "02_spheres_triangles/extremes.hpp"
#include "02_spheres_triangles/figure.hpp"
#include "02_spheres_triangles/nff_scene.hpp"
#include "common/cli.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/scene_file.hpp"
#include "common/lesson_table.hpp"
#include "common/trade.hpp"

#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <type_traits>

using namespace rt;

namespace {

struct Options {
    CommonOptions common;
    std::string sphere = "precise";
    std::string triangle = "moller-trumbore";
    SweepOptions sweep{false, 7, "02_spheres_triangles.csv"};
    int probes = 100000;
    std::string scene;
};

ShapeTests tests_named(const Options& o)
{
    ShapeTests tests;
    const std::map<std::string, SphereTest> spheres{{"slide", SphereTest::slide}, {"precise", SphereTest::precise}};
    const std::map<std::string, TriangleTest> triangles{{"slide", TriangleTest::slide},
                                                        {"moller-trumbore", TriangleTest::moller_trumbore},
                                                        {"watertight", TriangleTest::watertight}};
    if (!spheres.count(o.sphere))
        throw InputError("--sphere takes slide or precise, got '" + o.sphere + "'");
    if (!triangles.count(o.triangle))
        throw InputError("--triangle takes slide, moller-trumbore or watertight, got '" + o.triangle + "'");
    tests.sphere = spheres.at(o.sphere);
    tests.triangle = triangles.at(o.triangle);
    return tests;
}

// --- The trade: every test, in float and in double, on every extreme case ---

// One measured row: which case, which test in which precision, and what it cost and got wrong.
struct Measured {
    std::string group;  // "sphere" or "triangle"
    std::string case_name, test, precision;
    Timing seconds;
    std::uint64_t tests;
    extremes::Score score;
    double ns_per_test() const { return tests ? 1e9 * seconds.median / static_cast<double>(tests) : 0.0; }
};

template <class T>
const char* precision_name()
{
    return std::is_same_v<T, float> ? "float" : "double";
}

// Runs each test on each case `repeat` times (the median time counts) and scores its answers.
template <class T, class Probes, class Answers, class Test>
void measure(const Options& o, const std::string& group, const std::vector<std::pair<std::string, Test>>& tests,
             const std::vector<std::pair<std::string, std::function<Probes()>>>& cases, std::vector<Measured>& rows)
{
    Answers answers;
    for (const auto& [case_name, make] : cases) {
        const Probes probes = make();
        for (const auto& [name, test] : tests) {
            const Timing seconds =
                time_runs(o.sweep.repeat, [&, &test = test] { extremes::run(probes, test, answers); });
            rows.push_back({group, case_name, name, precision_name<T>(), seconds, extremes::tests_in(probes),
                            extremes::score(probes, answers)});
        }
    }
}

template <class T>
void measure_spheres(const Options& o, std::vector<Measured>& rows)
{
    using Test = std::optional<T> (*)(const BasicRay<T>&, const BasicSphere<T>&, BasicInterval<T>);
    using Probes = std::vector<extremes::SphereProbe<T>>;
    const int n = o.probes;
    measure<T, Probes, std::vector<std::optional<T>>, Test>(
        o, "sphere", {{"slide", &hit_sphere_slide<T>}, {"precise", &hit_sphere_precise<T>}},
        {
            {"D=1e2", [&] { return extremes::distant_spheres<T>(1e2f, 1.0f, n, 1); }},
            {"D=1e3", [&] { return extremes::distant_spheres<T>(1e3f, 1.0f, n, 1); }},
            {"D=1e4", [&] { return extremes::distant_spheres<T>(1e4f, 1.0f, n, 1); }},
            {"D=1e5", [&] { return extremes::distant_spheres<T>(1e5f, 1.0f, n, 1); }},
            {"D=1e6", [&] { return extremes::distant_spheres<T>(1e6f, 1.0f, n, 1); }},
            {"r=1e-3", [&] { return extremes::distant_spheres<T>(1.0f, 1e-3f, n, 1); }},
            {"r=1e-4", [&] { return extremes::distant_spheres<T>(1.0f, 1e-4f, n, 1); }},
            {"huge", [&] { return extremes::huge_sphere<T>(n, 1); }},
            {"inside", [&] { return extremes::inside_sphere<T>(n, 1); }},
        },
        rows);
}

template <class T>
void measure_triangles(const Options& o, std::vector<Measured>& rows)
{
    using Test = std::optional<TriangleHit<T>> (*)(const BasicRay<T>&, const BasicTriangle<T>&, BasicInterval<T>);
    using Probes = extremes::TriangleProbes<T>;
    // About o.probes tests a case (the mesh has 162 vertices, 480 edges; the far mesh 1280 faces).
    const IndexedMesh mesh = extremes::jittered_icosphere(1);
    const int n = o.probes;
    measure<T, Probes, std::vector<extremes::TriangleAnswer<T>>, Test>(
        o, "triangle",
        {{"slide", &hit_triangle_slide<T>},
         {"moller-trumbore", &hit_triangle_moller_trumbore<T>},
         {"watertight", &hit_triangle_watertight<T>}},
        {
            {"around", [&] { return extremes::around_triangles<T>(mesh, n, 1); }},
            {"vertex-aimed", [&] { return extremes::vertex_aimed<T>(mesh, std::max(1, n / 1000), 1); }},
            {"edge-aimed", [&] { return extremes::edge_aimed<T>(mesh, std::max(1, n / 1000), 1); }},
            {"inside-far-mesh", [&] { return extremes::inside_far_mesh<T>(std::max(1, n / 1280), 1); }},
            {"degenerate", [&] { return extremes::degenerate<T>(std::max(1, n / 42), 1); }},
        },
        rows);
}

// The lesson's tables per group: a row per case, a column per test and precision, each cell the
// wrong answers and the largest relative error of t; then, apart (it is timed), the median time
// per test over the cases.
std::vector<LessonTable> summary(const std::vector<Measured>& rows, const std::string& group, int repeat)
{
    const std::map<std::string, std::string> case_names = {
        {"D=1e2", "D = 1e2"}, {"D=1e3", "D = 1e3"}, {"D=1e4", "D = 1e4"}, {"D=1e5", "D = 1e5"}, {"D=1e6", "D = 1e6"},
        {"r=1e-3", "r = 1e-3 at 1"}, {"r=1e-4", "r = 1e-4 at 1"}, {"huge", "huge (r = 1e4, eye 1 above)"},
        {"inside", "from inside"}, {"around", "around faces (half hit)"}, {"vertex-aimed", "vertex-aimed"},
        {"edge-aimed", "edge-aimed"}, {"inside-far-mesh", "inside the far mesh"}, {"degenerate", "degenerate"}};
    const auto named = [&](const std::string& c) { return case_names.count(c) ? case_names.at(c) : c; };
    std::vector<std::string> columns, cases;
    std::map<std::pair<std::string, std::string>, const Measured*> cell;
    std::map<std::string, std::vector<double>> ns;
    for (const Measured& m : rows) {
        if (m.group != group)
            continue;
        const std::string column = (m.test == "moller-trumbore" ? std::string("M-T") : m.test) + " " + m.precision;
        if (std::find(columns.begin(), columns.end(), column) == columns.end())
            columns.push_back(column);
        if (std::find(cases.begin(), cases.end(), m.case_name) == cases.end())
            cases.push_back(m.case_name);
        cell[{m.case_name, column}] = &m;
        ns[column].push_back(m.ns_per_test());
    }
    LessonTable errors{"02." + group, {{"case"}}, {}, "Each cell: the share of wrong hit/miss answers, and the largest relative error of t, both against long double."};
    LessonTable times{"02." + group + "_ns", {{""}}, {},
                      "Release build, each test a call into the compiled code as the scene query makes it, median of " +
                          std::to_string(repeat) + " runs a case, then the median over the cases (they mix hits and misses)."};
    for (const std::string& column : columns) {
        errors.columns.push_back({column});
        times.columns.push_back({column, true});
    }
    for (const std::string& c : cases) {
        std::vector<std::string> cells{named(c)};
        for (const std::string& column : columns) {
            const Measured& m = *cell[{c, column}];
            std::string text = significant(100.0 * m.score.wrong_fraction(), 2) + "%";
            if (m.score.max_rel_t_error > 0.0)
                text += ", " + scientific(m.score.max_rel_t_error, 2);
            cells.push_back(text);
        }
        errors.row(cells);
    }
    std::vector<std::string> cells{"**ns per test**"};
    for (const std::string& column : columns) {
        std::vector<double>& v = ns[column];
        std::sort(v.begin(), v.end());
        cells.push_back(fixed(v[v.size() / 2], 1));
    }
    times.row(cells);
    return {errors, times};
}

void sweep(const Options& o)
{
    std::cerr << "measuring every test in float and double on the extreme cases...\n";
    std::vector<Measured> rows;
    measure_spheres<float>(o, rows);
    measure_spheres<double>(o, rows);
    measure_triangles<float>(o, rows);
    measure_triangles<double>(o, rows);

    // The common trade tables: the test is the knob; rays counts intersection tests.
    TradeTable wrong{"02_spheres_triangles", "fraction of wrong hit/miss answers against long double", {}};
    TradeTable t_error{"02_spheres_triangles", "max relative error of t against long double", {}};
    for (const Measured& m : rows) {
        const std::string value = m.group + ":" + m.case_name + ":" + m.test + ":" + m.precision;
        wrong.rows.push_back({"group:case:test:precision", value, m.seconds, m.tests, m.score.wrong_fraction()});
        t_error.rows.push_back({"group:case:test:precision", value, m.seconds, m.tests, m.score.max_rel_t_error});
    }
    print_trade_table(std::cout, wrong);
    std::cout << '\n';
    print_trade_table(std::cout, t_error);
    std::vector<LessonTable> lesson = summary(rows, "sphere", o.sweep.repeat);
    for (const LessonTable& t : summary(rows, "triangle", o.sweep.repeat))
        lesson.push_back(t);
    write_lesson_tables(tables_beside(o.sweep.csv), lesson, std::cout);
    const std::string t_error_csv = csv_beside(o.sweep.csv, "_t_error");
    write_trade_csv(o.sweep.csv, wrong);
    write_trade_csv(t_error_csv, t_error);
    std::cout << "\nwrote " << o.sweep.csv << ", " << t_error_csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("02_spheres_triangles", [&] {
        Options o;
        CommandLine cli = program_command_line(
            "02_spheres_triangles", "Spheres and triangles: the slide's tests, precise, robust, measured.", o.common);
        cli.option("--sphere", o.sphere, "the sphere test of the render: slide or precise");
        cli.option("--triangle", o.triangle, "the triangle test of the render: slide, moller-trumbore or watertight");
        add_sweep_options(cli, o.sweep, "measure every test's cost and error in float and double on the extreme cases",
                          "where --sweep writes its table (the t errors go beside it, *_t_error.csv)");
        cli.option("--probes", o.probes, "rays per extreme case in the sweep", 1000, 100000000);
        add_scene_option(cli, o.scene);
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        const ShapeTests tests = tests_named(o);
        check_scene_without_sweep(o.scene, o.sweep.on);
        if (o.sweep.on) {
            check_writable(o.sweep.csv, "CSV");
            sweep(o);
            return 0;
        }
        if (!o.scene.empty()) {
            const SceneRender file = load_scene_render(o.scene, o.common, cli);
            const ShapeScene scene = shape_scene(file.scene);
            return write_figure(o.common, [&] {
                return render(file.settings, [&](float x, float y, Rng&) {
                    return ch02::radiance(scene, file.eye_ray(primary_ray(file.camera, x, y)), tests);
                });
            });
        }
        return write_figure(o.common, [&] { return ch02::render_figure(render_settings(o.common), tests); });
    });
}
