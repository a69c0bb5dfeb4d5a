// SOLUTION BEGIN
// Chapter 10, hierarchies: the reference solution.
//
// This file is also the source of exercises/10_hierarchies.cpp: the kit's cutter drops every block
// between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 10, hierarchies: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/10_hierarchies/10_hierarchies.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// STUB // the stubs, the tree is one leaf and the traversal finds nothing (the picture is background).
// STUB // Check your work with:  cmake --build --preset grade --target check_10
// STUB //
// STUB // This chapter uses chapter 02's objects (Objects::intersect, closer_than) and the slab test
// STUB // (common/bounds.hpp); the build is given (bvh.hpp).
#include "10_hierarchies/10_hierarchies.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include "common/stats.hpp"

#include <cmath>

namespace rt {

float sah_cost(const Bounds& parent, const Bounds& left, int n_left, const Bounds& right, int n_right)
{
    // EXERCISE 10.1: the SAH cost of a split.
    // 1. A = parent.half_area(). A child's share is child.half_area() / A, or 1 when A is 0.
    //    An empty child (n = 0) has no share.
    // 2. cost = sah_traversal_cost + share_left n_left sah_intersect_cost + share_right n_right
    //    sah_intersect_cost.
    // Hint: Bounds::empty() tells an empty box; its half_area is 0 too.
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
    // EXERCISE 10.2: the best plane between bins.
    // 1. Sweep from the right: for each k, the box and count of bins k+1 .. end (suffix arrays).
    // 2. Sweep from the left, growing the box and count of bins 0 .. k; at each plane k from 0 to
    //    bins.size() - 2 with both sides non-empty, cost = sah_cost(parent, left box, left count,
    //    right box, right count); keep the least (strictly less: the first of equal costs stays).
    // Hint: std::vector<Bounds> and std::vector<int> of bins.size() for the right side.
    // SOLUTION BEGIN
    const int n = static_cast<int>(bins.size());
    SahSplit best;
    if (n < 2)
        return best;
    std::vector<Bounds> right_box(n);
    std::vector<int> right_count(n, 0);
    Bounds box;
    int count = 0;
    for (int k = n - 1; k > 0; --k) {
        box.grow(bins[k].bounds);
        count += bins[k].count;
        right_box[k] = box;
        right_count[k] = count;
    }
    Bounds left;
    int left_count = 0;
    for (int k = 0; k + 1 < n; ++k) {
        left.grow(bins[k].bounds);
        left_count += bins[k].count;
        if (left_count == 0 || right_count[k + 1] == 0)
            continue;
        const float cost = sah_cost(parent, left, left_count, right_box[k + 1], right_count[k + 1]);
        if (cost < best.cost)
            best = {k, cost};
    }
    return best;
    // SOLUTION END
    // STUB return stub("10.2", SahSplit{});
}

bool make_leaf(int n, int depth, int leaf_size, int max_depth, float best_split_cost)
{
    // EXERCISE 10.3: the slides' stopping rule, and the SAH's own.
    // A leaf when n <= leaf_size, or depth >= max_depth, or best_split_cost >= n sah_intersect_cost.
    // Hint: a node with no possible split has best_split_cost = infinity.
    // SOLUTION BEGIN
    return n <= leaf_size || depth >= max_depth || !(best_split_cost < static_cast<float>(n) * sah_intersect_cost);
    // SOLUTION END
    // STUB return stub("10.3", true);
}

bool bvh_query(const Bvh& bvh, const Ray& ray, Interval range, const Objects& objects, bool any_hit, ObjectHit& hit)
{
    // EXERCISE 10.4: the traversal loop.
    // 1. No nodes, or !valid_ray(ray): false. const RaySlabs slabs(ray); a stack of
    //    bvh_stack_size node numbers holding the root (0); ObjectHit best; bool found = false.
    // 2. While the stack is not empty: pop node i; count(Counter::nodes_visited). The range that
    //    could still beat best is Interval{range.min, found ? std::nextafter(best.t, infinity) :
    //    range.max}; skip the node when slab_interval(node.bounds(), slabs, that range) is empty.
    // 3. A leaf: for each k = bvh.object_index[first + j]: objects.intersect(k, ray,
    //    closer_than(range, best, k), h) keeps h in best (found = true); with any_hit, return true.
    // 4. An inner node: push the far child, then the near one (the near one is popped first). The
    //    near one is node i + 1 when ray.dir[node.axis] > 0, else node.first.
    // 5. hit = best when found; return found.
    // Hint: std::uint32_t stack[bvh_stack_size]; int top = 0;
    // SOLUTION BEGIN
    if (bvh.nodes.empty() || !valid_ray(ray))
        return false;
    const RaySlabs slabs(ray);
    std::uint32_t stack[bvh_stack_size];
    int top = 0;
    stack[top++] = 0;
    ObjectHit best;
    bool found = false;
    while (top > 0) {
        const BvhNode& node = bvh.nodes[stack[--top]];
        count(Counter::nodes_visited);
        const Interval reach{range.min, found ? std::nextafter(best.t, infinity) : range.max};
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
    // EXERCISE 10.5: the child grid's descent.
    // 1. const GridNode& node = h.grids[g]; GridWalk walk = start_walk(node.grid.shape, ray, part);
    //    a missed walk keeps nothing: return false.
    // 2. do { count the cell; a cell with a child asks hgrid_closest(h, child, ray,
    //    Interval{walk.t_enter, walk.cell_exit()}, range, objects, best); any other cell asks
    //    closest_in_cell(node.grid, walk, ray, range, objects, best). A cell that keeps a hit:
    //    return true. } while (next_cell(walk)); return false.
    // Hint: chapter 07's UniformGrid::closest (grid.hpp) is this walk for one level.
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

}  // namespace rt
