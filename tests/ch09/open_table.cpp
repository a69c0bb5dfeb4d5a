// EXERCISE 09.6 (open): the hash and the table size. The gate first: your hash keeps to its budget,
// the table it files finds every occupied cell and no other (two tables built one after the other,
// every lookup checked), and the hashed grid through it answers every ray as brute force does, on
// the scenes 09.A uses. Then its cost: keys compared per lookup on the cells seeded rays walk through
// on three generated scenes of regular structure, against the reference's, in three tiers (one case
// each, so the points add up by tier).
#include "09_hashed_voxels/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/grader/open_tiers.hpp"

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;
using rt::grader::open_exercise::fixed;

namespace {

std::string cell_words(const GridShape& shape, std::int32_t p)
{
    const cell3 s = shape.strides();
    return "cell " + std::to_string(p) + " (i " + std::to_string(p / s.x) + ", j " +
           std::to_string(p / s.y % shape.n.y) + ", l " + std::to_string(p % shape.n.z) + ")";
}

// Whether the grid's open table keeps the contract, in words: empty when it does; else the first
// thing wrong. Its hash within the budget; every address of the grid given a bucket inside the table;
// every occupied cell (its bit on) found, with its own key, and as many cells filed as occupied;
// every empty cell not found. The lookups are counted (find_open), so a caller resets the counters.
std::string first_wrong_lookup(const HashedGrid& grid, const char* which)
{
    const TableHash& h = grid.hash();
    const OpenHashBuild& b = grid.open_build();
    const std::string table = std::string(which) + " (" + std::to_string(grid.stats().occupied) + " occupied cells";
    if (b.over_budget)
        return table + "): your choose_table_hash gave M = " + std::to_string(h.M) + ", outside 1 to " +
               std::to_string(max_table_buckets(static_cast<std::size_t>(grid.stats().occupied))) +
               " (max_table_buckets: one bucket per occupied cell at most)";
    const std::string with = table + ", M = " + std::to_string(h.M) + "): ";
    if (b.lost)
        return with + "while the table was filed, your bucket_of gave " + cell_words(grid.shape(), b.lost_p) +
               " bucket " + std::to_string(b.lost_bucket) +
               (b.lost_bucket >= h.M ? ", past the table's last bucket (M - 1)"
                                     : ", the second time asked, another bucket than the first (a hash that keeps "
                                       "something outside TableHash)");
    const long long cells = grid.stats().cells;
    for (long long q = 0; q < cells; ++q) {
        const auto p = static_cast<std::int32_t>(q);
        const std::uint32_t bucket = bucket_of(h, p);
        if (bucket >= h.M)
            return with + "bucket_of gives " + cell_words(grid.shape(), p) + " bucket " + std::to_string(bucket) +
                   ", past the table's last bucket (M - 1)";
        const bool on = (grid.bits().words[q >> 6] >> (q & 63)) & 1u;
        const HashedCell* found = grid.find_open(p);
        if (on && (!found || found->p != p))
            return with + "looking up " + cell_words(grid.shape(), p) + ", which holds objects, finds " +
                   (found ? "the cell of key " + std::to_string(found->p) : std::string("nothing")) +
                   " in its bucket " + std::to_string(bucket) + " (filed there when the table was built: your "
                   "bucket_of answers otherwise now, after another table was built?)";
        if (!on && found)
            return with + "looking up the empty " + cell_words(grid.shape(), p) + " finds the cell of key " +
                   std::to_string(found->p);
    }
    return "";
}

const Build through_hash{"the hashed grid through your hash (09.6)",
                         [](const Objects& objects, float lambda) {
                             return std::make_unique<HashedGrid>(objects, 100.0f * lambda, OpenHashing{});
                         },
                         [](const Accelerator& built, const Ray&, Interval, const Objects&) {
                             const std::string wrong =
                                 first_wrong_lookup(dynamic_cast<const HashedGrid&>(built), "\n  this scene's table");
                             return wrong.empty() ? "\n  every lookup of this scene's table answered right" : wrong;
                         }};

// One sphere: at lambda 1 its grid is one cell, occupied, so the budget is one bucket.
void write_one_sphere(std::ostream& out, int)
{
    out << "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0.01\nresolution 8 8\nb 0 0 0\nl 2 2 5\n"
           "f 1 1 1 1 0 0 0 0\ns 0 0 0 1\n";
}

// The contract's lookups, called directly: two tables built one after the other (a lattice and
// gears), then every cell of each looked up, the first table's after the second was built (a hash
// that keeps its numbers anywhere but TableHash answers for the second table in the first); and a
// table of one occupied cell, whose budget is M = 1.
bool check_lookups()
{
    const auto build = [](void (*write)(std::ostream&, int), int depth, const char* name, float lambda) {
        const NffScene nff = generated_scene(write, depth, name);
        const LitScene scene = lit_scene(nff);
        const Objects objects = objects_of(scene, lit_tests);
        return std::make_unique<HashedGrid>(objects, lambda, OpenHashing{});
    };
    const std::unique_ptr<HashedGrid> first = build(write_lattice, 4, "lattice 4", 64.0f);
    const std::unique_ptr<HashedGrid> second = build(write_gears, 1, "gears 1", 16.0f);
    const std::unique_ptr<HashedGrid> one = build(write_one_sphere, 0, "one sphere", 1.0f);
    for (const auto& [grid, which] : {std::pair{first.get(), "the first table, lattice 4 at lambda 64"},
                                      std::pair{second.get(), "the second table, gears 1 at lambda 16"},
                                      std::pair{one.get(), "a table of one sphere at lambda 1 (one cell)"}}) {
        const std::string wrong = first_wrong_lookup(*grid, which);
        INFO(wrong << "\n(each occupied cell found with its own key, each empty one not found; the first table "
                      "looked up after the second was built)");
        CHECK(wrong.empty());
        if (!wrong.empty())
            return false;
    }
    return true;
}

// The gate: the lookups above, then 09.A's scenes and rays, ties, a huge floor, far away. Whether
// the hash passed it.
bool check_gate()
{
    INFO("the gate of 09.6: a hash past its budget, a table that loses or invents a cell, or a grid that answers "
         "a ray differently from brute force scores 0 in every 09.6 case");
    return check_lookups() && open_exercise::agrees_with_brute_force(through_hash, 300,
                                                                     {{write_stadium, 2, "stadium 2", 300},
                                                                      {write_mountain, 4, "mountain 4", 300}});
}

// The scenes 09.6's cost is measured on (the contract's "three of the kit's generated scenes"):
// regular ones, whose occupied cells lie in layers, rows and repeated shapes, with the reference's
// keys compared per lookup on each (grader.ch09.open_reference_costs... holds these to the
// solution's).
struct CostScene {
    const char* name;
    void (*write)(std::ostream&, int);
    int depth;
    float lambda;
    double reference;  // the reference hash's keys compared per lookup
};
const CostScene cost_scenes[] = {
    {"lattice 6 at lambda 256", write_lattice, 6, 256.0f, 1.249823},
    {"gears 1 at lambda 64", write_gears, 1, 64.0f, 1.099000},
    {"pyramid 5 at lambda 64", write_pyramid, 5, 64.0f, 1.079909},
};
constexpr int cost_rays = 4096;  // seeded rays per scene (seeded_ray), closest hits

// Keys compared per lookup through the hashed grid filed by `hashing` over a scene, on cost_rays
// seeded rays: table_probes over table_lookups.
double keys_per_lookup(const CostScene& c, OpenHashing hashing)
{
    const open_exercise::Counted n = open_exercise::count_closest(
        generated_scene(c.write, c.depth, c.name), cost_rays,
        [&](const Objects& objects) { return std::make_unique<HashedGrid>(objects, c.lambda, hashing); });
    return n.per_ray(Counter::table_probes) / n.per_ray(Counter::table_lookups);
}

double your_keys_per_lookup(const CostScene& c) { return keys_per_lookup(c, OpenHashing{}); }

// The lesson's other rows: p mod M with M chosen three ways, the largest prime within the budget
// (the chapter's rule), the largest power of two within it, and the budget itself; a
// multiplicative hash at the budget; and the chapter's default, which the budget does not allow.
std::uint32_t p_mod_M(const TableHash& h, std::int32_t p) { return static_cast<std::uint32_t>(p) % h.M; }

// Knuth's multiplicative hash: p times 2^32 over the golden ratio, its high bits scaled to M.
std::uint32_t golden(const TableHash& h, std::int32_t p)
{
    const std::uint32_t mixed = static_cast<std::uint32_t>(p) * 2654435761u;
    return static_cast<std::uint32_t>((static_cast<std::uint64_t>(mixed) * h.M) >> 32);
}

TableHash largest_prime(const std::vector<std::int32_t>& cells, cell3)
{
    TableHash h;
    for (h.M = max_table_buckets(cells.size()); h.M > 2; --h.M) {
        bool prime = true;
        for (std::uint32_t d = 2; d * d <= h.M && prime; ++d)
            prime = h.M % d != 0;
        if (prime)
            break;
    }
    return h;
}

TableHash largest_power_of_two(const std::vector<std::int32_t>& cells, cell3)
{
    TableHash h;
    for (h.M = 1; 2ull * h.M <= max_table_buckets(cells.size());)
        h.M *= 2;
    return h;
}

TableHash the_budget(const std::vector<std::int32_t>& cells, cell3)
{
    TableHash h;
    h.M = max_table_buckets(cells.size());
    return h;
}

// The chapter's default (HashedGrid's table_size 0): the least prime at least twice the occupied
// cells, a load of 0.5, past 09.6's budget (measured through a budget that allows it).
std::uint32_t twice_the_cells(std::size_t occupied)
{
    return prime_at_least(2 * static_cast<std::uint64_t>(std::max<std::size_t>(1, occupied)));
}

TableHash chapter_default(const std::vector<std::int32_t>& cells, cell3)
{
    TableHash h;
    h.M = twice_the_cells(cells.size());
    return h;
}

}  // namespace

OPEN_EXERCISE_TIERS("choose_table_hash, bucket_of (open): a correct hash", " keys", "09.6", 4, check_gate, cost_scenes,
                    your_keys_per_lookup, "keys per lookup", "your hash's cost (keys compared per lookup)")

// The kit's own check (not graded; grader.ch09.open_reference_costs_are_the_solutions runs it on
// the solutions): the reference costs above are what the reference hash measures now, and the
// lesson's other figures on the same rays.
TEST_CASE("09.6's stored reference costs are the reference hash's", "[.][open_reference_costs]")
{
    for (const CostScene& c : cost_scenes) {
        const double reference = your_keys_per_lookup(c);
        std::string others;
        const std::pair<const char*, OpenHashing> rows[] = {
            {"p mod the largest prime", {largest_prime, p_mod_M}},
            {"p mod the largest power of two", {largest_power_of_two, p_mod_M}},
            {"p mod M at the budget", {the_budget, p_mod_M}},
            {"Knuth's multiplicative hash at the budget", {the_budget, golden}},
            {"the chapter's default (twice the budget's buckets)", {chapter_default, p_mod_M, twice_the_cells}}};
        for (const auto& [name, hashing] : rows) {
            const double keys = keys_per_lookup(c, hashing);
            others += std::string(", ") + name + " " + fixed(keys, 4) + " (" + fixed(keys / reference, 3) + "x)";
        }
        WARN(c.name << ": reference " << fixed(reference, 6) << others);
        CHECK(fixed(reference, 6) == fixed(c.reference, 6));
    }
}
