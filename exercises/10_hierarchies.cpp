// Chapter 10, hierarchies: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/10_hierarchies/10_hierarchies.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// the stubs, the tree is one leaf and the traversal finds nothing (the picture is background).
// Check your work with:  cmake --build --preset grade --target check_10
// Stuck? Hints in tiers you open one at a time: chapters/10_hierarchies/hints.md, or
// ./build/grade/hint 10.1 (tier 1, the idea), ./build/grade/hint 10.1 2 (the trap), ... 3 (the walk-through).
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
    // EXERCISE 10.1: the SAH cost of a split
    // Return the surface area heuristic's expected cost of splitting a node of box `parent` into the
    // two children given (each a box and an object count), with the header's two cost constants.
    // An empty child (no objects, an empty box) adds nothing; a parent of no area (every object at
    // one point) gives each child a share of 1. Lesson: "The surface area heuristic (EXERCISES 10.1
    // and 10.2)".
    // Stuck? hint 10.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("10.1", infinity);
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
    return stub("10.2", SahSplit{});
}

bool make_leaf(int n, int depth, int leaf_size, int max_depth, float best_split_cost)
{
    // EXERCISE 10.3: the slides' stopping rule, and the SAH's own
    // Return whether a node of n objects at this depth (the root is depth 0) becomes a leaf: at most
    // leaf_size objects, the depth limit reached, or a best split (best_split_cost, infinity when
    // none is possible) that saves nothing over testing all n here. Nudge: each bound is met exactly.
    // Lesson: "When to stop (EXERCISE 10.3)".
    // Stuck? hint 10.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("10.3", true);
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
    return stub("10.4", false);
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
    return stub("10.5", false);
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
    return stub("10.6", FourHits::not_tested());
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
    return stub("10.7", Bvh{});
}

}  // namespace rt
