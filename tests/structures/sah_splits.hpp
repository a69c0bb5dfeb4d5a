// Each split of the SAH build (chapter 10's bvh.hpp) re-derived as the lesson states the binning:
// one Bounds::grow an object, then 10.2's cheapest plane of the three axes. The build bins four
// floats at a time (its boxes in lanes, SSE or plain); a binning that lost or misplaced a box or a
// bin chooses another plane, or puts another set of objects in the first child. 10.2's own
// answers are the reference's on both sides: this checks the binning, not best_split.
#pragma once

#include "10_hierarchies/bvh.hpp"
#include "tests/grader/catch.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace rt::grader {

// The objects under node n, leaf by leaf.
inline void objects_under(const Bvh& bvh, std::uint32_t n, std::vector<std::uint32_t>& out)
{
    const BvhNode& node = bvh.nodes[n];
    if (node.count > 0) {
        out.insert(out.end(), bvh.object_index.begin() + node.first, bvh.object_index.begin() + node.first + node.count);
        return;
    }
    objects_under(bvh, n + 1, out);
    objects_under(bvh, node.first, out);
}

// Checks every inner node of the SAH tree built over `objects` with `settings`; returns how many.
inline int check_sah_splits(const Objects& objects, const BvhSettings& settings, const std::string& name)
{
    const BvhAccel accel(objects, settings);
    const Bvh& bvh = accel.bvh();
    const Margins margins = margins_of(objects);
    const auto box_of = [&](std::uint32_t k) {
        const Bounds own = objects.bounds(static_cast<int>(k));
        return grown(own, margins.of(own));
    };
    int splits = 0;
    for (std::uint32_t n = 0; n < bvh.nodes.size(); ++n) {
        const BvhNode& node = bvh.nodes[n];
        if (node.count > 0)
            continue;
        std::vector<std::uint32_t> held, first;
        objects_under(bvh, n, held);
        objects_under(bvh, n + 1, first);
        Bounds box, centres;
        for (const std::uint32_t k : held) {
            box.grow(box_of(k));
            centres.grow(box_of(k).centre());
        }
        const int count = std::min(settings.bins, 4 + static_cast<int>(held.size()) / 20);
        SahSplit best;
        int best_axis = -1;
        std::vector<std::vector<int>> bin_of(3, std::vector<int>(held.size()));
        for (int a = 0; a < 3; ++a) {
            const float scale = static_cast<float>(count) / centres.extent()[a];
            if (!(scale > 0.0f && scale < infinity))
                continue;
            std::vector<SahBin> bins(static_cast<std::size_t>(count));
            for (std::size_t j = 0; j < held.size(); ++j) {
                const Bounds b = box_of(held[j]);
                bin_of[a][j] = std::min(count - 1, static_cast<int>((b.centre()[a] - centres.min[a]) * scale));
                ++bins[bin_of[a][j]].count;
                bins[bin_of[a][j]].bounds.grow(b);
            }
            const SahSplit s = best_split(box, bins);
            if (s.split >= 0 && s.split + 1 < count && s.cost < best.cost) {
                best = s;
                best_axis = a;
            }
        }
        INFO(name << ", node " << n << " of " << held.size() << " objects: its axis " << node.axis << ", the plane's "
                  << best_axis << " (after bin " << best.split << " of " << count << ", cost " << best.cost << ")");
        REQUIRE(best_axis >= 0);
        CHECK(static_cast<int>(node.axis) == best_axis);
        std::vector<std::uint32_t> want;
        for (std::size_t j = 0; j < held.size(); ++j)
            if (bin_of[best_axis][j] <= best.split)
                want.push_back(held[j]);
        std::sort(want.begin(), want.end());
        std::sort(first.begin(), first.end());
        const auto differ = std::mismatch(want.begin(), want.end(), first.begin(), first.end());
        INFO("the first child holds " << first.size() << " objects, the plane's side " << want.size()
                                      << "; the first that differs: the plane's side "
                                      << (differ.first == want.end() ? std::string("(none)") : std::to_string(*differ.first))
                                      << ", the child "
                                      << (differ.second == first.end() ? std::string("(none)") : std::to_string(*differ.second)));
        CHECK(first == want);
        ++splits;
    }
    return splits;
}

}  // namespace rt::grader
