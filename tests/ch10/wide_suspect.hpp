// Chapter 10's diagnosis of one ray the 4-wide tree answers differently from brute force
// (tests/ch07/suspect.hpp): the four-lane test (10.6) asked again on every block of the tree for
// that ray, each lane held to its contract: it answers as 02.5 answers for its triangle (hit or
// miss, t, V / det and W / det to the bit), a lane without area never hits.
#pragma once

#include "10_hierarchies/wide_bvh.hpp"
#include "tests/ch07/grid_suspect.hpp"

namespace rt::grader::suspect {

inline std::string diagnose_wide(const WideBvh& tree, const Ray& ray, Interval range)
{
    Diagnosis d;
    d.exercised = "10.6 (with the given wide tree and 02.5's test)";
    d.check("10.6", "hit_four_triangles");
    const RayFrame frame = ray_frame(ray);
    for (size_t b = 0; b < tree.blocks.size(); ++b) {
        const FourTriangles& g = tree.blocks[b];
        const FourHits h = hit_four_triangles(g, frame, range);
        if (!h.tested)
            continue;
        for (int i = 0; i < 4; ++i) {
            const bool area = g.with_area >> i & 1u;
            // 02.5's answer for the lane (none for a lane without area), as a flag and its fields.
            const std::optional<TriangleHit<float>> answer =
                area ? hit_triangle_watertight(ray, g.triangle(i), range) : std::optional<TriangleHit<float>>{};
            const bool hits = answer.has_value();
            const TriangleHit<float> want = answer.value_or(TriangleHit<float>{});
            const bool got = h.hit >> i & 1u;
            std::ostringstream s;
            s.precision(9);
            s << "lane " << i << " (object " << g.object[i] << (area ? "" : ", no area") << ") of block " << b << ", t in " << show_range(range) << ": it ";
            if (got)
                s << "hit at t = " << h.t[i] << ", V / det " << h.V[i] / h.det[i] << ", W / det " << h.W[i] / h.det[i];
            else
                s << "missed";
            s << "; its contract promises 02.5's answer, ";
            if (hits)
                s << "a hit at t = " << want.t << ", beta " << want.beta << ", gamma " << want.gamma << " (to the bit)";
            else
                s << (area ? "a miss" : "a miss (a lane without area never hits)");
            if (got != hits || (got && (h.t[i] != want.t || h.V[i] / h.det[i] != want.beta || h.W[i] / h.det[i] != want.gamma))) {
                d.fail("10.6", "hit_four_triangles", s.str());
                return d.text();
            }
        }
    }
    return d.text();
}

}  // namespace rt::grader::suspect
