// Chapter 10, hierarchies: your exercises.
//
// Each function below says what to compute and gives a hint; its contract is documented in
// chapters/10_hierarchies/10_hierarchies.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// the stubs, the tree is one leaf and the traversal finds nothing (the picture is background).
// Check your work with:  cmake --build --preset grade --target check_10
//
// This chapter uses chapter 02's objects (Objects::intersect, closer_than) and the slab test
// (common/bounds.hpp); the build is given (bvh.hpp).
#include "10_hierarchies/10_hierarchies.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

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
    return stub("10.1", infinity);
}

SahSplit best_split(const Bounds& parent, const std::vector<SahBin>& bins)
{
    // EXERCISE 10.2: the best plane between bins.
    // 1. Sweep from the right: for each k, the box and count of bins k+1 .. end (suffix arrays).
    // 2. Sweep from the left, growing the box and count of bins 0 .. k; at each plane k from 0 to
    //    bins.size() - 2 with both sides non-empty, cost = sah_cost(parent, left box, left count,
    //    right box, right count); keep the least (strictly less: the first of equal costs stays).
    // Hint: std::vector<Bounds> and std::vector<int> of bins.size() for the right side.
    return stub("10.2", SahSplit{});
}

bool make_leaf(int n, int depth, int leaf_size, int max_depth, float best_split_cost)
{
    // EXERCISE 10.3: the slides' stopping rule, and the SAH's own.
    // A leaf when n <= leaf_size, or depth >= max_depth, or best_split_cost >= n sah_intersect_cost.
    // Hint: a node with no possible split has best_split_cost = infinity.
    return stub("10.3", true);
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
    return stub("10.4", false);
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
    return stub("10.5", false);
}

}  // namespace rt
