// Chapter 04's program: renders the figure (a sphere with a hard shadow from a point light) with
// the offset and shadow query of your choice, at any scale, and with --sweep measures the two
// trades: how often each offset re-hits its own surface or misses a real occluder, at scales from
// 1e-4 to 1e6; and what shadow feelers cost, any-hit against closest-hit.
#include "04_shadow_feelers/classic.hpp"
#include "04_shadow_feelers/figure.hpp"
#include "04_shadow_feelers/scale_families.hpp"
#include "04_shadow_feelers/self_intersection.hpp"
#include "common/cli.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/scene_file.hpp"
#include "common/lesson_table.hpp"
#include "common/trade.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace rt;

namespace {

struct Options {
    CommonOptions common;
    std::string offset = "robust";
    std::string feelers = "any-hit";
    float scale = 1.0f;
    SweepOptions sweep{false, 7, "04_shadow_feelers.csv"};
    int probes = 100000;
    std::string scene;
    bool classic = false;
    bool two_sided = false;
};

const std::vector<std::pair<std::string, Offset>> offsets = {
    {"none", Offset::none}, {"t-min", Offset::t_min}, {"normal", Offset::normal}, {"robust", Offset::robust}};

FeelerSettings feelers_named(const Options& o)
{
    const std::map<std::string, Offset> offset_names(offsets.begin(), offsets.end());
    const std::map<std::string, ShadowQuery> queries{
        {"any-hit", ShadowQuery::any_hit}, {"closest-hit", ShadowQuery::closest_hit}, {"off", ShadowQuery::off}};
    if (!offset_names.count(o.offset))
        throw InputError("--offset takes none, t-min, normal or robust, got '" + o.offset + "'");
    if (!queries.count(o.feelers))
        throw InputError("--feelers takes any-hit, closest-hit or off, got '" + o.feelers + "'");
    return {offset_names.at(o.offset), queries.at(o.feelers)};
}

// --- The measured problem: self-intersection by scale ---

struct Case {
    std::string name;  // what the table's title says
    std::string table;  // the lesson's table of it ("" for none)
    self_intersection::Surface surface;
    self_intersection::Side side;
    self_intersection::PointFrom from;
    float eye_distance = 3.0f;  // in units of S
    self_intersection::Test test = self_intersection::Test::watertight;
};

// 0%, 0.0035%, 3.5%, 45%, 100%: two significant digits, never in exponent form.
std::string percent(double rate)
{
    std::ostringstream s;
    const double p = 100.0 * rate;
    if (p == 0.0 || p >= 10.0)
        s << std::fixed << std::setprecision(0) << p << '%';
    else
        s << std::setprecision(2) << p << '%';
    return s.str();
}

// 1e-4, ..., 1, ..., 1e6: the scales as powers of ten.
std::string power_of_ten(float scale)
{
    const int k = static_cast<int>(std::lround(std::log10(scale)));
    return k == 0 ? "1" : "1e" + std::to_string(k);
}

// A markdown table per case: a row per scale, a column per offset, each cell the re-hit rate and,
// for front-side feelers, the rate of occluders missed. Every row also goes into the trade tables.
void measure_offsets(const Options& o, TradeTable& rehit_table, TradeTable& missed_table, std::vector<LessonTable>& lesson)
{
    using namespace self_intersection;
    const std::vector<Case> cases = {
        {"triangles (icosphere), feelers toward a light outside", "04.triangles", Surface::triangles, Side::front, PointFrom::surface},
        {"triangles, feelers into the object (back side)", "", Surface::triangles, Side::back, PointFrom::surface},
        {"a sphere, feelers toward a light outside", "", Surface::sphere, Side::front, PointFrom::surface},
        {"a floor through y = 0, 20 S square, feelers up", "04.floor", Surface::floor, Side::front, PointFrom::surface},
        {"a floor through y = 0, feelers down (back side)", "", Surface::floor, Side::back, PointFrom::surface},
        {"a floor through y = 0, feelers up, the test refusing t within its rounding (the kit's)", "04.floor_bounded",
         Surface::floor, Side::front, PointFrom::surface, 3.0f, Test::bounded},
        {"a floor through y = 0, feelers down, the test refusing t within its rounding (the kit's)", "", Surface::floor,
         Side::back, PointFrom::surface, 3.0f, Test::bounded},
        {"triangles, p from the surface", "04.far", Surface::triangles, Side::front, PointFrom::surface, 1000.0f},
        {"triangles, p = ray.at(t)", "04.far", Surface::triangles, Side::front, PointFrom::ray, 1000.0f},
        {"sphere, p from the surface", "04.far", Surface::sphere, Side::front, PointFrom::surface, 1000.0f},
        {"sphere, p = ray.at(t)", "04.far", Surface::sphere, Side::front, PointFrom::ray, 1000.0f},
    };
    // The lesson's names of the offsets, and the far eye's table: Wachter-Binder's re-hits, a row
    // per case and a column per scale.
    const std::map<std::string, std::string> offset_header = {
        {"none", "none"}, {"t-min", "t-min = 1e-4"}, {"normal", "p + 1e-4 n"}, {"robust", "Wachter-Binder"}};
    LessonTable far{"04.far", {{"S"}}, {}, "Wachter-Binder's re-hits with the eye 1000 S away; " +
                                              grouped(static_cast<unsigned long long>(o.probes)) + " feelers a cell."};
    for (const float scale : self_intersection::scales)
        far.columns.push_back({power_of_ten(scale)});
    for (const Case& c : cases) {
        const bool front = c.side == Side::front;
        LessonTable table{c.table, {{"S"}}, {},
                          grouped(static_cast<unsigned long long>(o.probes)) + " feelers a cell" +
                              (front ? ": re-hits / occluders missed." : ": re-hits.")};
        for (const auto& [name, offset] : offsets)
            table.columns.push_back({offset_header.at(name)});
        std::vector<std::string> far_row{c.name};
        std::cout << "\n" << c.name << (front ? ": re-hits / occluders missed" : ": re-hits") << "\n\n| S |";
        for (const auto& [name, offset] : offsets)
            std::cout << ' ' << name << " |";
        std::cout << "\n|---|";
        for (size_t k = 0; k < offsets.size(); ++k)
            std::cout << "---|";
        std::cout << '\n';
        for (const float scale : self_intersection::scales) {
            const ScaledScene scene = scaled_scene(scale);
            const std::vector<SurfacePoint> points = surface_points(scene, c.surface, o.probes, 1, c.from, c.eye_distance);
            std::cout << "| " << power_of_ten(scale) << " |";
            std::vector<std::string> cells{power_of_ten(scale)};
            for (const auto& [name, offset] : offsets) {
                Score score;
                const Timing seconds = time_runs(1, [&, &offset = offset] { score = measure(scene, points, offset, c.side, 2, c.test); });
                const std::string cell = percent(score.rehit_rate()) + (front ? " / " + percent(score.missed_rate()) : "");
                std::cout << ' ' << cell << " |";
                cells.push_back(cell);
                if (offset == Offset::robust)
                    far_row.push_back(percent(score.rehit_rate()));
                std::ostringstream value;
                value << (c.surface == Surface::sphere ? "sphere" : c.surface == Surface::floor ? "floor" : "triangles") << ':' << (front ? "front" : "back")
                      << ':' << (c.from == PointFrom::surface ? "surface" : "ray") << ':' << c.eye_distance << "S:"
                      << (c.test == Test::bounded ? "bounded:" : "") << name
                      << ':' << power_of_ten(scale);
                rehit_table.rows.push_back({"surface:side:point:eye:offset:scale", value.str(), seconds, score.feelers,
                                            score.rehit_rate()});
                if (front)
                    missed_table.rows.push_back({"surface:side:point:eye:offset:scale", value.str(), seconds,
                                                 score.feelers, score.missed_rate()});
            }
            std::cout << '\n';
            table.row(cells);
        }
        if (c.table == "04.far")
            far.row(far_row);
        else if (!c.table.empty())
            lesson.push_back(table);
    }
    lesson.push_back(far);
}

// --- The cost of shadow feelers: any-hit against closest-hit ---

// The figure rendered without feelers, with any-hit feelers and with closest-hit ones. The runs are
// interleaved (one of each per round, --repeat rounds) so that a change in the machine's load
// falls on every row alike; each row's time is its median. The feelers' own cost is a row's time
// minus that of the row without them.
LessonTable measure_feeler_cost(const Options& o, TradeTable& table)
{
    RenderSettings settings = render_settings(o.common);
    settings.show_progress = false;
    const std::vector<std::pair<std::string, ShadowQuery>> queries = {
        {"off", ShadowQuery::off}, {"any-hit", ShadowQuery::any_hit}, {"closest-hit", ShadowQuery::closest_hit}};
    std::vector<Image> images;
    std::vector<Counts> counts;
    for (const auto& query : queries) {
        reset_counters();
        images.push_back(ch04::render_figure(settings, {Offset::robust, query.second}));
        counts.push_back(total_counts());
    }
    std::vector<std::vector<double>> runs(queries.size());
    for (int round = 0; round < o.sweep.repeat; ++round)
        for (size_t q = 0; q < queries.size(); ++q) {
            const Timer timer;
            ch04::render_figure(settings, {Offset::robust, queries[q].second});
            runs[q].push_back(timer.seconds());
        }
    const double seconds_off = median(runs[0]);
    const double feelers_any_hit = median(runs[1]) - seconds_off;
    const auto tests_of = [&](size_t q) {
        return static_cast<double>(counts[q][static_cast<size_t>(Counter::intersection_tests)]);
    };
    LessonTable lesson{"04.cost",
                       {{"feelers"}, {"seconds", true}, {"rays"}, {"rays/second", true}, {"shadow rays"},
                        {"tests per shadow ray"}, {"seconds in feelers", true}, {"vs any-hit", true},
                        {"RMSE vs any-hit"}},
                       {},
                       "The figure at " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                           ", " + std::to_string(settings.spp) + " spp, release build, median of " +
                           std::to_string(o.sweep.repeat) + " interleaved runs."};
    for (size_t q = 0; q < queries.size(); ++q) {
        const Timing timing = timing_of(runs[q]);
        const double seconds = timing.median;
        const std::uint64_t rays = total_rays(counts[q]);
        const auto shadow = counts[q][static_cast<size_t>(Counter::shadow_rays)];
        const double per_shadow_ray = shadow ? (tests_of(q) - tests_of(0)) / static_cast<double>(shadow) : 0.0;
        const double error = rmse(images[q], images[1]);
        lesson.row({queries[q].first, fixed(seconds, 3) + spread(timing), grouped(rays),
                    fixed(static_cast<double>(rays) / seconds / 1e3, 0) + " k", grouped(shadow), fixed(per_shadow_ray, 1),
                    fixed(seconds - seconds_off, 3), fixed((seconds - seconds_off) / feelers_any_hit, 2),
                    scientific(error, 3)});
        table.rows.push_back({"feelers", queries[q].first, timing, rays, error});
    }
    return lesson;
}

// Where the any-hit query saves: every feeler the figure sends, asked both ways on one thread, its
// intersection tests counted and its time taken, with blocked and unblocked feelers apart.
LessonTable feeler_tests_by_outcome(const Options& o)
{
    const Camera cam = make_camera(ch04::figure_camera(o.common.width, o.common.height));
    const LitScene scene = ch04::figure_scene();
    struct Tally {
        std::uint64_t feelers = 0, tests[2] = {0, 0};
        double seconds[2] = {0.0, 0.0};  // [0] any-hit, [1] closest-hit
    } blocked, seen, all;
    const auto tests = [] { return local_counts()[static_cast<size_t>(Counter::intersection_tests)]; };
    for (int j = 0; j < o.common.height; ++j)
        for (int i = 0; i < o.common.width; ++i) {
            const Ray ray = primary_ray(cam, static_cast<float>(i), static_cast<float>(j));
            const std::optional<Hit> hit = closest_hit(ray, scene, Interval{0.0f, infinity});
            if (!hit)
                continue;
            for_each_feeler(scene, ray, *hit, [&](const point3& light, const point3& origin) {
                bool is_blocked = false;
                std::uint64_t used[2];
                double seconds[2];
                for (int q = 0; q < 2; ++q) {
                    const std::uint64_t before = tests();
                    const Timer timer;
                    const bool b = q == 0 ? occluded(scene, origin, light, 0.0f)
                                          : occluded_by_closest_hit(scene, origin, light, 0.0f);
                    seconds[q] = timer.seconds();
                    used[q] = tests() - before;
                    is_blocked = is_blocked || b;
                }
                for (Tally* t : {is_blocked ? &blocked : &seen, &all}) {
                    ++t->feelers;
                    for (int q = 0; q < 2; ++q) {
                        t->tests[q] += used[q];
                        t->seconds[q] += seconds[q];
                    }
                }
            });
        }
    LessonTable lesson{"04.per_feeler",
                       {{"feelers"}, {"share"}, {"any-hit tests"}, {"closest-hit tests"}, {"any-hit ns", true},
                        {"closest-hit ns", true}},
                       {},
                       "Every feeler of the figure (" + std::to_string(scene.spheres.size() + scene.triangles.size()) +
                           " objects) asked both ways, one thread, release build."};
    for (const auto& [name, t] : {std::pair<const char*, const Tally&>{"blocked", blocked}, {"unblocked", seen}, {"all", all}}) {
        const double n = static_cast<double>(std::max<std::uint64_t>(1, t.feelers));
        lesson.row({name, percent(static_cast<double>(t.feelers) / static_cast<double>(std::max<std::uint64_t>(1, all.feelers))),
                    fixed(static_cast<double>(t.tests[0]) / n, 1), fixed(static_cast<double>(t.tests[1]) / n, 1),
                    fixed(1e9 * t.seconds[0] / n, 0), fixed(1e9 * t.seconds[1] / n, 0)});
    }
    return lesson;
}

void sweep(const Options& o)
{
    std::cerr << "measuring self-intersection at scales 1e-4 to 1e6, then the cost of the feelers...\n";
    TradeTable rehits{"04_shadow_feelers", "fraction of feelers re-hitting their own surface", {}};
    TradeTable missed{"04_shadow_feelers", "fraction of occluders 0.25 S above the surface missed", {}};
    TradeTable cost{"04_shadow_feelers", "rmse_linear_rgb_vs_any_hit_feelers", {}};
    std::vector<LessonTable> lesson;
    measure_offsets(o, rehits, missed, lesson);
    lesson.push_back(measure_feeler_cost(o, cost));
    lesson.push_back(feeler_tests_by_outcome(o));
    std::cerr << "drawing the scale families (990 scenes) in float and in double...\n";
    const std::vector<scale_families::Row> scales = scale_families::run_sweep();
    lesson.push_back(scale_families::scales_table(scales));
    const std::string missed_csv = csv_beside(o.sweep.csv, "_missed"), cost_csv = csv_beside(o.sweep.csv, "_cost");
    const std::string scales_csv = csv_beside(o.sweep.csv, "_scales");
    write_trade_csv(o.sweep.csv, rehits);
    write_trade_csv(missed_csv, missed);
    write_trade_csv(cost_csv, cost);
    std::ofstream scales_out(scales_csv);
    if (!scales_out)
        throw InputError("cannot write " + scales_csv);
    scale_families::write_rows_csv(scales_out, scales);
    write_lesson_tables(tables_beside(o.sweep.csv), lesson, std::cout);
    std::cout << "\nwrote " << o.sweep.csv << ", " << missed_csv << ", " << cost_csv << ", " << scales_csv << " and "
              << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("04_shadow_feelers", [&] {
        Options o;
        CommandLine cli = program_command_line(
            "04_shadow_feelers", "Shadow feelers: local shading, point lights, hard shadows, no acne.", o.common);
        cli.option("--offset", o.offset, "how feelers leave the surface: none, t-min, normal or robust");
        cli.option("--feelers", o.feelers, "the shadow query: any-hit, closest-hit or off (no shadows)");
        // Below 1e-7 the camera's squared lengths (1e-60 at S = 1e-30) underflow float; the kit's
        // tables measure 1e-4 to 1e6.
        cli.option("--scale", o.scale, "multiply every length of the scene and camera by this", 1e-7f, 1e7f);
        add_sweep_options(cli, o.sweep, "measure self-intersection by scale and offset, and what feelers cost",
                          "where --sweep writes its tables (*_missed.csv and *_cost.csv beside it)",
                          "renders per feeler-cost row; the table gives the median");
        cli.option("--probes", o.probes, "feelers per scale and offset in the sweep", 1000, 100000000);
        add_scene_option(cli, o.scene);
        cli.flag("--classic", o.classic, "with --scene: the classic NFF test rules (corner rays, depth 5, SPD counts)");
        cli.flag("--two-sided", o.two_sided, "with --classic: every polygon seen from both sides (SPD's teapot)");
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        const FeelerSettings feelers = feelers_named(o);
        check_scene_without_sweep(o.scene, o.sweep.on);
        classic::check_classic_options(o.classic, o.scene, o.common.spp, o.two_sided);
        if (o.classic && (cli.given("--offset") || cli.given("--feelers")))
            throw InputError("--classic sends NFF's feelers, any-hit from the robust offset: --offset and --feelers "
                             "do not apply");
        if (!o.scene.empty() && cli.given("--scale"))
            throw InputError("--scale scales the figure's scene; it does not apply to --scene");
        if (!o.scene.empty()) {
            const SceneRender file = load_scene_render(o.scene, o.common, cli);
            if (o.classic) {
                const classic::ClassicScene scene = classic::classic_scene(file.scene, o.two_sided);
                return write_figure(o.common, [&] { return classic::render_classic(file, scene); }, print_classic_stats);
            }
            note_unmodelled_materials(file.scene, "04_shadow_feelers");
            const LitScene scene = lit_scene(file.scene);
            return write_figure(o.common, [&] {
                return render(file.settings, [&](float x, float y, Rng&) {
                    return ch04::radiance(scene, file.eye_ray(primary_ray(file.camera, x, y)), feelers);
                });
            });
        }
        if (o.sweep.on) {
            check_writable(o.sweep.csv, "CSV");
            sweep(o);
            return 0;
        }
        return write_figure(o.common, [&] { return ch04::render_figure(render_settings(o.common), feelers, o.scale); });
    });
}
