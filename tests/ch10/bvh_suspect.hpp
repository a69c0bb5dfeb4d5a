// Chapter 10's diagnosis of one ray the BVH answers differently from brute force
// (tests/ch07/suspect.hpp), each exercise held to its own contract, in the order the query uses
// them:
//  - the build's stop rule (10.3, for the SAH build; the median split asks nothing of 10.1-10.3):
//    no inner node at the depth limit or deeper (a node there is a leaf, whatever else holds),
//    asked again for such a node;
//  - the query (10.4), both kinds, on the tree as built (any tree of the kit holds its objects'
//    grown boxes, so brute force's answer is the query's promise): the closest hit is brute
//    force's, object and t; the any-hit answer is brute force's, with a hit its object really has
//    there. For a closest hit it misses, the diagnosis says in which leaf the object lies and where
//    the ray meets that leaf's box (searched up to one float step past the best hit so far).
// 10.1 and 10.2 shape the tree but not its answers, and are not asked again here.
#pragma once

#include "10_hierarchies/bvh.hpp"
#include "tests/ch07/grid_suspect.hpp"

namespace rt::grader::suspect {

// 10.3 over the tree: false (and the finding) when an inner node lies at max_depth or deeper and
// make_leaf, asked again for it, does not make it a leaf.
inline bool check_depth_limit(Diagnosis& d, const Bvh& bvh, int leaf_size, int max_depth)
{
    d.check("10.3", "make_leaf");
    struct At {
        std::uint32_t node;
        int depth;
    };
    // Objects under each node, from the leaves up (children come after their parent).
    std::vector<long long> under(bvh.nodes.size(), 0);
    for (size_t i = bvh.nodes.size(); i-- > 0;) {
        const BvhNode& n = bvh.nodes[i];
        if (n.count > 0)
            under[i] = n.count;
        else if (i + 1 < bvh.nodes.size() && n.first < bvh.nodes.size())
            under[i] = under[i + 1] + under[n.first];
    }
    std::vector<At> stack{{0, 0}};
    while (!stack.empty() && !bvh.nodes.empty()) {
        const At at = stack.back();
        stack.pop_back();
        if (at.node >= bvh.nodes.size())
            continue;
        const BvhNode& n = bvh.nodes[at.node];
        if (n.count > 0)
            continue;
        if (at.depth >= max_depth) {
            const int objects = static_cast<int>(under[at.node]);
            if (!make_leaf(objects, at.depth, leaf_size, max_depth, 0.0f)) {
                d.fail("10.3", "make_leaf", "the tree has an inner node at depth " + std::to_string(at.depth) + " over " + std::to_string(objects) +
                                                " objects; make_leaf(" + std::to_string(objects) + ", " + std::to_string(at.depth) + ", " + std::to_string(leaf_size) + ", " +
                                                std::to_string(max_depth) + ", 0) returns false; its contract promises true: at the depth limit or deeper a node is a leaf");
                return false;
            }
            continue;  // not make_leaf's doing (a group too large for one leaf is halved)
        }
        stack.push_back({at.node + 1, at.depth + 1});
        stack.push_back({n.first, at.depth + 1});
    }
    return true;
}

// Where object k lies in the tree, and where the ray meets that leaf's box: in words.
inline std::string where_in_tree(const Bvh& bvh, int k, const Ray& ray, Interval range)
{
    for (size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& n = bvh.nodes[i];
        if (n.count == 0)
            continue;
        for (std::uint32_t j = n.first; j < n.first + n.count && j < bvh.object_index.size(); ++j)
            if (static_cast<int>(bvh.object_index[j]) == k) {
                const std::optional<Interval> met = slab_interval(n.bounds(), RaySlabs(ray), range);
                return "object " + std::to_string(k) + " lies in leaf node " + std::to_string(i) +
                       (met ? ", whose box the ray meets from t = " + show_t(met->min) : std::string(", whose box the slab test does not meet"));
            }
    }
    return "object " + std::to_string(k) + " lies in no leaf";
}

inline std::string diagnose_bvh(const Bvh& bvh, const Ray& ray, Interval range, const Objects& objects, const BvhSettings& settings = {})
{
    Diagnosis d;
    d.exercised = "10.1-10.4 (10.1-10.3 the build, 10.4 the query)";
    if (settings.split == BvhSplit::sah && !check_depth_limit(d, bvh, settings.leaf_size, settings.max_depth))
        return d.text();  // (the median split asks nothing of 10.1-10.3)
    d.check("10.4", "bvh_query");
    ObjectHit want, got;
    const bool want_found = brute_force().closest(ray, range, objects, want);
    const bool got_found = bvh_query(bvh, ray, range, objects, false, got);
    if (want_found != got_found || (want_found && (want.object != got.object || want.t != got.t))) {
        std::string what = "the closest hit: it returned " + std::string(got_found ? show(got) : "no hit") + "; its contract promises brute force's " +
                           (want_found ? show(want) : "no hit") + " (the nearest; at equal t the lower object number)";
        if (want_found)
            what += "; " + where_in_tree(bvh, want.object, ray, range) +
                    (got_found ? " (a box met no farther than one float step past the best hit so far is searched)" : "");
        d.fail("10.4", "bvh_query", what);
        return d.text();
    }
    ObjectHit any_hit;
    const bool want_any = brute_force().any(ray, range, objects);
    const bool got_any = bvh_query(bvh, ray, range, objects, true, any_hit);
    ObjectHit check;
    const bool real = got_any && any_hit.object >= 0 && any_hit.object < objects.size() && objects.intersect(any_hit.object, ray, range, check) && check.t == any_hit.t;
    if (got_any != want_any || (got_any && !real))
        d.fail("10.4", "bvh_query", "the any-hit query: it returned " + std::string(got_any ? "true, " + show(any_hit) : "false") + "; its contract promises " +
                                        (want_any ? "true, with a hit its object has in the range" : "false: no object is hit in the range"));
    return d.text();
}

}  // namespace rt::grader::suspect
