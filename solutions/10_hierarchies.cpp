// SOLUTION BEGIN
// Chapter 10, hierarchies: the reference solution.
//
// This file is also the source of exercises/10_hierarchies.cpp: the kit's cutter drops every block
// between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 10, hierarchies: your exercises.
// STUB //
// STUB // Each function below states what to compute (not how); its contract is documented in
// STUB // chapters/10_hierarchies/10_hierarchies.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// STUB // the stubs, the tree is one leaf and the traversal finds nothing (the picture is background).
// STUB // Check your work with:  cmake --build --preset grade --target check_10
// STUB // Stuck? Hints in tiers you open one at a time: chapters/10_hierarchies/hints.md, or
// STUB // ./build/grade/hint 10.1 (tier 1, the idea), ./build/grade/hint 10.1 2 (the trap), ... 3 (the walk-through).
// STUB //
// STUB // This chapter uses chapter 02's objects (Objects::intersect, closer_than) and the slab test
// STUB // (common/bounds.hpp); the build is given (bvh.hpp).
#include "10_hierarchies/10_hierarchies.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include "common/stats.hpp"

#include <cmath>
// SOLUTION BEGIN
#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>
// SOLUTION END

namespace rt {

float sah_cost(const Bounds& parent, const Bounds& left, int n_left, const Bounds& right, int n_right)
{
    // EXERCISE 10.1: the SAH cost of a split
    // Return the surface area heuristic's expected cost of splitting a node of box `parent` into the
    // two children given (each a box and an object count), with the header's two cost constants.
    // An empty child (no objects, an empty box) adds nothing; a parent of no area (every object at
    // one point) gives each child a share of 1. Lesson: "The surface area heuristic (EXERCISES 10.1
    // and 10.2)".
    // Stuck? hint 10.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const float area = parent.half_area();
    const auto share = [&](const Bounds& child, int n) {
        if (n == 0)
            return 0.0f;
        return area > 0.0f ? child.half_area() / area : 1.0f;
    };
    return sah_traversal_cost + (share(left, n_left) * static_cast<float>(n_left) +
                                 share(right, n_right) * static_cast<float>(n_right)) * sah_intersect_cost;
    // SOLUTION END
    // STUB return stub("10.1", infinity);
}

SahSplit best_split(const Bounds& parent, const std::vector<SahBin>& bins)
{
    // EXERCISE 10.2: the best plane between bins
    // Return the cheapest plane k between neighbouring bins (bins 0..k left, the rest right) with
    // its cost by 10.1, or the default SahSplit (no split) when no plane has objects on both
    // sides, as with fewer than two bins. On equal costs the first plane wins; the last plane
    // counts. Lesson: "The surface area heuristic (EXERCISES 10.1 and 10.2)".
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // One pass each way over the bins, not one per plane.
    // DETAIL END
    // Stuck? hint 10.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const int n = static_cast<int>(bins.size());
    SahSplit best;
    if (n < 2)
        return best;
    std::vector<SahBin> right(n);  // right[k]: bins k..n - 1 as one, their count and box
    SahBin suffix;
    for (int k = n - 1; k > 0; --k) {
        suffix.count += bins[k].count;
        suffix.bounds.grow(bins[k].bounds);
        right[k] = suffix;
    }
    SahBin left;
    for (int k = 0; k + 1 < n; ++k) {
        left.count += bins[k].count;
        left.bounds.grow(bins[k].bounds);
        if (left.count == 0 || right[k + 1].count == 0)
            continue;
        const float cost = sah_cost(parent, left.bounds, left.count, right[k + 1].bounds, right[k + 1].count);
        if (cost < best.cost)
            best = {k, cost};
    }
    return best;
    // SOLUTION END
    // STUB return stub("10.2", SahSplit{});
}

bool make_leaf(int n, int depth, int leaf_size, int max_depth, float best_split_cost)
{
    // EXERCISE 10.3: the slides' stopping rule, and the SAH's own
    // Return whether a node of n objects at this depth (the root is depth 0) becomes a leaf: at most
    // leaf_size objects, the depth limit reached, or a best split (best_split_cost, infinity when
    // none is possible) that saves nothing over testing all n here. Nudge: each bound is met exactly.
    // Lesson: "When to stop (EXERCISE 10.3)".
    // Stuck? hint 10.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    return n <= leaf_size || depth >= max_depth || !(best_split_cost < static_cast<float>(n) * sah_intersect_cost);
    // SOLUTION END
    // STUB return stub("10.3", true);
}

bool bvh_query(const Bvh& bvh, const Ray& ray, Interval range, const Objects& objects, bool any_hit, ObjectHit& hit)
{
    // EXERCISE 10.4: the traversal loop
    // Return whether the ray hits an object of the tree within range, the nearest in `hit` (on a tie
    // the lower object number; with any_hit, the first found, at once). The near child first; no box
    // searched that the ray meets only beyond the best hit so far; each node whose box is tested
    // counted (Counter::nodes_visited). A tree of no nodes, or a ray that is not valid_ray: no hit.
    // Lesson: "The traversal (EXERCISE 10.4)".
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // A loop over a small stack of node numbers (bvh_stack_size), no recursion; each node taken
    // from the stack counted.
    // DETAIL END
    // Stuck? hint 10.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    if (bvh.nodes.empty() || !valid_ray(ray))
        return false;
    const RaySlabs slabs(ray);
    // What could still beat the best hit: up to and including best.t (a lower-numbered object may
    // tie), so its end moves only when the best does.
    Interval reach = range;
    ObjectHit best;
    bool found = false;
    std::uint32_t stack[bvh_stack_size];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode& node = bvh.nodes[stack[--top]];
        count(Counter::nodes_visited);
        if (!slab_interval(node.bounds(), slabs, reach))
            continue;
        if (node.count > 0) {
            for (std::uint32_t j = 0; j < node.count; ++j) {
                const int k = static_cast<int>(bvh.object_index[node.first + j]);
                ObjectHit h;
                if (objects.intersect(k, ray, closer_than(range, best, k), h)) {
                    best = h;
                    found = true;
                    if (any_hit) {
                        hit = best;
                        return true;
                    }
                    reach.max = std::nextafter(best.t, infinity);
                }
            }
            continue;
        }
        const auto self = static_cast<std::uint32_t>(&node - bvh.nodes.data());
        const bool first_is_near = ray.dir[node.axis] > 0.0f;
        const std::uint32_t near = first_is_near ? self + 1 : node.first;
        const std::uint32_t far = first_is_near ? node.first : self + 1;
        stack[top++] = far;
        stack[top++] = near;
    }
    if (found)
        hit = best;
    return found;
    // SOLUTION END
    // STUB return stub("10.4", false);
}

bool hgrid_closest(const HGrid& h, int g, const Ray& ray, Interval part, Interval range, const Objects& objects,
                   ObjectHit& best)
{
    // EXERCISE 10.5: the child grid's descent
    // Walk grid g of h over `part` of the ray (chapter 07's walk), counting each cell visited
    // (Counter::cells_visited), and ask each cell in turn: one without a grid of its own as 07.6
    // does, in the query's `range`; one with a grid by this same function, over only the part of the
    // ray inside that cell. The first cell that keeps a hit ends the walk, at every level; a walk
    // that misses keeps nothing. Returns whether best changed. Lesson: "The hierarchy of grids
    // (EXERCISE 10.5)".
    // Stuck? hint 10.5 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const GridNode& node = h.grids[g];
    GridWalk walk = start_walk(node.grid.shape, ray, part);
    if (walk.missed)
        return false;
    do {
        count(Counter::cells_visited);
        const int child = node.child[walk.p];
        const bool kept = child >= 0
                              ? hgrid_closest(h, child, ray, Interval{walk.t_enter, walk.cell_exit()}, range, objects, best)
                              : closest_in_cell(node.grid, walk, ray, range, objects, best);
        if (kept)
            return true;
    } while (next_cell(walk));
    return false;
    // SOLUTION END
    // STUB return stub("10.5", false);
}

FourHits hit_four_triangles(const FourTriangles& g, const RayFrame& f, Interval range)
{
    // EXERCISE 10.6 (advanced): four triangles at once
    // Return the lanes of block g that the ray of frame f hits with t strictly inside range, each with
    // its t, V, W and det exactly as the watertight test (02.5) computes them for that lane's
    // triangle: 02.5's float operations with Float4 in place of float, in the same order (where an
    // edge function is 0 in float, that lane's three again in double, each rounded back to float);
    // triangles without area and empty lanes never hit. The stub's FourHits::not_tested()
    // has the wide tree ask the block one triangle at a time. Lesson: "Four triangles at once
    // (EXERCISE 10.6, advanced)".
    // Stuck? hint 10.6 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const Float4 Sx = f.Sx, Sy = f.Sy, Sz = f.Sz;
    // Corner c moved to the ray's origin and sheared, in the ray's frame, as 02.5 does it:
    // x = (c[kx] - o[kx]) - Sx (c[kz] - o[kz]).
    struct Sheared {
        Float4 x, y, z;
    };
    const auto shear = [&](int c) {
        const Float4 z = Float4::load(g.p[c][f.kz]) - f.o[2];
        return Sheared{Float4::load(g.p[c][f.kx]) - f.o[0] - Sx * z, Float4::load(g.p[c][f.ky]) - f.o[1] - Sy * z, z};
    };
    const Sheared A = shear(0), B = shear(1), C = shear(2);
    Float4 U = cross_2d(C.x, C.y, B.x, B.y), V = cross_2d(A.x, A.y, C.x, C.y), W = cross_2d(B.x, B.y, A.x, A.y);

    // A 0 may be a product difference that float rounded away: those lanes again in double (02.5).
    const unsigned zeros = bits((U == 0.0f) | (V == 0.0f) | (W == 0.0f)) & g.with_area;
    if (zeros != 0) {
        float ax[4], ay[4], bx[4], by[4], cx[4], cy[4], u[4], v[4], w[4];
        A.x.store(ax), A.y.store(ay), B.x.store(bx), B.y.store(by), C.x.store(cx), C.y.store(cy);
        U.store(u), V.store(v), W.store(w);
        for (int i = 0; i < 4; ++i)
            if (zeros >> i & 1u) {
                u[i] = static_cast<float>(cross_2d<double>(cx[i], cy[i], bx[i], by[i]));
                v[i] = static_cast<float>(cross_2d<double>(ax[i], ay[i], cx[i], cy[i]));
                w[i] = static_cast<float>(cross_2d<double>(bx[i], by[i], ax[i], ay[i]));
            }
        U = Float4::load(u), V = Float4::load(v), W = Float4::load(w);
    }
    const Mask4 differ = ((U < 0.0f) | (V < 0.0f) | (W < 0.0f)) & ((U > 0.0f) | (V > 0.0f) | (W > 0.0f));
    const Float4 det = U + V + W;
    const Float4 t = (U * (Sz * A.z) + V * (Sz * B.z) + W * (Sz * C.z)) / det;
    FourHits hits;
    hits.hit = bits(~differ & (det != 0.0f) & (t > range.min) & (t < range.max)) & g.with_area;
    t.store(hits.t), V.store(hits.V), W.store(hits.W), det.store(hits.det);
    return hits;
    // SOLUTION END
    // STUB return stub("10.6", FourHits::not_tested());
}

Bvh build_bvh(const std::vector<Bounds>& boxes)
{
    // EXERCISE 10.7 (open): your own build of the BVH
    // Return a tree of the objects whose boxes are `boxes` (already grown by their margins), in the
    // chapter's layout (BvhNode, Bvh): every object in exactly one leaf, each box holding what is
    // below it, a node's first child right after it. Any method; the grader checks the tree's
    // answers against brute force, then measures its nodes visited and objects tested per ray
    // against the reference's. Lesson: "Your own build (EXERCISE 10.7, open)".
    // Stuck? hint 10.7 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    // The reference's build (10.7): the surface area heuristic swept over every object rather than over
    // bins. At each node, along each axis, the objects sorted by the centre of their boxes; every
    // plane between two neighbours costed by 10.1 (a sweep from the right stores the suffixes' boxes,
    // one from the left grows the prefix); the cheapest of the three axes splits the node, unless
    // 10.3 says leaf (the SAH's own rule, no leaf size). Nodes depth first, as bvh.hpp lays them out.
    class SweepBuild {
    public:
        explicit SweepBuild(const std::vector<Bounds>& boxes) : boxes_(boxes), centres_(boxes.size())
        {
            for (size_t k = 0; k < boxes.size(); ++k)
                centres_[k] = boxes[k].centre();
            bvh_.object_index.resize(boxes.size());
            std::iota(bvh_.object_index.begin(), bvh_.object_index.end(), 0u);
            if (!boxes.empty())
                node(0, static_cast<int>(boxes.size()), 0);
        }
        Bvh take() { return std::move(bvh_); }

    private:
        std::uint32_t node(int begin, int end, int depth)
        {
            const auto self = static_cast<std::uint32_t>(bvh_.nodes.size());
            bvh_.nodes.push_back({});
            Bounds box;
            for (int i = begin; i < end; ++i)
                box.grow(boxes_[bvh_.object_index[i]]);
            const int n = end - begin;
            std::uint32_t* index = bvh_.object_index.data();
            int best_axis = -1, best_middle = 0;
            float best_cost = infinity;
            std::vector<std::uint32_t> sorted[3];
            for (int a = 0; a < 3 && n > 1; ++a) {
                sorted[a].assign(index + begin, index + end);
                std::sort(sorted[a].begin(), sorted[a].end(), [&](std::uint32_t p, std::uint32_t q) {
                    return centres_[p][a] < centres_[q][a] || (centres_[p][a] == centres_[q][a] && p < q);
                });
                suffix_.resize(static_cast<size_t>(n) + 1);
                suffix_[n] = Bounds{};
                for (int i = n - 1; i > 0; --i) {
                    suffix_[i] = suffix_[i + 1];
                    suffix_[i].grow(boxes_[sorted[a][i]]);
                }
                Bounds prefix;
                for (int i = 1; i < n; ++i) {  // the first i objects on the left
                    prefix.grow(boxes_[sorted[a][i - 1]]);
                    const float cost = sah_cost(box, prefix, i, suffix_[i], n - i);
                    if (cost < best_cost)
                        best_cost = cost, best_axis = a, best_middle = i;
                }
            }
            const bool too_many = n > std::numeric_limits<std::uint16_t>::max();  // a leaf counts in 16 bits
            if (!too_many && (best_axis < 0 || make_leaf(n, depth, 1, bvh_stack_size - 2, best_cost))) {
                bvh_.nodes[self] = {box.min, static_cast<std::uint32_t>(begin), box.max, static_cast<std::uint16_t>(n), 0};
                return self;
            }
            if (best_axis < 0 || too_many)
                best_axis = std::max(best_axis, 0), best_middle = n / 2;
            if (sorted[best_axis].empty())
                sorted[best_axis].assign(index + begin, index + end);
            std::copy(sorted[best_axis].begin(), sorted[best_axis].end(), index + begin);
            node(begin, begin + best_middle, depth + 1);
            const std::uint32_t second = node(begin + best_middle, end, depth + 1);
            bvh_.nodes[self] = {box.min, second, box.max, 0, static_cast<std::uint16_t>(best_axis)};
            return self;
        }

        const std::vector<Bounds>& boxes_;
        std::vector<point3> centres_;
        std::vector<Bounds> suffix_;  // the boxes of the objects from i on, along the axis swept
        Bvh bvh_;
    };
    return SweepBuild(boxes).take();
    // SOLUTION END
    // STUB return stub("10.7", Bvh{});
}

}  // namespace rt
