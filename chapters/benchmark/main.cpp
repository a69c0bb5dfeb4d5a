// The benchmark: every structure of chapters 07-10 beside Embree, on the same rays of the same
// scenes, in one run. Brute force is the floor, Embree 3 (when this build found it) the production
// reference. Every structure's answers are checked against one reference before it is timed: the
// kit's structures must give the BVH's answers bit for bit (object and t), Embree the same object
// at a t within float tolerance (an exact tie of two objects, as at a shared edge, may go either
// way); a mismatch fails the run.
//
// Writes, into --out-dir: results.csv (closest hits), any_hit.csv (the same for any-hit queries),
// results.md (the tables), scaling.csv (the BVH's time per ray against N) and, with --classic,
// classic.csv (the classic SPD rules at 513 x 513 through the BVH and the 4-wide BVH).
#include "10_hierarchies/figure.hpp"
#include "benchmark/embree_accel.hpp"
#include "benchmark/rays.hpp"
#include "common/cli.hpp"
#include "common/output.hpp"
#include "common/parallel.hpp"
#include "common/trade.hpp"
#include "programs/measure.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace rt;
using namespace rt::bench;

namespace {

struct Options {
    int width = 256, height = 256;
    int repeat = 5;
    std::string scene;
    std::string out_dir = ".";
    bool tiny = false;
    bool classic = false;
    std::string only;  // comma-separated structure names; empty: all
};

bool wanted(const Options& o, const std::string& name)
{
    return o.only.empty() || ("," + o.only + ",").find("," + name + ",") != std::string::npos;
}

int all_threads() { return resolve_threads(0); }

// Rays per second to three significant digits: brute force on two million objects is 0.0000x.
std::string rate(double v)
{
    std::ostringstream s;
    s << std::setprecision(3) << v;
    return s.str();
}

// A structure of the benchmark (the kit's, from its registry, or Embree): its name, and how to
// build it for a scene with a number of threads
// (only Embree builds in parallel; the kit's builds are single-threaded).
struct Entrant {
    std::string name;
    std::function<std::unique_ptr<Accelerator>(const Objects&, int threads)> make;
    bool embree = false;
};

// The kit's structures' names, comma-separated, for --structures' help.
std::string kit_names()
{
    std::string names;
    for (const rt::Structure& s : ch10::structures())
        names += (names.empty() ? "" : ",") + s.name;
    return names;
}

std::vector<Entrant> structures()
{
    std::vector<Entrant> list;
    for (const rt::Structure& s : ch10::structures())  // the registry (programs/structures.hpp)
        list.push_back({s.name,
                        [s](const Objects& o, int) -> std::unique_ptr<Accelerator> {
                            if (std::unique_ptr<Accelerator> built = s.make(o))
                                return built;
                            return std::make_unique<BruteForce>();  // brute force builds nothing
                        },
                        false});
    if (have_embree()) {
        list.push_back({"embree-medium",
                        [](const Objects& o, int t) { return std::make_unique<EmbreeAccel>(o, EmbreeQuality::medium, t); },
                        true});
        list.push_back({"embree-high",
                        [](const Objects& o, int t) { return std::make_unique<EmbreeAccel>(o, EmbreeQuality::high, t); },
                        true});
    }
    return list;
}

// What one structure answered on each ray of a set.
struct Answers {
    std::vector<ObjectHit> closest;  // object -1: no hit
    std::vector<char> any;
};

// The rays of `set` with these indices, answered one by one (single thread), counted.
Answers answer(const Accelerator& accel, const RaySet& set, const Objects& objects, const std::vector<size_t>& which)
{
    Answers a;
    for (const size_t k : which) {
        ObjectHit h;
        if (!accel.closest(set.rays[k], set.ranges[k], objects, h))
            h = ObjectHit{};
        a.closest.push_back(h);
        a.any.push_back(accel.any(set.rays[k], set.ranges[k], objects));
    }
    return a;
}

// Why 1e-4 of t: Embree's triangle test (a different formula, rounded differently) and its sphere
// test agree with the kit's to a few float ulps on these scenes; 1e-4 leaves room for glancing
// rays, whose t is ill-conditioned, and is still far below any gap between two objects here.
bool same_t(float a, float b, float scale) { return std::abs(a - b) <= 1e-4f * std::max(std::abs(a), scale); }

struct Check {
    int rays = 0, wrong = 0, ties = 0;
    std::string first;
};

Check check(const Answers& got, const Answers& want, const std::vector<size_t>& which, const RaySet& set, bool exact,
            float scale)
{
    Check c;
    for (size_t i = 0; i < which.size(); ++i) {
        ++c.rays;
        const ObjectHit& g = got.closest[i];
        const ObjectHit& w = want.closest[which[i]];
        bool ok = g.object == w.object && (exact ? g.t == w.t : (g.object < 0 || same_t(g.t, w.t, scale)));
        if (!ok && !exact && g.object >= 0 && w.object >= 0 && same_t(g.t, w.t, scale)) {
            ++c.ties;  // two objects at one t: either is the nearest
            ok = true;
        }
        ok = ok && got.any[i] == want.any[which[i]];
        if (!ok && c.wrong++ == 0) {
            std::ostringstream s;
            s.precision(9);
            const Ray& r = set.rays[which[i]];
            s << set.name << " ray " << which[i] << " from (" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z
              << ") along (" << r.dir.x << ", " << r.dir.y << ", " << r.dir.z << "): object " << g.object << " at t "
              << g.t << " (any " << int(got.any[i]) << "), the reference object " << w.object << " at t " << w.t
              << " (any " << int(want.any[which[i]]) << ")";
            c.first = s.str();
        }
    }
    return c;
}

// Every `stride`-th ray: a sample spread over the whole image.
std::vector<size_t> strided(size_t count, size_t stride)
{
    std::vector<size_t> which;
    for (size_t k = 0; k < count; k += std::max<size_t>(1, stride))
        which.push_back(k);
    return which;
}

// Seconds for one pass over the rays `which`, with `threads` threads: closest or any.
double pass(const Accelerator& accel, const RaySet& set, const Objects& objects, const std::vector<size_t>& which,
            bool any_hit, int threads)
{
    const Timer timer;
    // Each ray's answer in its own byte (no shared counter between threads), so no pass is optimised away.
    std::vector<unsigned char> found(which.size());
    parallel_for(static_cast<long>(which.size()), threads, 256, [&](long i) {
        const size_t k = which[static_cast<size_t>(i)];
        ObjectHit h;
        found[static_cast<size_t>(i)] =
            any_hit ? accel.any(set.rays[k], set.ranges[k], objects) : accel.closest(set.rays[k], set.ranges[k], objects, h);
    }, [] {});
    const double seconds = timer.seconds();
    volatile long long keep = std::count(found.begin(), found.end(), 1);
    (void)keep;
    return seconds;
}

struct Row {
    std::string scene;
    int objects = 0;
    std::string rays, structure;
    int threads = 1;
    double mrays_closest = 0, mrays_any = 0, build_ms = 0;
    std::size_t bytes = 0;
    double tests_per_ray = 0, steps_per_ray = 0;  // steps: nodes or cells
    size_t timed_rays = 0, all_rays = 0;
    int checked_rays = 0, ties = 0;
};

struct Scene {
    NffScene nff;
    std::string name;
};

std::vector<Scene> scenes(const Options& o)
{
    if (!o.scene.empty())
        return {{read_nff(o.scene), std::filesystem::path(o.scene).filename().string()}};
    if (o.tiny)
        return {{generated_scene(write_sphereflake, 1, "sphereflake 1"), "sphereflake 1"}};
    std::cerr << "generating the six scenes (the mountain of 2 million triangles takes a while)...\n";
    return {
        {generated_scene(write_sphereflake, 3, "sphereflake 3"), "sphereflake 3"},
        {generated_scene(write_tree, 6, "tree 6"), "tree 6"},
        {generated_scene(write_pyramid, 6, "pyramid 6"), "pyramid 6"},
        {ch10::figure_scene(), "teapot in a stadium 5"},
        {generated_scene(write_mountain, 7, "mountain 7"), "mountain 7"},
        {generated_scene(write_mountain, 10, "mountain 10"), "mountain 10 (dense mesh)"},
    };
}

// Why these budgets: a timing of about a tenth of a second (a pass over the rays, repeated when it
// is shorter) is well above the timer's resolution and these machines' scheduling noise, and keeps
// the whole run to minutes; brute force and the slowest structures on the largest scenes are timed
// on an evenly spread sample of the rays instead (the table says how many).
constexpr double pass_budget_seconds = 0.1;
constexpr double brute_tests_budget = 3e7;

// The median of up to `repeat` builds (one when a build takes over a second), in `build_ms`.
std::unique_ptr<Accelerator> build_timed(const Entrant& s, const Objects& objects, int threads, int repeat,
                                         double& build_ms)
{
    std::unique_ptr<Accelerator> accel;
    std::vector<double> builds;
    for (int r = 0; r < repeat; ++r) {
        const Timer timer;
        accel = s.make(objects, threads);
        builds.push_back(timer.seconds());
        if (builds.back() > 1.0)
            break;
    }
    build_ms = 1e3 * median(builds);
    return accel;
}

// One structure on one set of rays: checked against the reference's answers on every ray it is
// timed on (single-threaded, counted), then timed, closest and any, on `threads` threads.
Row time_rays(const Entrant& s, const Accelerator& accel, const RaySet& set, const Answers& want,
              const Objects& objects, float scale, int threads, const Options& o, const std::string& scene)
{
    std::vector<size_t> which = strided(set.rays.size(), 1);
    if (s.name == "brute")
        which = strided(set.rays.size(), static_cast<size_t>(std::ceil(static_cast<double>(set.rays.size()) *
                                                                        objects.size() / brute_tests_budget)));
    reset_counters();
    const Timer check_timer;
    const Answers got = answer(accel, set, objects, which);
    const double check_seconds = check_timer.seconds();
    const Counts counts = total_counts();
    const Check c = check(got, want, which, set, !s.embree, scale);
    if (c.wrong > 0)
        throw std::runtime_error(s.name + " on " + scene + ": " + std::to_string(c.wrong) + " of " +
                                 std::to_string(c.rays) + " rays differ from the reference; the first: " + c.first);
    // Timed on a sample when the full set would take too long.
    const double per_ray = check_seconds / (2.0 * static_cast<double>(which.size()));
    const double wanted = pass_budget_seconds / std::max(per_ray, 1e-12);
    if (static_cast<double>(which.size()) > 4.0 * wanted)
        which = strided(set.rays.size(), static_cast<size_t>(static_cast<double>(set.rays.size()) / wanted));
    // A pass shorter than the budget is repeated within one timing, as many times as the untimed
    // warm-up pass says fit in the budget: the warm-up's own time, thread starts included, so that a
    // scene of one object (nanoseconds a ray) is not repeated a million times to measure the
    // scheduler. (Not in --tiny, a check: one pass.)
    const auto timed = [&](bool any_hit) {
        const double warm_up = pass(accel, set, objects, which, any_hit, threads);
        const int loops = o.tiny ? 1
                                 : static_cast<int>(
                                       std::clamp(std::ceil(pass_budget_seconds / std::max(warm_up, 1e-6)), 1.0, 1e4));
        double seconds = 0.0;
        for (int l = 0; l < loops; ++l)
            seconds += pass(accel, set, objects, which, any_hit, threads);
        return seconds / loops;
    };
    std::vector<double> closest_s, any_s;
    for (int run = 0; run < o.repeat; ++run) {
        closest_s.push_back(timed(false));
        any_s.push_back(timed(true));
    }
    Row row;
    row.scene = scene;
    row.objects = objects.size();
    row.rays = set.name;
    row.structure = s.name;
    row.threads = threads;
    row.mrays_closest = static_cast<double>(which.size()) / median(closest_s) / 1e6;
    row.mrays_any = static_cast<double>(which.size()) / median(any_s) / 1e6;
    row.bytes = accel.bytes();
    const double n = 2.0 * static_cast<double>(c.rays);  // closest and any, per ray
    row.tests_per_ray = static_cast<double>(counted(counts, Counter::intersection_tests)) / n;
    row.steps_per_ray =
        static_cast<double>(counted(counts, Counter::nodes_visited) + counted(counts, Counter::cells_visited)) / n;
    row.timed_rays = which.size();
    row.all_rays = set.rays.size();
    row.checked_rays = c.rays;
    row.ties = c.ties;
    return row;
}

void bench_scene(const Scene& sc, const Options& o, std::vector<Row>& rows, std::ostream& log)
{
    RenderSettings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.show_progress = false;
    const SceneRender file = scene_render(sc.nff, settings);
    LitScene scene = lit_scene(file.scene);
    const Objects objects = objects_of(scene, lit_tests);
    const float scale = 1e-3f * glm::length(bounds_of_all(objects).extent());

    // The reference: the kit's BVH, proven equal to brute force by chapter 10's tests (and checked
    // against brute force again here, on its sample).
    const BvhAccel reference(objects);
    scene.accelerator = &reference;
    const RaySet primary = primary_rays(file);
    const std::vector<RaySet> sets = {primary, incoherent_rays(scene, primary, 7)};
    std::vector<Answers> want;
    for (const RaySet& set : sets)
        want.push_back(answer(reference, set, objects, strided(set.rays.size(), 1)));
    log << "\n" << sc.name << ": " << objects.size() << " objects, " << sets[0].rays.size() << " primary and "
        << sets[1].rays.size() << " incoherent rays\n";

    for (const Entrant& s : structures()) {
        if (!wanted(o, s.name))
            continue;
        std::unique_ptr<Accelerator> accel;
        double build_ms = 0.0;
        for (const int threads : {1, all_threads()}) {
            if (threads > 1 && all_threads() == 1)
                break;
            // The kit builds on one thread, so its structure serves both thread counts; Embree
            // builds again on the threads it is given.
            if (!accel || s.embree) {
                try {
                    accel = build_timed(s, objects, threads, o.repeat, build_ms);
                } catch (const InputError& e) {
                    log << "  " << s.name << ": not built: " << e.what() << '\n';
                    break;
                }
            }
            for (size_t r = 0; r < sets.size(); ++r) {
                if (sets[r].rays.empty())
                    continue;
                Row row = time_rays(s, *accel, sets[r], want[r], objects, scale, threads, o, sc.name);
                row.build_ms = build_ms;
                rows.push_back(row);
                log << "  " << std::left << std::setw(14) << s.name << std::right << " " << threads << " thread"
                    << (threads > 1 ? "s " : "  ") << std::setw(10) << sets[r].name << std::setw(9)
                    << rate(row.mrays_closest) << " Mrays/s closest, " << std::setw(9) << rate(row.mrays_any)
                    << " any; " << row.checked_rays << " rays checked"
                    << (row.ties ? ", " + std::to_string(row.ties) + " ties" : "") << '\n';
            }
        }
    }
}

const Row* find_row(const std::vector<Row>& rows, const Row& like, const std::string& structure)
{
    for (const Row& r : rows)
        if (r.scene == like.scene && r.rays == like.rays && r.threads == like.threads && r.structure == structure)
            return &r;
    return nullptr;
}

void write_csv(const std::string& path, const std::vector<Row>& rows, bool any_hit)
{
    std::ofstream csv(path);
    csv << "scene,objects,rays,structure,threads,mrays_per_s,build_ms,bytes,ratio_to_embree\n";
    for (const Row& r : rows) {
        const Row* embree = find_row(rows, r, "embree-high");
        const double mrays = any_hit ? r.mrays_any : r.mrays_closest;
        csv << '"' << r.scene << "\"," << r.objects << ',' << r.rays << ',' << r.structure << ',' << r.threads << ','
            << mrays << ',' << r.build_ms << ',' << r.bytes << ',';
        if (embree)
            csv << mrays / (any_hit ? embree->mrays_any : embree->mrays_closest);
        csv << '\n';
    }
}

std::string fixed(double v, int digits)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}


void write_tables(std::ostream& md, const std::vector<Row>& rows, const Options& o)
{
    md << "All rays " << o.width << "x" << o.height << " per set; Mrays/s the median of " << o.repeat
       << " passes; tests and nodes or cells per ray counted on the checking pass (closest and any); "
       << "x Embree: closest-hit rays per second over Embree high's on the same rays and threads. "
       << "A structure timed on a sample of the rays says how many.\n";
    std::string scene;
    for (const Row& r : rows) {
        if (r.scene != scene) {
            scene = r.scene;
            md << "\n**" << r.scene << "** (" << r.objects << " objects)\n\n"
               << "| rays | structure | threads | Mrays/s closest | Mrays/s any | x Embree | build ms | MB | tests/ray | "
                  "nodes or cells/ray |\n|---|---|---|---|---|---|---|---|---|---|\n";
        }
        const Row* embree = find_row(rows, r, "embree-high");
        md << "| " << r.rays << (r.timed_rays < r.all_rays ? " (" + std::to_string(r.timed_rays) + " sampled)" : "")
           << " | " << r.structure << " | " << r.threads << " | " << rate(r.mrays_closest) << " | "
           << rate(r.mrays_any) << " | " << (embree ? rate(r.mrays_closest / embree->mrays_closest) : "-")
           << " | " << fixed(r.build_ms, 1) << " | " << fixed(static_cast<double>(r.bytes) / 1e6, 2) << " | "
           << (r.structure.rfind("embree", 0) == 0 ? "-" : fixed(r.tests_per_ray, 1)) << " | "
           << (r.structure.rfind("embree", 0) == 0 || r.structure == "brute" ? "-" : fixed(r.steps_per_ray, 1)) << " |\n";
    }
}

// The BVH's time per primary ray against N: mountains of 2 x 4^d triangles.
void scaling(const Options& o, std::ostream& md)
{
    std::ofstream csv(o.out_dir + "/scaling.csv");
    csv << "objects,build_ms,ns_per_ray,nodes_per_ray,tests_per_ray\n";
    md << "\n**The BVH against N** (mountains of 2 x 4^d triangles, primary rays, 1 thread)\n\n"
       << "| objects | build ms | ns/ray | nodes/ray | tests/ray |\n|---|---|---|---|---|\n";
    for (int depth = 3; depth <= (o.tiny ? 3 : 10); ++depth) {
        const NffScene nff = generated_scene(write_mountain, depth, "mountain");
        RenderSettings settings;
        settings.width = o.width;
        settings.height = o.height;
        const SceneRender file = scene_render(nff, settings);
        const LitScene scene = lit_scene(file.scene);
        const Objects objects = objects_of(scene, lit_tests);
        const Timer build;
        const BvhAccel bvh(objects);
        const double build_ms = 1e3 * build.seconds();
        const RaySet rays = primary_rays(file);
        const std::vector<size_t> all = strided(rays.rays.size(), 1);
        reset_counters();
        answer(bvh, rays, objects, all);
        const Counts counts = total_counts();
        std::vector<double> times;
        for (int run = 0; run < o.repeat; ++run)
            times.push_back(pass(bvh, rays, objects, all, false, 1));
        const double ns = 1e9 * median(times) / static_cast<double>(all.size());
        const double n = 2.0 * static_cast<double>(all.size());
        const double nodes = static_cast<double>(counted(counts, Counter::nodes_visited)) / n;
        const double tests = static_cast<double>(counted(counts, Counter::intersection_tests)) / n;
        csv << objects.size() << ',' << build_ms << ',' << ns << ',' << nodes << ',' << tests << '\n';
        md << "| " << objects.size() << " | " << fixed(build_ms, 1) << " | " << fixed(ns, 0) << " | " << fixed(nodes, 1)
           << " | " << fixed(tests, 1) << " |\n";
    }
}

// The classic SPD rules (chapter 04's --classic) at 513 x 513 through the BVH and the 4-wide BVH:
// seconds per frame, build included.
template <class Tree>
double classic_seconds(SceneRender& file)
{
    const Timer timer;
    classic::ClassicScene scene = classic::classic_scene(file.scene);
    const Objects objects = objects_of(scene.lit, lit_tests);
    const Tree tree(objects);
    scene.lit.accelerator = &tree;
    const Image image = classic::render_classic(file, scene);
    return timer.seconds();
}

void classic_frames(const Options& o, const std::vector<Scene>& list, std::ostream& md)
{
    std::ofstream csv(o.out_dir + "/classic.csv");
    csv << "scene,objects,structure,threads,seconds\n";
    md << "\n**The classic SPD rules** at 513x513 (build included; median of " << o.repeat
       << ")\n\n| scene | objects | bvh, 1 thread | bvh4, 1 thread | bvh4, " << all_threads()
       << " threads |\n|---|---|---|---|---|\n";
    for (const Scene& sc : list) {
        RenderSettings settings;
        settings.width = o.tiny ? 33 : 513;
        settings.height = o.tiny ? 33 : 513;
        settings.show_progress = false;
        SceneRender file = scene_render(sc.nff, settings);
        const int count = objects_of(classic::classic_scene(file.scene).lit, lit_tests).size();
        std::vector<double> seconds[3];
        for (int run = 0; run < o.repeat; ++run) {
            file.settings.threads = 1;
            seconds[0].push_back(classic_seconds<BvhAccel>(file));
            seconds[1].push_back(classic_seconds<WideBvhAccel>(file));
            file.settings.threads = all_threads();
            seconds[2].push_back(classic_seconds<WideBvhAccel>(file));
        }
        csv << '"' << sc.name << "\"," << count << ",bvh,1," << median(seconds[0]) << '\n'
            << '"' << sc.name << "\"," << count << ",bvh4,1," << median(seconds[1]) << '\n'
            << '"' << sc.name << "\"," << count << ",bvh4," << all_threads() << ',' << median(seconds[2]) << '\n';
        md << "| " << sc.name << " | " << count << " | " << fixed(median(seconds[0]), 3) << " | "
           << fixed(median(seconds[1]), 3) << " | " << fixed(median(seconds[2]), 3) << " |\n";
        std::cerr << "classic " << sc.name << ": " << fixed(median(seconds[0]), 3) << " s (bvh), "
                  << fixed(median(seconds[1]), 3) << " s (bvh4) on 1 thread\n";
    }
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("benchmark", [&] {
        Options o;
        CommandLine cli("benchmark", "Every structure of chapters 07-10 beside Embree, on the same rays, checked and timed.");
        cli.option("--width", o.width, "primary rays across (the scene's view)", 1, 4096);
        cli.option("--height", o.height, "primary rays down", 1, 4096);
        cli.option("--repeat", o.repeat, "timed passes per measurement; the tables give the median", 1, 100);
        cli.option("--scene", o.scene, "benchmark this NFF file instead of the six generated scenes");
        cli.option("--out-dir", o.out_dir, "where results.csv and the other tables go");
        cli.flag("--tiny", o.tiny, "one small scene, 16x16 rays, one pass: a check that runs in seconds (CI)");
        cli.option("--structures", o.only, "only these, comma-separated (" + kit_names() + ","
                   "embree-medium,embree-high); default all");
        cli.flag("--classic", o.classic, "also time the classic SPD rules at 513x513 through the BVH and the 4-wide BVH");
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        for (std::string rest = o.only; !rest.empty();) {
            const size_t comma = rest.find(',');
            const std::string name = rest.substr(0, comma);
            bool known = false;
            for (const Entrant& s : structures())
                known = known || s.name == name;
            if (!known && !(name.rfind("embree", 0) == 0 && !have_embree()))
                throw InputError("--structures: unknown structure '" + name + "'");
            rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
        }
        if (o.tiny) {
            o.width = o.height = 16;
            o.repeat = 1;
        }
        std::filesystem::create_directories(o.out_dir);
        check_writable(o.out_dir + "/results.csv", "CSV");
        std::cerr << (have_embree() ? "Embree 3 found: embree-medium and embree-high are measured\n"
                                    : "Embree not found (install libembree-dev and configure again): skipped; the "
                                      "kit's structures only, no ratio to Embree\n");
        std::vector<Row> rows;
        const std::vector<Scene> list = scenes(o);
        for (const Scene& sc : list)
            bench_scene(sc, o, rows, std::cerr);
        write_csv(o.out_dir + "/results.csv", rows, false);
        write_csv(o.out_dir + "/any_hit.csv", rows, true);
        std::ofstream md(o.out_dir + "/results.md");
        write_tables(md, rows, o);
        if (o.scene.empty())
            scaling(o, md);
        if (o.classic)
            classic_frames(o, list, md);
        md.close();
        std::ifstream back(o.out_dir + "/results.md");
        std::cout << back.rdbuf() << "\nwrote " << o.out_dir << "/results.csv, any_hit.csv and results.md\n";
        return 0;
    });
}
