// The contract's example tree for 10.4 (10_hierarchies.hpp): two spheres along x, one per leaf.
// Node 0 is the root (split along x), node 1 the leaf of sphere 0 at x = 1, node 2 the leaf of
// sphere 1 at x = 5. 10.4's cases walk it, and 10.7's gate asks 10.4 to count on it as its contract
// says before 10.7's cost is counted through 10.4.
#pragma once

#include "10_hierarchies/10_hierarchies.hpp"

#include <vector>

namespace rt::grader {

inline const std::vector<Sphere> two_spheres = {{{1, 0, 0}, 0.5f}, {{5, 0, 0}, 0.5f}};

inline Objects two_objects()
{
    Objects o;
    o.spheres = two_spheres.data();
    o.sphere_count = 2;
    return o;
}

inline Bvh two_leaves()
{
    Bvh b;
    b.nodes = {{{0.5f, -0.5f, -0.5f}, 2, {5.5f, 0.5f, 0.5f}, 0, 0},
               {{0.5f, -0.5f, -0.5f}, 0, {1.5f, 0.5f, 0.5f}, 1, 0},
               {{4.5f, -0.5f, -0.5f}, 1, {5.5f, 0.5f, 0.5f}, 1, 0}};
    b.object_index = {0, 1};
    return b;
}

}  // namespace rt::grader
