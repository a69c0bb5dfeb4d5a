// The bounding volume hierarchy as an accelerator (given): built top-down by the surface area
// heuristic over binned box centres (your 10.1-10.3), queried by your traversal (10.4).
//
// The build (after pbrt-v4's BVHAggregate and Wald's binned SAH, 2007): a node's objects are
// binned by the centre of their boxes into `bins` equal slices along the axis where the centres
// spread most; the best plane between bins (10.2) splits them, unless 10.3 says leaf. The nodes are
// laid out depth first in one array, a node's first child right after it.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "10_hierarchies/10_hierarchies.hpp"
#include "common/error.hpp"
#include "common/stats.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace rt {

enum class BvhSplit { sah, median };

struct BvhSettings {
    int leaf_size = 4;   // the slides' "4-8 works well"
    int max_depth = 48;  // below bvh_stack_size, so the traversal's stack cannot overflow
    int bins = 12;       // pbrt's twelve buckets: within a few percent of testing every plane
    BvhSplit split = BvhSplit::sah;
};

struct BvhStats {
    int nodes = 0, leaves = 0, depth = 0;
    std::size_t bytes = 0;
    double build_seconds = 0.0;
};

class BvhAccel final : public Accelerator {
public:
    BvhAccel(const Objects& objects, const BvhSettings& settings = {}) : settings_(settings)
    {
        if (settings.max_depth < 0 || settings.max_depth >= bvh_stack_size - 1)
            throw InputError("--max-depth must be between 0 and " + std::to_string(bvh_stack_size - 2) + ", got " +
                             std::to_string(settings.max_depth));
        build(objects);
    }

    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        return bvh_query(bvh_, ray, range, objects, /*any_hit=*/false, hit);
    }

    bool any(const Ray& ray, Interval range, const Objects& objects) const override
    {
        ObjectHit hit;
        return bvh_query(bvh_, ray, range, objects, /*any_hit=*/true, hit);
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
    // The most objects a leaf can count (BvhNode::count is 16 bits): a larger group that 10.3 would
    // keep whole (or whose boxes all share one centre) is halved instead.
    static constexpr int max_leaf = std::numeric_limits<std::uint16_t>::max();

    void build(const Objects& objects)
    {
        const Timer timer;
        const int n = objects.size();
        boxes_.resize(static_cast<std::size_t>(n));
        centres_.resize(static_cast<std::size_t>(n));
        // Each box grown by chapter 07's margin (grid_margin_of): a hit's t carries its test's
        // rounding, which can put the hit point a little outside the object's own box (a ray leaving
        // a plane at a grazing angle, a triangle far larger than its distance from the ray's origin);
        // brute force reports such a hit, and the BVH must find it too.
        const float margin = n > 0 ? grid_margin_of(bounds_of_all(objects)) : 0.0f;
        for (int k = 0; k < n; ++k) {
            boxes_[k] = grown(objects.bounds(k), margin);
            centres_[k] = boxes_[k].centre();
        }
        bvh_.object_index.resize(static_cast<std::size_t>(n));
        std::iota(bvh_.object_index.begin(), bvh_.object_index.end(), 0u);
        if (n > 0)
            build_node(0, n, 0);
        stats_.nodes = static_cast<int>(bvh_.nodes.size());
        stats_.bytes = bvh_.nodes.size() * sizeof(BvhNode) + bvh_.object_index.size() * sizeof(std::uint32_t);
        stats_.build_seconds = timer.seconds();
        boxes_ = {};
        centres_ = {};
    }

    // Builds the node for object_index[begin, end) at the end of the array; returns its number.
    std::uint32_t build_node(int begin, int end, int depth)
    {
        const auto self = static_cast<std::uint32_t>(bvh_.nodes.size());
        bvh_.nodes.push_back({});
        stats_.depth = std::max(stats_.depth, depth);
        Bounds box, centres;
        for (int i = begin; i < end; ++i) {
            box.grow(boxes_[bvh_.object_index[i]]);
            centres.grow(centres_[bvh_.object_index[i]]);
        }
        const int n = end - begin;
        const vec3 spread = centres.extent();
        const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;

        int middle = -1;  // where the objects split, or -1: a leaf
        if (settings_.split == BvhSplit::median) {
            if (n > settings_.leaf_size && depth < settings_.max_depth)
                middle = median_split(begin, end, axis);
        } else if (spread[axis] > 0.0f) {
            std::vector<SahBin> bins(static_cast<std::size_t>(settings_.bins));
            const auto bin_of = [&](std::uint32_t k) {
                const float f = (centres_[k][axis] - centres.min[axis]) / spread[axis];
                return std::min(settings_.bins - 1, static_cast<int>(f * static_cast<float>(settings_.bins)));
            };
            for (int i = begin; i < end; ++i) {
                SahBin& bin = bins[bin_of(bvh_.object_index[i])];
                ++bin.count;
                bin.bounds.grow(boxes_[bvh_.object_index[i]]);
            }
            const SahSplit best = best_split(box, bins);
            if (!make_leaf(n, depth, settings_.leaf_size, settings_.max_depth, best.cost) && best.split >= 0 &&
                best.split + 1 < settings_.bins) {
                const auto mid = std::partition(bvh_.object_index.begin() + begin, bvh_.object_index.begin() + end,
                                                [&](std::uint32_t k) { return bin_of(k) <= best.split; });
                middle = static_cast<int>(mid - bvh_.object_index.begin());
                if (middle == begin || middle == end)
                    middle = -1;  // a student's 10.2 chose a plane with an empty side
            }
        }
        // Too many for one leaf (all at one centre, or a student's 10.3 keeping everything): halved
        // in the objects' order.
        if (middle < 0 && n > max_leaf)
            middle = begin + n / 2;
        // Whatever 10.3 says, a path stays within the traversal's stack.
        if (depth >= bvh_stack_size - 2 && n <= max_leaf)
            middle = -1;
        if (middle < 0) {
            bvh_.nodes[self] = {box.min, static_cast<std::uint32_t>(begin), box.max, static_cast<std::uint16_t>(n), 0};
            ++stats_.leaves;
            return self;
        }
        build_node(begin, middle, depth + 1);
        const std::uint32_t second = build_node(middle, end, depth + 1);
        bvh_.nodes[self] = {box.min, second, box.max, 0, static_cast<std::uint16_t>(axis)};
        return self;
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

    BvhSettings settings_;
    Bvh bvh_;
    BvhStats stats_;
    std::vector<Bounds> boxes_;
    std::vector<point3> centres_;
};

}  // namespace rt
