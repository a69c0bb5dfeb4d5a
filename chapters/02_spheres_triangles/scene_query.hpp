// The scene's two queries, the slides' QueryScene: the closest hit along a ray, and whether
// anything at all lies along it (a shadow feeler needs only that). Each takes the accelerator that
// answers it; brute force, which tests every object, is the default until chapter 07.
//
// The rules every accelerator keeps, so that all of them render brute force's image byte for byte:
//   - a hit counts only with t strictly inside the query's range (Interval::surrounds);
//   - the closest hit is the least t, and on an exact tie in t the lower object number wins (brute
//     force, testing in order with a range open at its end, keeps the first);
//   - a ray with a NaN or infinite component hits nothing.
// An accelerator is chosen once per query (one virtual call per ray); inside it the objects are
// tested by number through Objects::intersect, with no virtual call per object.
#pragma once

#include "02_spheres_triangles/objects.hpp"

#include <cmath>
#include <cstddef>
#include <ostream>

namespace rt {

class Accelerator {
public:
    virtual ~Accelerator() = default;

    // The nearest hit with t inside `range` (ties to the lower object number): true, with `hit`
    // filled in, or false when the ray hits nothing there.
    virtual bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const = 0;

    // Whether any object is hit with t inside `range`; it may stop at the first one it finds.
    virtual bool any(const Ray& ray, Interval range, const Objects& objects) const = 0;

    // What it holds beyond the objects themselves, for --stats and the trade tables.
    virtual std::size_t bytes() const = 0;

    // Its lines of --stats (name=value, one a line): its shape, what it holds and what its build
    // cost. Each structure says its own, so a program prints whichever it was given.
    virtual void report(std::ostream& out) const { out << "bytes=" << bytes() << '\n'; }
};

// The range an object must be hit in to beat the best hit so far: up to best.t, and for an object
// with a lower number than best's, up to and including best.t (it wins the tie). An accelerator
// that meets objects out of order asks with this range; brute force, in order, needs only best.t.
inline Interval closer_than(Interval range, const ObjectHit& best, int object)
{
    if (best.object >= 0)
        range.max = object < best.object ? next_up(best.t) : best.t;
    return range;
}

// The slides' QueryScene: every object, in order.
class BruteForce final : public Accelerator {
public:
    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        bool found = false;
        for (int k = 0; k < objects.size(); ++k)
            if (objects.intersect(k, ray, range, hit)) {
                range.max = hit.t;  // later objects count only when nearer
                found = true;
            }
        return found;
    }

    bool any(const Ray& ray, Interval range, const Objects& objects) const override
    {
        ObjectHit hit;
        for (int k = 0; k < objects.size(); ++k)
            if (objects.intersect(k, ray, range, hit))
                return true;
        return false;
    }

    std::size_t bytes() const override { return 0; }
};

inline const Accelerator& brute_force()
{
    static const BruteForce brute;
    return brute;
}

}  // namespace rt
