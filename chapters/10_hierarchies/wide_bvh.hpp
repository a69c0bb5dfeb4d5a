// The next step after 10.4 (given): the same tree, four children to a node, their four boxes tested
// at once, as Embree's trees are (Wald et al., "Embree", 2014; Dammertz et al., "Shallow Bounding
// Volume Hierarchies", 2008). Why: a binary tree spends most of a query stepping from node to node,
// one box at a time, and four boxes in arrays of four, plane by plane, cost one pass of the slab
// test (one SSE instruction each on x86). Step 5 of the lesson's "Where a query's time goes"; the
// measurements are in chapters/benchmark/README.md, "Chapter 10's steps".
//
// The tree is your BVH (10.1-10.3), collapsed: each wide node takes a binary node's two children,
// and opens the largest of them that is not a leaf (by surface area, the child a ray is likeliest
// to enter) until it has four. It tests boxes the binary traversal would not (the children of a
// box the ray misses, when that box was opened), and that costs nothing in exactness: the answers
// are brute force's, bit for bit, as 10.4's are, because every box is tested with the robust slab
// test (common/bounds.hpp) against the range that could still beat the best hit, so the boxes
// around the nearest object are always entered, and every object is asked with closer_than.
//
// Its leaves are the binary tree's; a leaf of triangles only is copied into blocks of four
// (four_triangles.hpp) at the build, its node pointing at them, and a query that asks for the
// watertight test (chapter 04 on) tests each block with your 10.6, four triangles in one pass, then
// asks each lane hit what the one-by-one loop asks an object ("Four triangles at once" in the
// lesson).
#pragma once

#include "10_hierarchies/bvh.hpp"
#include "10_hierarchies/four_triangles.hpp"
#include "10_hierarchies/lane_bounds.hpp"
#include "10_hierarchies/lanes.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(_MSC_VER) && !defined(__clang__)
#include <intrin.h>
#endif

namespace rt {

// A node of four children, 128 bytes (two cache lines): each child's box, plane by plane, four to
// an array; and what the child is: a leaf of count > 0 objects, another wide node (count == 0:
// nodes[first]), or nothing (its bit clear in `occupied`, its box empty: min +infinity, max
// -infinity). A leaf of triangles only (its bit set in `in_blocks`) is blocks[first ..], its
// triangles four to a block; any other leaf is object_index[first .. first + count) of the binary
// tree. The mask, not the empty box, keeps a ray out of an empty slot: where a program flushes
// tiny floats to 0 (-ffast-math), a direction of huge components has 1 / d = 0, every slab NaN,
// and every box entered.
struct alignas(64) WideNode {
    float min[3][4];
    float max[3][4];
    std::uint32_t first[4];
    std::uint16_t count[4];   // as BvhNode::count: at most 65535 objects a leaf
    std::uint32_t occupied;   // bit i: child i exists
    std::uint32_t in_blocks;  // bit i: child i is a leaf of triangles, first[i] its first block
};
static_assert(sizeof(WideNode) == 128, "a wide node is two cache lines");

// Whether lane i is in a mask of four lanes: child i of a node's `occupied` or `in_blocks`, of the
// boxes a ray enters, or lane i of the triangles a block's test hit.
inline bool lane_in(unsigned mask, int i) { return (mask >> i & 1u) != 0; }

// The lane of a mask with exactly one lane in it (1, 2, 4 or 8): its count of trailing zeros, one
// instruction where the compiler has one. Why not a table of nine: the lane is what the walk waits
// for between a node's boxes and its child's address, and a table is a load on that path (4-5
// cycles where the instruction takes 1-3). Measured in chapters/benchmark/README.md, "Chapter
// 10's steps", step 18.
inline int only_lane(unsigned mask)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctz(mask);
#elif defined(_MSC_VER)
    unsigned long lane;
    _BitScanForward(&lane, mask);
    return static_cast<int>(lane);
#else
    return mask == 1u ? 0 : mask == 2u ? 1 : mask == 4u ? 2 : 3;
#endif
}

struct WideBvh {
    std::vector<WideNode> nodes;  // nodes[0] is the root
    std::vector<std::uint32_t> object_index;  // the binary tree's: where a leaf of other kinds reads its objects
    // The triangles of each leaf of triangles only, four to a block, a leaf's blocks one after
    // another: the leaf's node points straight at its first (no table between, which a large scene
    // paid a cache miss for on every leaf).
    std::vector<FourTriangles> blocks;
};

// Why 3 a level: a visit pops one entry and pushes at most four, and a wide level spans at least
// one binary level, of which a path has fewer than bvh_stack_size (bvh.hpp's depth limit).
constexpr int wide_stack_size = 3 * bvh_stack_size + 1;

// Asks the processor to start loading `bytes` from p into its cache, and goes on: the wide tree
// asks it for each child it pushes (its node, or its leaf's first block), which then arrives while
// the nearer children are walked. Why: on a tree larger than the cache a visit waits on memory
// (step 7; measured in chapters/benchmark/README.md, "Chapter 10's steps"). Where the lanes are
// plain C++ (not x86), nothing is asked.
inline void prefetch(const void* p, std::size_t bytes)
{
#if RT_WIDE_SSE
    // Every 64-byte line the bytes touch: a line from each 64 bytes on, and the last byte's.
    const char* first = static_cast<const char*>(p);
    for (std::size_t at = 0; at < bytes; at += 64)
        _mm_prefetch(first + at, _MM_HINT_T0);
    _mm_prefetch(first + bytes - 1, _MM_HINT_T0);
#else
    (void)p;
    (void)bytes;
#endif
}

// The slab test of common/bounds.hpp on the node's four boxes at once: the same formula, the
// same order of operations, so each box is entered exactly when slab_interval would enter it.
// Returns the mask of the boxes entered (bit i: child i), with each one's entry t in t0_out[i].
// greater_or_second and less_or_second keep t0 and t1, as the scalar test's
// `t_near > t0 ? t_near : t0` does, when a slab is NaN (an origin on a face, d_i = 0).
inline unsigned enter_boxes(const WideNode& node, const RaySlabs& slabs, Interval reach, float t0_out[4])
{
    Float4 t0 = reach.min, t1 = reach.max;
    for (int a = 0; a < 3; ++a) {
        const Float4 near_plane = Float4::load(slabs.down[a] ? node.max[a] : node.min[a]);
        const Float4 far_plane = Float4::load(slabs.down[a] ? node.min[a] : node.max[a]);
        const Float4 o = slabs.origin[a], inv = slabs.inv_dir[a];
        const Float4 t_near = (near_plane - o) * inv;
        const Float4 t_far = (far_plane - o) * inv * Float4(slab_far_widening);
        t0 = greater_or_second(t_near, t0);
        t1 = less_or_second(t_far, t1);
    }
    t0.store(t0_out);
    // Entered unless t0 > t1, as slab_interval says it: t0 <= t1, as neither is NaN (each starts at
    // an end of the reach and keeps it against a NaN slab; a NaN range, which nothing can hit in,
    // enters no box). One compare, where ~(t0 > t1) took two more steps between the boxes and the
    // next node (step 18).
    return bits(t0 <= t1);
}

// Which answer a query wants: the nearest hit (a camera ray's), or whether anything is hit at all
// (a shadow feeler's: the first hit found ends it).
enum class QueryKind { closest, any };

// Where a query stands after a step of its walk: going on, or answered (only an any-hit query's
// first hit answers it before the walk ends).
enum class Walk { go_on, answered };

// One query's walk down the wide tree: the state it carries (the ray, the reach that could still
// beat the best hit, the best so far, the stack of children to visit) and its three steps, a node
// (open: the child to go into next), a leaf asked one by one (leaf) and a block of four triangles
// (block), each of these two saying where the query stands (Walk).
template <QueryKind kind>
class WideQuery {
public:
    WideQuery(const WideBvh& tree, const Ray& ray, Interval range, const Objects& objects)
        : tree_(tree), ray_(ray), range_(range), objects_(objects), slabs_(ray), reach_(range),
          bounded_(objects.tests.triangle == TriangleTest::watertight_bounded),
          // Four triangles at once where the query asks for the watertight test (chapter 04 on); the
          // other tests go one by one through the object list.
          four_wide_(bounded_ || objects.tests.triangle == TriangleTest::watertight),
          frame_(four_wide_ ? ray_frame(ray) : RayFrame{})
    {
    }

    // Walks the tree from the root, nearest child first; the best hit goes to `hit`.
    bool run(ObjectHit& hit)
    {
        Entry e{0, 0, 0, range_.min};  // the root: a wide node (count 0), number 0
        for (;;) {
            if (e.in_blocks) {
                const FourTriangles* g = &tree_.blocks[e.first];
                for (std::uint32_t j = 0; j < e.count; j += 4, ++g)
                    if (block(*g, std::min<std::uint32_t>(4, e.count - j)) == Walk::answered)
                        return answer(hit);
            } else if (e.count > 0) {
                if (leaf(&tree_.object_index[e.first], e.count) == Walk::answered)
                    return answer(hit);
            } else if (open(tree_.nodes[e.first], e)) {
                continue;
            }
            if (!next(e)) {
                if (found_)
                    hit = best_;
                return found_;
            }
        }
    }

private:
    struct Entry {
        std::uint32_t first;
        std::uint16_t count;
        std::uint16_t in_blocks;  // a leaf of triangles: first is its first block
        float t;                  // where the ray enters the child's box
    };

    // Child i of `node`, which the ray enters at t.
    static Entry child(const WideNode& node, int i, float t)
    {
        return {node.first[i], node.count[i], static_cast<std::uint16_t>(lane_in(node.in_blocks, i)), t};
    }

    bool answer(ObjectHit& hit) const
    {
        hit = best_;
        return true;
    }

    // A hit becomes the best so far, which answers an any-hit query.
    Walk keep(const ObjectHit& h)
    {
        best_ = h;
        found_ = true;
        reach_.max = next_up(best_.t);
        return kind == QueryKind::any ? Walk::answered : Walk::go_on;
    }

    // Object k asked as 10.4's loop asks it, in the range that beats the best so far.
    Walk ask(int k)
    {
        ObjectHit h;
        if (!objects_.intersect(k, ray_, closer_than(range_, best_, k), h))
            return Walk::go_on;
        return keep(h);
    }

    // A leaf of other kinds: its objects one by one, in order, through the object list.
    Walk leaf(const std::uint32_t* object, std::uint32_t n)
    {
        for (std::uint32_t j = 0; j < n; ++j)
            if (ask(static_cast<int>(object[j])) == Walk::answered)
                return Walk::answered;
        return Walk::go_on;
    }

    // A node: its children that the ray enters within reach. The nearest becomes `e`, the others are
    // pushed far to near; false when the ray enters none. An any-hit query pushes them as they come:
    // any hit answers it, the nearest no sooner than another (as Embree's occlusion rays walk).
    bool open(const WideNode& node, Entry& e)
    {
        count(Counter::nodes_visited);
        float t0[4];
        const unsigned entered = enter_boxes(node, slabs_, reach_, t0) & node.occupied;
        if (entered == 0)
            return false;
        if ((entered & (entered - 1)) == 0) {
            // One child entered (the commonest case): straight into it, nothing pushed.
            const int i = only_lane(entered);
            e = child(node, i, t0[i]);
            return true;
        }
        const std::ptrdiff_t base = top_;
        for (int i = 0; i < 4; ++i) {
            if (!lane_in(entered, i))
                continue;
            // Asked for now, to arrive while the nearer children are walked.
            if (lane_in(node.in_blocks, i))
                prefetch(&tree_.blocks[node.first[i]], sizeof(FourTriangles));
            else if (node.count[i] == 0)
                prefetch(&tree_.nodes[node.first[i]], sizeof(WideNode));
            // Written straight into its slot, field by field: an Entry built aside and copied in
            // was stored in four narrow pieces and read back as one 8-byte word, which the
            // processor cannot forward from its store buffer (a stall of a dozen cycles a push,
            // 12% of the closest-hit walk on the pyramid by perf; chapters/benchmark/README.md,
            // "Chapter 10's steps", step 10).
            std::ptrdiff_t j = top_++;
            if (kind == QueryKind::closest)
                for (; j > base && stack_[j - 1].t < t0[i]; --j)
                    stack_[j] = stack_[j - 1];
            stack_[j] = child(node, i, t0[i]);
        }
        e = stack_[--top_];
        return true;
    }

    // The next child on the stack, passing over those that lie beyond a hit found since they were
    // pushed; false when none is left.
    bool next(Entry& e)
    {
        do {
            if (top_ == 0)
                return false;
            e = stack_[--top_];
        } while (e.t > reach_.max);
        return true;
    }

    // What the one-by-one loop asks an object, for a lane the block's test hit: the bound on t
    // (bounded_answer, before the range, as hit_triangle_bounded applies it), the tie rule, its
    // front; true when the hit is kept.
    bool lane_kept(const FourTriangles& g, const FourHits& h, const FourBounds& bounds, int i)
    {
        const int k = g.object[i];
        const Triangle tri = g.triangle(i);
        TriangleHit<float> answer{h.t[i], h.V[i] / h.det[i], h.W[i] / h.det[i]};
        if (bounded_) {
            // bounded_answer's steps where the four-lane bound already decides them, else itself.
            const LaneAnswer lane = lane_answer(h, bounds, i);
            if (known(bounds, i) && lane.beyond() && (lane.coarse() || lane.fine()))
                answer_beyond_bound(ray_, tri, answer, lane.coarse(), answer);
            else if (!bounded_answer(ray_, tri, answer, answer))
                return false;
        }
        if (!closer_than(range_, best_, k).surrounds(answer.t))
            return false;
        if (back_refused(g, i))
            return false;
        keep(ObjectHit{answer.t, k, answer.beta, answer.gamma});
        return true;
    }

    // A block of a leaf of triangles, its first n lanes: four at a time (10.6) where the query asks
    // for the watertight test, else (or with 10.6's stub) one by one.
    Walk block(const FourTriangles& g, std::uint32_t n)
    {
        if (bounded_ && leaves_plane(g))
            return Walk::go_on;
        // Bounded, every lane hit along the whole line, as hit_triangle_bounded asks: a lane's
        // answer may lie in the range when its float t does not (bounded_answer).
        const Interval asked = bounded_ ? Interval{-infinity, infinity} : Interval{range_.min, reach_.max};
        const FourHits h = four_wide_ ? hit_four_triangles(g, frame_, asked) : FourHits::not_tested();
        if (!h.tested) {
            for (std::uint32_t i = 0; i < n; ++i)
                if (ask(g.object[i]) == Walk::answered)
                    return Walk::answered;
            return Walk::go_on;
        }
        // Bounded, the lanes hit are told apart by their bound, four at once (lane_bounds.hpp),
        // before any is asked one by one: most then need only the plane's t, or nothing.
        const FourBounds bounds = bounded_ && h.hit != 0 ? four_t_error_bounds(g, frame_) : FourBounds{};
        if (kind == QueryKind::any)
            return first_lane_kept(g, h, bounds, n);
        count(Counter::intersection_tests, n);
        nearest_lane_kept(g, h, bounds, h.hit & ((1u << n) - 1u));
        return Walk::go_on;
    }

    // Whether the ray starts off the plane every triangle of the block lies on, and moves away from
    // it: a ray leaving a floor, a wall. Then the bounded test answers no lane: each triangle's true t
    // is below 0, so a float t beyond its bound cannot be (the bound is on |t - true t|), and within
    // it double's own test, which places a hit in front only beyond double's bound, refuses it too.
    // (Without the bound, a float t rounded above range.min could be a hit: not passed over.) Why:
    // a ray leaving a surface starts within that surface's margin (chapter 07: 2^-20 of the reach's
    // width, wider than chapter 04's offset of the origin), so the walk entered the floor's leaf
    // from every ray that left the floor, and tested it, the floor's own triangle in double:
    // chapters/benchmark/README.md, "Chapter 10's steps", step 15.
    bool leaves_plane(const FourTriangles& g) const
    {
        if (g.flat_axis < 0)
            return false;
        const float o = ray_.origin[g.flat_axis], d = ray_.dir[g.flat_axis];
        return (o > g.flat_at && d > 0.0f) || (o < g.flat_at && d < 0.0f);
    }

    // Lane i's answer told from its bound, where the bound is known there.
    static bool known(const FourBounds& bounds, int i) { return lane_in(bounds.known, i); }
    static LaneAnswer lane_answer(const FourHits& h, const FourBounds& bounds, int i)
    {
        return {h.t[i], bounds.upper[i], bounds.lower[i]};
    }

    // Whether the ray meets lane i's back, where the scene says its triangle has only a front.
    bool back_refused(const FourTriangles& g, int i) const
    {
        const int k = g.object[i];
        return objects_.one_sided && (*objects_.one_sided)[objects_.ref(k).index] &&
               glm::dot(face_normal(g.triangle(i)), ray_.dir) > 0.0f;
    }

    // An any-hit query's block: the lanes in the leaf's order, counted as the one-by-one loop counts
    // them (the tests up to the hit); answered at the first lane kept. A lane whose bound puts its
    // answer certainly inside the range is hit there whatever that answer's t, and one whose bound
    // puts it certainly outside is not: neither is asked one by one (an any-hit query says only
    // whether, never where).
    Walk first_lane_kept(const FourTriangles& g, const FourHits& h, const FourBounds& bounds, std::uint32_t n)
    {
        for (std::uint32_t j = 0; j < n; ++j) {
            const int i = static_cast<int>(j);
            if (!lane_in(h.hit, i))
                continue;
            const LaneAnswer lane = lane_answer(h, bounds, i);
            const bool decided = known(bounds, i);
            bool kept;
            if (decided && lane.certainly_in(range_))
                kept = !back_refused(g, i) && keep(ObjectHit{h.t[i], g.object[i], 0.0f, 0.0f}) == Walk::answered;
            else
                kept = !(decided && lane.refused_by(range_)) && lane_kept(g, h, bounds, i);
            if (kept) {
                count(Counter::intersection_tests, j + 1);
                return Walk::answered;
            }
        }
        count(Counter::intersection_tests, n);
        return Walk::go_on;
    }

    // A closest-hit query's block, the lanes hit in `left`.
    void nearest_lane_kept(const FourTriangles& g, const FourHits& h, const FourBounds& bounds, unsigned left)
    {
        if (bounded_) {
            // Every lane asked, as the one-by-one loop asks them (closer_than keeps the nearest
            // whatever the order): a lane whose float t is within the bound is answered by double,
            // nearer or farther than the float t says, so no float order can end the block early.
            // But nearest first, so that a lane whose bound puts it certainly beyond the best hit
            // found meanwhile (or outside the range) is passed over without being asked.
            while (left != 0) {
                int i = -1;
                for (int l = 0; l < 4; ++l)
                    if (lane_in(left, l) && (i < 0 || h.t[l] < h.t[i]))
                        i = l;
                left &= ~(1u << i);
                if (!(known(bounds, i) && lane_answer(h, bounds, i).refused_by(reach_)))
                    lane_kept(g, h, bounds, i);
            }
            return;
        }
        // Nearest first, by t and then object number (closer_than's order): the first lane kept is
        // the block's answer (every lane after it would fail closer_than). A lane that fails is
        // passed over, not taken to end the block: a 10.6 that breaks its contract (a hit in an
        // empty lane, a NaN t, t at the range's start) costs its own lanes, not the others'.
        while (left != 0) {
            int i = -1;
            for (int l = 0; l < 4; ++l)
                if (lane_in(left, l) && (i < 0 || h.t[l] < h.t[i] || (h.t[l] == h.t[i] && g.object[l] < g.object[i])))
                    i = l;
            if (lane_kept(g, h, bounds, i))
                return;
            left &= ~(1u << i);
        }
    }

    const WideBvh& tree_;
    const Ray& ray_;
    const Interval range_;
    const Objects& objects_;
    const RaySlabs slabs_;
    Interval reach_;  // the range that could still beat the best hit
    ObjectHit best_;
    bool found_ = false;
    const bool bounded_, four_wide_;
    const RayFrame frame_;
    Entry stack_[wide_stack_size];
    // Not an int, which an Entry's unsigned fields may alias: the compiler then stored it and read it
    // back around every push (step 18).
    std::ptrdiff_t top_ = 0;
};

class WideBvhAccel final : public MarginedAccelerator {
public:
    explicit WideBvhAccel(const Objects& objects, const BvhSettings& settings = {})
    {
        const Timer timer;
        const BvhAccel binary(objects, settings);
        const Bvh& b = binary.bvh();
        margins_ = binary.margins();
        tree_.object_index = b.object_index;
        // A wide node for each binary inner node at most, of which a tree of m nodes has (m - 1) / 2.
        tree_.nodes.reserve(b.nodes.size() / 2 + 1);
        if (!b.nodes.empty()) {
            if (b.nodes[0].count > 0)
                collapse_leaf_root(b.nodes[0]);
            else
                collapse(b, 0);
        }
        build_triangle_blocks(objects);
        bytes_ = tree_.nodes.size() * sizeof(WideNode) + tree_.blocks.size() * sizeof(FourTriangles) +
                 tree_.object_index.size() * sizeof(std::uint32_t);
        build_seconds_ = timer.seconds();
    }

    std::size_t bytes() const override { return bytes_; }
    void report(std::ostream& out) const override
    {
        out << "wide_nodes=" << tree_.nodes.size() << '\n'
            << "bytes=" << bytes_ << '\n'
            << "build_seconds=" << build_seconds_ << '\n';
    }
    const WideBvh& tree() const { return tree_; }

private:
    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        return ready(ray) && WideQuery<QueryKind::closest>(tree_, ray, range, objects).run(hit);
    }

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        ObjectHit hit;
        return ready(ray) && WideQuery<QueryKind::any>(tree_, ray, range, objects).run(hit);
    }

    // Each leaf of triangles only, its triangles copied four to a block (four_triangles.hpp), the
    // blocks of a leaf one after another, its node pointed at them; leaves holding another kind keep
    // their objects in object_index.
    void build_triangle_blocks(const Objects& objects)
    {
        const auto triangles_only = [&](const WideNode& w, int i) {
            if (!lane_in(w.occupied, i) || w.count[i] == 0)
                return false;
            for (std::uint32_t j = 0; j < w.count[i]; ++j)
                if (objects.ref(static_cast<int>(tree_.object_index[w.first[i] + j])).kind != ObjectKind::triangle)
                    return false;
            return true;
        };
        // Marked and counted first, so the blocks take one allocation, not a vector's growing copies.
        std::size_t blocks = 0;
        for (WideNode& w : tree_.nodes)
            for (int i = 0; i < 4; ++i)
                if (triangles_only(w, i)) {
                    w.in_blocks |= 1u << i;
                    blocks += (w.count[i] + 3u) / 4u;
                }
        tree_.blocks.reserve(blocks);
        for (WideNode& w : tree_.nodes)
            for (int i = 0; i < 4; ++i) {
                if (!lane_in(w.in_blocks, i))
                    continue;
                const std::uint32_t* object = &tree_.object_index[w.first[i]];
                w.first[i] = static_cast<std::uint32_t>(tree_.blocks.size());
                for (std::uint32_t j = 0; j < w.count[i]; j += 4)
                    tree_.blocks.push_back(four_triangles(objects, object + j, std::min<std::uint32_t>(4, w.count[i] - j)));
            }
    }

    static void set_child(WideNode& w, int i, const Bounds& box, std::uint32_t first, std::uint16_t count)
    {
        for (int a = 0; a < 3; ++a) {
            w.min[a][i] = box.min[a];
            w.max[a][i] = box.max[a];
        }
        w.first[i] = first;
        w.count[i] = count;
        w.occupied |= 1u << i;
    }

    static WideNode empty_node()
    {
        WideNode w{};
        for (int i = 0; i < 4; ++i)
            set_child(w, i, Bounds{}, 0, 0);
        w.occupied = 0;
        return w;
    }

    void collapse_leaf_root(const BvhNode& leaf)
    {
        tree_.nodes.push_back(empty_node());
        set_child(tree_.nodes[0], 0, leaf.bounds(), leaf.first, leaf.count);
    }

    // The wide node for binary inner node `n`; returns its number.
    std::uint32_t collapse(const Bvh& b, std::uint32_t n)
    {
        const auto self = static_cast<std::uint32_t>(tree_.nodes.size());
        tree_.nodes.push_back(empty_node());
        std::uint32_t children[4] = {n + 1, b.nodes[n].first};
        int k = 2;
        while (k < 4) {
            int open = -1;
            for (int i = 0; i < k; ++i)
                if (b.nodes[children[i]].count == 0 &&
                    (open < 0 || b.nodes[children[i]].bounds().half_area() > b.nodes[children[open]].bounds().half_area()))
                    open = i;
            if (open < 0)
                break;
            const std::uint32_t c = children[open];
            children[open] = c + 1;
            children[k++] = b.nodes[c].first;
        }
        for (int i = 0; i < k; ++i) {
            const BvhNode& c = b.nodes[children[i]];
            const std::uint32_t first = c.count > 0 ? c.first : collapse(b, children[i]);
            set_child(tree_.nodes[self], i, c.bounds(), first, c.count);
        }
        return self;
    }

    // A tree with something in it, and a ray the slab test can take (common/bounds.hpp).
    bool ready(const Ray& ray) const { return !tree_.nodes.empty() && valid_ray(ray); }

    WideBvh tree_;
    std::size_t bytes_ = 0;
    double build_seconds_ = 0.0;
};

}  // namespace rt
