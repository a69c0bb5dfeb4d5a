// The bounding volume hierarchy as an accelerator (given): built top-down by the surface area
// heuristic over binned box centres (your 10.1-10.3), or by your own build (10.7, --split open),
// queried by your traversal (10.4).
//
// The build (after pbrt-v4's BVHAggregate, and Wald's binned SAH, 2007, as Embree bins): a node's
// objects are binned by the centre of their boxes into equal slices along each of the three axes;
// the best plane between bins (10.2) of the three splits them, unless 10.3 says leaf. The nodes are
// laid out depth first in one array, a node's first child right after it.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "10_hierarchies/10_hierarchies.hpp"
#include "10_hierarchies/lanes.hpp"
#include "common/error.hpp"
#include "common/stats.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rt {

enum class BvhSplit { sah, median, open };  // open: your 10.7, build_bvh

struct BvhSettings {
    int leaf_size = 4;   // the slides' "4-8 works well"
    int max_depth = 48;  // below bvh_stack_size, so the traversal's stack cannot overflow
    int bins = 32;       // the most bins along an axis: Embree's 32 (fewer for a small node, sah_split)
    BvhSplit split = BvhSplit::sah;
};

struct BvhStats {
    int nodes = 0, leaves = 0, depth = 0;
    std::size_t bytes = 0;
    double build_seconds = 0.0;
};

// What is wrong with a tree for the objects whose (grown) boxes are `boxes`, by 10.7's rules (the
// contract's "Correct"), in words naming the first node or object at fault; "" for a tree 10.4 can
// walk that holds every object. Fills `shape` with its nodes, leaves and depth.
inline std::string bvh_problem(const Bvh& bvh, const std::vector<Bounds>& boxes, BvhStats& shape)
{
    const std::size_t n = boxes.size(), nodes = bvh.nodes.size();
    shape = {};
    if (bvh.object_index.size() != n)
        return "object_index lists " + std::to_string(bvh.object_index.size()) + " objects, the scene has " +
               std::to_string(n);
    if (n == 0)
        return nodes == 0 ? "" : "no objects, yet " + std::to_string(nodes) + " nodes";
    if (nodes == 0)
        return "no nodes for " + std::to_string(n) + " objects";
    if (nodes > 2 * n - 1)
        return std::to_string(nodes) + " nodes for " + std::to_string(n) +
               " objects: a tree of them has at most 2 n - 1";
    const auto holds = [](const Bounds& outer, const Bounds& inner) {
        return glm::all(glm::lessThanEqual(outer.min, inner.min)) &&
               glm::all(glm::greaterThanEqual(outer.max, inner.max));
    };
    const auto node_words = [](std::size_t k) { return "node " + std::to_string(k); };
    const auto describe_box = [](const Bounds& b) {
        std::ostringstream s;
        s.precision(9);
        s << '(' << b.min.x << ", " << b.min.y << ", " << b.min.z << ") to (" << b.max.x << ", " << b.max.y << ", "
          << b.max.z << ')';
        return s.str();
    };
    std::vector<char> listed(n, 0), reached(nodes, 0);
    struct Visit {
        std::uint32_t node;
        int depth;
    };
    std::vector<Visit> todo = {{0, 0}};
    while (!todo.empty()) {
        const Visit v = todo.back();
        todo.pop_back();
        if (reached[v.node]++)
            return node_words(v.node) + " is reached twice";
        shape.depth = std::max(shape.depth, v.depth);
        if (v.depth > bvh_stack_size - 2)
            return node_words(v.node) + " is at depth " + std::to_string(v.depth) + ", deeper than " +
                   std::to_string(bvh_stack_size - 2) + " (the traversal's stack)";
        const BvhNode& node = bvh.nodes[v.node];
        if (node.count > 0) {
            ++shape.leaves;
            if (std::size_t{node.first} + node.count > n)
                return node_words(v.node) + ", a leaf, lists object_index[" + std::to_string(node.first) + " .. " +
                       std::to_string(std::size_t{node.first} + node.count) + "), past its end (" +
                       std::to_string(n) + ")";
            for (std::uint32_t j = node.first; j < node.first + node.count; ++j) {
                const std::uint32_t k = bvh.object_index[j];
                if (k >= n)
                    return "object_index[" + std::to_string(j) + "] is " + std::to_string(k) + ", not an object";
                if (listed[k]++)
                    return "object " + std::to_string(k) + " is listed twice (the second time in " +
                           node_words(v.node) + ")";
                if (!holds(node.bounds(), boxes[k]))
                    return node_words(v.node) + "'s box " + describe_box(node.bounds()) + " does not hold object " +
                           std::to_string(k) + "'s box " + describe_box(boxes[k]);
            }
            continue;
        }
        const std::uint32_t first = v.node + 1, second = node.first;
        if (node.axis > 2)
            return node_words(v.node) + ", an inner node, has axis " + std::to_string(node.axis) + ", not 0, 1 or 2";
        if (first >= nodes || second <= first || second >= nodes)
            return node_words(v.node) + ", an inner node, has children " + std::to_string(first) + " and " +
                   std::to_string(second) + ": the second must come after the first, within the " +
                   std::to_string(nodes) + " nodes";
        for (const std::uint32_t child : {first, second})
            if (!holds(node.bounds(), bvh.nodes[child].bounds()))
                return node_words(v.node) + "'s box " + describe_box(node.bounds()) + " does not hold its child " +
                       node_words(child) + "'s box " + describe_box(bvh.nodes[child].bounds());
        todo.push_back({second, v.depth + 1});
        todo.push_back({first, v.depth + 1});
    }
    for (std::size_t k = 0; k < nodes; ++k)
        if (!reached[k])
            return node_words(k) + " is not reached from the root";
    for (std::size_t k = 0; k < n; ++k)
        if (!listed[k])
            return "object " + std::to_string(k) + " is in no leaf";
    shape.nodes = static_cast<int>(nodes);
    return "";
}

class BvhAccel final : public MarginedAccelerator {
public:
    BvhAccel(const Objects& objects, const BvhSettings& settings = {}) : settings_(settings)
    {
        if (settings.max_depth < 0 || settings.max_depth >= bvh_stack_size - 1)
            throw InputError("--max-depth must be between 0 and " + std::to_string(bvh_stack_size - 2) + ", got " +
                             std::to_string(settings.max_depth));
        if (settings.bins < 2 || settings.bins > max_bins)
            throw InputError("the BVH's bins must be between 2 and " + std::to_string(max_bins) + ", got " +
                             std::to_string(settings.bins));
        build(objects);
    }

    std::size_t bytes() const override { return stats_.bytes; }
    void report(std::ostream& out) const override
    {
        out << "bvh_nodes=" << stats_.nodes << '\n'
            << "bvh_leaves=" << stats_.leaves << '\n'
            << "bvh_depth=" << stats_.depth << '\n'
            << "bytes=" << stats_.bytes << '\n'
            << "build_seconds=" << stats_.build_seconds << '\n';
    }
    const BvhStats& stats() const { return stats_; }
    const Bvh& bvh() const { return bvh_; }

private:
    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        return bvh_query(bvh_, ray, range, objects, /*any_hit=*/false, hit);
    }

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        ObjectHit hit;
        return bvh_query(bvh_, ray, range, objects, /*any_hit=*/true, hit);
    }

    // The most objects a leaf can count (BvhNode::count is 16 bits): a larger group that 10.3 would
    // keep whole (or whose boxes all share one centre) is halved instead.
    static constexpr int max_leaf = std::numeric_limits<std::uint16_t>::max();
    // A bound on BvhSettings::bins, so that a mistaken setting cannot ask for millions of bins a node.
    static constexpr int max_bins = 1024;

    void build(const Objects& objects)
    {
        const Timer timer;
        const int n = objects.size();
        boxes_.resize(static_cast<std::size_t>(n));
        centres_.resize(static_cast<std::size_t>(n));
        // Each box grown by its margin (chapter 07's Margins, grid.hpp, which derives it): a hit's t
        // carries its test's rounding, which can put the hit point a little outside the object's own
        // box (a ray leaving a plane at a grazing angle, a triangle far larger than its distance from
        // the ray's origin); brute force reports such a hit, and the BVH must find it too. The
        // margin follows the rounding of the object's coordinates and of the rays' origins within the
        // margins' reach, so a small object near the origin keeps a small box beside a far one.
        for (int k = 0; k < n; ++k)
            boxes_[k] = objects.bounds(k);
        margins_ = margins_of(boxes_);
        for (int k = 0; k < n; ++k) {
            boxes_[k] = grown(boxes_[k], margins_.of(boxes_[k]));
            centres_[k] = boxes_[k].centre();
        }
        if (settings_.split == BvhSplit::sah) {
            // In object_index's order (the identity here), which the SAH split keeps them in.
            lane_boxes_.resize(static_cast<std::size_t>(n));
            for (int i = 0; i < n; ++i)
                lane_boxes_[i] = lane_box(boxes_[i]);
            lane_bins_.resize(3 * static_cast<std::size_t>(settings_.bins));
        }
        if (settings_.split == BvhSplit::open) {
            // Your own build (10.7): held to its rules before any ray walks it.
            bvh_ = build_bvh(boxes_);
            if (const std::string problem = bvh_problem(bvh_, boxes_, stats_); !problem.empty())
                throw InputError("your build_bvh (10.7) made a tree 10.4 cannot walk: " + problem);
        } else {
            bvh_.object_index.resize(static_cast<std::size_t>(n));
            std::iota(bvh_.object_index.begin(), bvh_.object_index.end(), 0u);
            if (n > 0)
                build_node(measure(0, n), 0);
        }
        stats_.nodes = static_cast<int>(bvh_.nodes.size());
        stats_.bytes = bvh_.nodes.size() * sizeof(BvhNode) + bvh_.object_index.size() * sizeof(std::uint32_t);
        stats_.build_seconds = timer.seconds();
        boxes_ = {};
        centres_ = {};
        lane_boxes_ = {};
        lane_bins_ = {};
    }

    // A run of object_index, object_index[begin, end), with the box around its objects' boxes and
    // the box around their centres.
    struct Group {
        int begin = 0, end = 0;
        Bounds box, centres;
    };

    Group measure(int begin, int end) const
    {
        Group g{begin, end, {}, {}};
        for (int i = begin; i < end; ++i) {
            g.box.grow(boxes_[bvh_.object_index[i]]);
            g.centres.grow(centres_[bvh_.object_index[i]]);
        }
        return g;
    }

    // Builds the node for the group at the end of the array; returns its number.
    std::uint32_t build_node(const Group& g, int depth)
    {
        const auto self = static_cast<std::uint32_t>(bvh_.nodes.size());
        bvh_.nodes.push_back({});
        stats_.depth = std::max(stats_.depth, depth);
        const int n = g.end - g.begin;
        const vec3 spread = g.centres.extent();
        int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;

        Group left, right;  // the children, once split
        const auto halve = [&] {
            const int middle = median_split(g.begin, g.end, axis);
            if (!lane_boxes_.empty())  // the SAH build's boxes follow object_index
                for (int i = g.begin; i < g.end; ++i)
                    lane_boxes_[i] = lane_box(boxes_[bvh_.object_index[i]]);
            left = measure(g.begin, middle);
            right = measure(middle, g.end);
            return true;
        };
        bool split = false;
        if (settings_.split == BvhSplit::median) {
            if (n > settings_.leaf_size && depth < settings_.max_depth)
                split = halve();
        } else if (n > settings_.leaf_size) {
            // A group of at most leaf_size is a leaf by 10.3's first rule, whatever its best split
            // would cost, so it is not binned: about half the groups a build meets are that small.
            split = sah_split(g, depth, axis, left, right);
        }
        // Too many for one leaf (all at one centre, or a student's 10.3 keeping everything): halved
        // by the median along the axis, so the first child still holds the lower centres.
        if (!split && n > max_leaf)
            split = halve();
        // Whatever 10.3 says, a path stays within the traversal's stack.
        if (depth >= bvh_stack_size - 2 && n <= max_leaf)
            split = false;
        if (!split) {
            bvh_.nodes[self] = {g.box.min, static_cast<std::uint32_t>(g.begin), g.box.max, static_cast<std::uint16_t>(n), 0};
            ++stats_.leaves;
            return self;
        }
        build_node(left, depth + 1);
        const std::uint32_t second = build_node(right, depth + 1);
        bvh_.nodes[self] = {g.box.min, second, g.box.max, 0, static_cast<std::uint16_t>(axis)};
        return self;
    }

    // The surface area heuristic's split of a group: its objects binned by centre along each axis
    // their centres spread along, in one pass (as Embree's builder bins, after Wald, "On fast
    // Construction of SAH-based Bounding Volume Hierarchies", 2007), the best plane of each axis
    // (10.2), the cheapest of those unless 10.3 says leaf. Three axes rather than one: a better
    // tree (step 8 of the lesson's "Where a query's time goes"; measured in
    // chapters/benchmark/README.md). Fills in the children and the split's axis; false: a leaf.
    bool sah_split(const Group& g, int depth, int& axis, Group& left, Group& right)
    {
        // Embree's count (BinMapping in its kernels/builders/heuristic_binning.h: the lesser of its
        // 32 bins and 4 + 0.05 n): 32 for a group of 560 objects or more, fewer below. The kit's
        // reason to follow it: 10.2's sweep costs about the same for each bin, and a small group's
        // planes are few, so a full 32 would make the build's small groups its most costly part.
        const int bins = std::min(settings_.bins, 4 + (g.end - g.begin) / 20);
        const float* low = glm::value_ptr(g.centres.min);
        const vec3 spread = g.centres.extent();
        // Bins a spread wide, each spread / bins: a centre's bin is its distance from the lowest
        // times bins / spread (a multiplication, not a division, for each object and axis).
        float scale[3];
        bool along[3];  // the axes the centres spread along, by a finite positive scale (not 0, NaN
                        // or infinite: a spread of 0, infinity, NaN or too small to divide by)
        LaneBin* axis_bins[3];  // bins 0 .. bins - 1 along each axis
        for (int a = 0; a < 3; ++a) {
            scale[a] = static_cast<float>(bins) / spread[a];
            along[a] = scale[a] > 0.0f && scale[a] < infinity;
            axis_bins[a] = &lane_bins_[static_cast<std::size_t>(a * bins)];
            if (along[a])
                std::fill(axis_bins[a], axis_bins[a] + bins, LaneBin{});
        }
        // An object's bin along each axis at once, from its centre: the distance from the lowest
        // times bins / spread, in lanes; the lesser of that and bins - 1 taken before the conversion
        // to int, which gives the same bin (truncation never decreases, and bins - 1 is whole). A NaN
        // centre (a box from -infinity to infinity, which no scene's object has) falls in the last bin.
        const Float4 low4(low[0], low[1], low[2], 0.0f), scale4(scale[0], scale[1], scale[2], 0.0f);
        const Float4 last_bin = static_cast<float>(bins - 1);
        const auto bins_of = [&](Float4 centre, float bin[4]) {
            less_or_second((centre - low4) * scale4, last_bin).store(bin);
        };
        for (int i = g.begin; i < g.end; ++i) {
            const LaneBox& box = lane_boxes_[i];
            float bin[4];
            bins_of(box.centre(), bin);
            for (int a = 0; a < 3; ++a)
                if (along[a])
                    axis_bins[a][static_cast<int>(bin[a])].grow(box);
        }
        // 10.2 takes the bins as the contract gives them: a count and a Bounds each.
        for (int a = 0; a < 3; ++a)
            if (along[a]) {
                bins_[a].resize(static_cast<std::size_t>(bins));
                for (int b = 0; b < bins; ++b)
                    bins_[a][b] = axis_bins[a][b].sah_bin();
            }
        SahSplit best;
        int best_axis = -1;
        for (int a = 0; a < 3; ++a)
            if (along[a]) {
                const SahSplit s = best_split(g.box, bins_[a]);
                if (s.split >= 0 && s.split + 1 < bins && s.cost < best.cost) {
                    best = s;
                    best_axis = a;
                }
            }
        if (best_axis < 0 || make_leaf(g.end - g.begin, depth, settings_.leaf_size, settings_.max_depth, best.cost))
            return false;
        // The objects of bins 0 .. best.split to the front, their boxes with them, and the box around
        // each side's centres grown on the way. From both ends, as Hoare partitions: past the objects
        // already on their side, each pair out of place swapped once (a pass from one end would move
        // every object of the right side). An object goes left when the binning's bin for it, the
        // whole part of b = min(t, bins - 1), is at most best.split: exactly when b < best.split + 1,
        // which compares b in its lane with no conversion to int.
        const Float4 past_left = static_cast<float>(best.split + 1);
        const unsigned along_best = 1u << best_axis;
        const auto goes_left = [&](Float4 centre) {
            return (bits(less_or_second((centre - low4) * scale4, last_bin) < past_left) & along_best) != 0;
        };
        std::uint32_t* index = bvh_.object_index.data();
        LaneBox* box = lane_boxes_.data();
        LaneBox left_centres, right_centres;
        int i = g.begin, j = g.end;  // [g.begin, i) go left, [j, g.end) go right
        for (;;) {
            Float4 ci = 0.0f, cj = 0.0f;
            while (i < j && goes_left(ci = box[i].centre())) {
                left_centres.grow(ci, ci);
                ++i;
            }
            if (i == j)
                break;
            --j;  // box[i] goes right: find one from the back that goes left
            while (i < j && !goes_left(cj = box[j].centre())) {
                right_centres.grow(cj, cj);
                --j;
            }
            right_centres.grow(ci, ci);
            if (i == j)
                break;
            left_centres.grow(cj, cj);
            std::swap(box[i], box[j]);
            std::swap(index[i], index[j]);
            ++i;
        }
        left = {g.begin, i, {}, {}};
        right = {i, g.end, {}, {}};
        left.centres = left_centres.bounds();
        right.centres = right_centres.bounds();
        if (left.end == g.begin || left.end == g.end)
            return false;  // a student's 10.2 chose a plane with an empty side
        for (int b = 0; b < bins; ++b)
            (b <= best.split ? left.box : right.box).grow(bins_[best_axis][b].bounds);
        axis = best_axis;
        return true;
    }

    // The median split the lesson measures SAH against: half the objects, by box centre, on each side.
    int median_split(int begin, int end, int axis)
    {
        const int middle = begin + (end - begin) / 2;
        std::nth_element(bvh_.object_index.begin() + begin, bvh_.object_index.begin() + middle,
                         bvh_.object_index.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) { return centres_[a][axis] < centres_[b][axis]; });
        return middle;
    }

    // A box in four-float lanes (x, y, z and a fourth unused), and a bin of them: the binning grows a
    // bin by an object's box in two instructions (SSE's minps and maxps) where Bounds::grow takes six,
    // and it grows three bins an object at every level of the tree: a third of the build's
    // instructions went to it (chapters/benchmark/README.md, "Chapter 10's steps", step 16). Minimum
    // and maximum are exact, so the bins hold what Bounds::grow would, bit for bit.
    struct LaneBox {
        Float4 min = infinity, max = -infinity;

        // As Bounds::grow: glm::min(min, p) keeps min unless p < min (and glm::max likewise).
        void grow(Float4 low, Float4 high)
        {
            min = less_or_second(low, min);
            max = greater_or_second(high, max);
        }
        Float4 centre() const { return (min + max) * 0.5f; }  // as Bounds::centre, lane by lane
        Bounds bounds() const
        {
            float low[4], high[4];
            min.store(low);
            max.store(high);
            return {point3(low[0], low[1], low[2]), point3(high[0], high[1], high[2])};
        }
    };
    static LaneBox lane_box(const Bounds& b)
    {
        return {Float4(b.min.x, b.min.y, b.min.z, 0.0f), Float4(b.max.x, b.max.y, b.max.z, 0.0f)};
    }
    struct LaneBin {
        LaneBox box;
        int count = 0;

        void grow(const LaneBox& b)
        {
            box.grow(b.min, b.max);
            ++count;
        }
        SahBin sah_bin() const { return {count, box.bounds()}; }
    };

    BvhSettings settings_;
    Bvh bvh_;
    BvhStats stats_;
    std::vector<Bounds> boxes_;
    std::vector<point3> centres_;
    std::vector<LaneBox> lane_boxes_;  // boxes_ in lanes, in object_index's order (the SAH build's only)
    std::vector<LaneBin> lane_bins_;   // the binning's bins along x, y and z, reused node after node
    std::vector<SahBin> bins_[3];      // the same as 10.2 takes them
};

}  // namespace rt
