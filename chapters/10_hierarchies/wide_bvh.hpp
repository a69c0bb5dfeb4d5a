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
#include "10_hierarchies/lanes.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

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
// SSE's max and min return their second operand when either is NaN, as the scalar test's
// `t_near > t0 ? t_near : t0` keeps t0: a NaN slab (an origin on a face, d_i = 0) leaves the
// interval alone.
inline unsigned enter_boxes(const WideNode& node, const RaySlabs& slabs, Interval reach, float t0_out[4])
{
#if RT_WIDE_SSE
    __m128 t0 = _mm_set1_ps(reach.min), t1 = _mm_set1_ps(reach.max);
    const __m128 widening = _mm_set1_ps(slab_far_widening);
    for (int a = 0; a < 3; ++a) {
        const __m128 near_plane = _mm_loadu_ps(slabs.down[a] ? node.max[a] : node.min[a]);
        const __m128 far_plane = _mm_loadu_ps(slabs.down[a] ? node.min[a] : node.max[a]);
        const __m128 o = _mm_set1_ps(slabs.origin[a]), inv = _mm_set1_ps(slabs.inv_dir[a]);
        const __m128 t_near = _mm_mul_ps(_mm_sub_ps(near_plane, o), inv);
        const __m128 t_far = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(far_plane, o), inv), widening);
        t0 = _mm_max_ps(t_near, t0);
        t1 = _mm_min_ps(t_far, t1);
    }
    _mm_storeu_ps(t0_out, t0);
    // Entered unless t0 > t1, as slab_interval says it.
    return ~static_cast<unsigned>(_mm_movemask_ps(_mm_cmpgt_ps(t0, t1))) & 0xfu;
#else
    float t0[4], t1[4];
    for (int i = 0; i < 4; ++i) {
        t0[i] = reach.min;
        t1[i] = reach.max;
    }
    for (int a = 0; a < 3; ++a) {
        const float* near_plane = slabs.down[a] ? node.max[a] : node.min[a];
        const float* far_plane = slabs.down[a] ? node.min[a] : node.max[a];
        const float o = slabs.origin[a], inv = slabs.inv_dir[a];
        for (int i = 0; i < 4; ++i) {
            const float t_near = (near_plane[i] - o) * inv;
            const float t_far = (far_plane[i] - o) * inv * slab_far_widening;
            t0[i] = t_near > t0[i] ? t_near : t0[i];
            t1[i] = t_far < t1[i] ? t_far : t1[i];
        }
    }
    unsigned entered = 0;
    for (int i = 0; i < 4; ++i) {
        t0_out[i] = t0[i];
        entered |= (t0[i] > t1[i] ? 0u : 1u) << i;
    }
    return entered;
#endif
}

class WideBvhAccel final : public Accelerator {
public:
    explicit WideBvhAccel(const Objects& objects, const BvhSettings& settings = {})
    {
        const Timer timer;
        const BvhAccel binary(objects, settings);
        const Bvh& b = binary.bvh();
        tree_.object_index = b.object_index;
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

    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        return query(ray, range, objects, false, hit);
    }
    bool any(const Ray& ray, Interval range, const Objects& objects) const override
    {
        ObjectHit hit;
        return query(ray, range, objects, true, hit);
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
    // Each leaf of triangles only, its triangles copied four to a block (four_triangles.hpp), the
    // blocks of a leaf one after another, its node pointed at them; leaves holding another kind keep
    // their objects in object_index.
    void build_triangle_blocks(const Objects& objects)
    {
        const auto triangles_only = [&](const WideNode& w, int i) {
            if (!(w.occupied >> i & 1u) || w.count[i] == 0)
                return false;
            for (std::uint32_t j = 0; j < w.count[i]; ++j)
                if (objects.ref(static_cast<int>(tree_.object_index[w.first[i] + j])).kind != ObjectKind::triangle)
                    return false;
            return true;
        };
        // Counted first, so the blocks take one allocation, not a vector's growing copies.
        std::size_t blocks = 0;
        for (const WideNode& w : tree_.nodes)
            for (int i = 0; i < 4; ++i)
                if (triangles_only(w, i))
                    blocks += (w.count[i] + 3u) / 4u;
        tree_.blocks.reserve(blocks);
        for (WideNode& w : tree_.nodes)
            for (int i = 0; i < 4; ++i) {
                if (!triangles_only(w, i))
                    continue;
                const std::uint32_t* object = &tree_.object_index[w.first[i]];
                w.first[i] = static_cast<std::uint32_t>(tree_.blocks.size());
                w.in_blocks |= 1u << i;
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

    bool query(const Ray& ray, Interval range, const Objects& objects, bool any_hit, ObjectHit& hit) const
    {
        if (tree_.nodes.empty() || !valid_ray(ray))
            return false;
        const RaySlabs slabs(ray);
        // Four triangles at once where the query asks for the watertight test (chapter 04 on);
        // the other tests go one by one through the object list.
        const bool bounded = objects.tests.triangle == TriangleTest::watertight_bounded;
        const bool four_wide = bounded || objects.tests.triangle == TriangleTest::watertight;
        const RayFrame frame = four_wide ? ray_frame(ray) : RayFrame{};
        Interval reach = range;
        ObjectHit best;
        bool found = false;
        // A hit becomes the best so far; true when it answers an any-hit query.
        const auto keep = [&](const ObjectHit& h) {
            best = h;
            found = true;
            reach.max = std::nextafter(best.t, infinity);
            return any_hit;
        };
        // Objects asked one by one, in order, through the object list, as 10.4's loop asks them.
        const auto ask = [&](int k) {
            ObjectHit h;
            return objects.intersect(k, ray, closer_than(range, best, k), h) && keep(h);
        };
        const auto one_by_one = [&](const std::uint32_t* object, std::uint32_t n) {
            for (std::uint32_t j = 0; j < n; ++j)
                if (ask(static_cast<int>(object[j])))
                    return true;
            return false;
        };
        // What the one-by-one loop asks an object, for a lane the block's test hit: the bound on t
        // (bounded_answer, before the range, as hit_triangle_bounded applies it), the tie rule, its
        // front; true when the hit is kept.
        const auto lane_kept = [&](const FourTriangles& g, const FourHits& h, int i) {
            const int k = g.object[i];
            const Triangle tri = g.triangle(i);
            TriangleHit<float> answer{h.t[i], h.V[i] / h.det[i], h.W[i] / h.det[i]};
            if (bounded && !bounded_answer(ray, tri, answer, answer))
                return false;
            if (!closer_than(range, best, k).surrounds(answer.t))
                return false;
            if (objects.one_sided && (*objects.one_sided)[objects.ref(k).index] && glm::dot(face_normal(tri), ray.dir) > 0.0f)
                return false;  // its back
            keep(ObjectHit{answer.t, k, answer.beta, answer.gamma});
            return true;
        };
        // A block of a leaf of triangles: four at a time (10.6) where the query asks for the
        // watertight test, else (or with 10.6's stub) one by one; true when a hit answers an any-hit
        // query.
        const auto block = [&](const FourTriangles& g, std::uint32_t n) {
            // Bounded, every lane hit beyond range.min: a lane's answer may come nearer than its float t.
            const FourHits h = four_wide ? hit_four_triangles(g, frame, Interval{range.min, bounded ? infinity : reach.max})
                                         : FourHits::not_tested();
            if (!h.tested) {
                for (std::uint32_t i = 0; i < n; ++i)
                    if (ask(g.object[i]))
                        return true;
                return false;
            }
            if (any_hit) {
                // In the leaf's order, counted as the one-by-one loop counts: the tests up to the hit.
                for (std::uint32_t i = 0; i < n; ++i)
                    if (h.hit >> i & 1u && lane_kept(g, h, static_cast<int>(i))) {
                        count(Counter::intersection_tests, i + 1);
                        return true;
                    }
                count(Counter::intersection_tests, n);
                return false;
            }
            count(Counter::intersection_tests, n);
            unsigned left = h.hit & ((1u << n) - 1u);
            if (bounded) {
                // Every lane asked, as the one-by-one loop asks them (closer_than keeps the nearest
                // whatever the order): a lane whose float t is within the bound is answered by
                // double, nearer or farther than the float t says, so no float order can end the
                // block early.
                for (int i = 0; left != 0; ++i, left >>= 1)
                    if (left & 1u)
                        lane_kept(g, h, i);
                return false;
            }
            // Nearest first, by t and then object number (closer_than's order): the first lane kept
            // is the block's answer (every lane after it would fail closer_than). Only the block's n
            // lanes, and a lane that fails is passed over, not taken to end the block: a 10.6 that
            // breaks its contract (a hit in an empty lane, a NaN t, t at the range's start) costs its
            // own lanes, not the others'.
            while (left != 0) {
                int i = -1;
                for (int l = 0; l < 4; ++l)
                    if (left >> l & 1u && (i < 0 || h.t[l] < h.t[i] || (h.t[l] == h.t[i] && g.object[l] < g.object[i])))
                        i = l;
                if (lane_kept(g, h, i))
                    break;
                left &= ~(1u << i);
            }
            return false;
        };
        struct Entry {
            std::uint32_t first;
            std::uint16_t count;
            std::uint16_t in_blocks;  // a leaf of triangles: first is its first block
            float t;                  // where the ray enters the child's box
        };
        Entry stack[wide_stack_size];
        int top = 0;
        Entry e{0, 0, 0, range.min};  // the root: a wide node (count 0), number 0
        const auto answer = [&] {
            hit = best;
            return true;
        };
        for (;;) {
            if (e.in_blocks) {
                const FourTriangles* g = &tree_.blocks[e.first];
                for (std::uint32_t j = 0; j < e.count; j += 4, ++g)
                    if (block(*g, std::min<std::uint32_t>(4, e.count - j)))
                        return answer();
            } else if (e.count > 0) {
                if (one_by_one(&tree_.object_index[e.first], e.count))
                    return answer();
            } else {
                const WideNode& node = tree_.nodes[e.first];
                count(Counter::nodes_visited);
                float t0[4];
                const unsigned entered = enter_boxes(node, slabs, reach, t0) & node.occupied;
                if (entered != 0 && (entered & (entered - 1)) == 0) {
                    // One child entered (the commonest case): straight into it, nothing pushed.
                    const int i = entered == 1u ? 0 : entered == 2u ? 1 : entered == 4u ? 2 : 3;
                    e = {node.first[i], node.count[i], static_cast<std::uint16_t>(node.in_blocks >> i & 1u), t0[i]};
                    continue;
                }
                if (entered != 0) {
                    // The children entered, pushed far to near; the nearest is taken at once.
                    const int base = top;
                    for (int i = 0; i < 4; ++i) {
                        if (!(entered >> i & 1u))
                            continue;
                        if (node.in_blocks >> i & 1u)
                            prefetch(&tree_.blocks[node.first[i]], sizeof(FourTriangles));
                        else if (node.count[i] == 0)
                            prefetch(&tree_.nodes[node.first[i]], sizeof(WideNode));
                        const Entry c{node.first[i], node.count[i], static_cast<std::uint16_t>(node.in_blocks >> i & 1u), t0[i]};
                        int j = top++;
                        for (; j > base && stack[j - 1].t < c.t; --j)
                            stack[j] = stack[j - 1];
                        stack[j] = c;
                    }
                    e = stack[--top];
                    continue;
                }
            }
            // The next child on the stack, passing over those that lie beyond a hit found since
            // they were pushed.
            do {
                if (top == 0) {
                    if (found)
                        hit = best;
                    return found;
                }
                e = stack[--top];
            } while (e.t > reach.max);
        }
    }

    WideBvh tree_;
    std::size_t bytes_ = 0;
    double build_seconds_ = 0.0;
};

}  // namespace rt
