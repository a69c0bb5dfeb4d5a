#include "common/polygon.hpp"

#include "common/error.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace rt {

namespace {

// The corners are floats, exact as read: the polygon is the one they give. Every distance below is
// worked out in double from them, each step rounding by at most 2^-53 of the magnitudes it combines
// (the standard model: pbrt-v4 sec. 6.8.1). A distance below this many such roundings of the
// polygon's largest coordinate is what those computations cannot tell from 0: two vertices that
// close are one vertex, a vertex that close to another edge touches it. Sized on double's rounding,
// not float's: two distinct float corners are at least a float step apart, 2^29 times more, so a
// mesh finer than float's steps at its distance from the origin (a ball 0.1 across at x = 1000,
// triangles 1e-5 across at 10) keeps every corner and every triangle.
constexpr double noise_roundings = 16.0;
constexpr double double_rounding = 0x1p-53;

// What the file meant, which float only approximates: a float read from a decimal number is off by
// up to half a unit in its last place, 2^-24 of its size, and a polygon off the coordinate planes
// is projected onto one, off by a few more. A vertex meant to lie on the line between its
// neighbours lies within a few such roundings of it; within straight_roundings, the ear clipper
// keeps it as a corner of later triangles instead of cutting it off as a sliver whose winding the
// rounding decides. Within touch_roundings of an ear's border, a vertex counts as on it and keeps
// the ear from being cut (a vertex on the new edge would leave a T-junction); far fewer, since a
// vertex a little more off the new edge of a long thin ear is really outside. Both are preferences:
// where they leave no ear to cut (a polygon not much larger than these roundings), the clipper
// drops them and decides on the float corners as they are.
constexpr double float_rounding = 0x1p-24;
constexpr double straight_roundings = 16.0;
constexpr double touch_roundings = 2.0;

// The area vector's rounding: each corner's difference from the first rounds once by 2^-53 of
// itself, each product of two such differences once more, and the sum of two products and of the
// n - 2 cross products once a step: at most n + 2 roundings of the sum of the products' magnitudes
// (pbrt-v4 sec. 6.8.1's gamma(n)). An area vector no longer than that bound is one double cannot
// tell from 0: the polygon has no area. Above it the polygon is kept, however small or far out.
double gamma_double(std::size_t n) { return n * double_rounding / (1.0 - n * double_rounding); }

// NFF polygons are planar; files printed with C's "%g" keep six significant digits, a relative
// rounding of up to 5e-6 of each coordinate. A vertex farther from the polygon's plane than 1% of
// the polygon's size plus that printing noise is a mistake in the file (a mistyped coordinate),
// not rounding.
constexpr double planarity_tolerance = 1e-2;
constexpr double printed_rounding = 1e-5;

// How far the triangles' total area may stray from the polygon's, relative to it: the sum of a few
// thousand double-precision triangle areas, far above their rounding, far below a missing triangle.
constexpr double area_sum_tolerance = 1e-6;

using dvec2 = glm::dvec2;

double cross2(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }

// Signed distance of p from the line through a and b, positive to the left of a -> b.
// Zero when a and b coincide (the caller treats a zero-length line as "on it").
double side(const dvec2& a, const dvec2& b, const dvec2& p)
{
    const double length = glm::length(b - a);
    return length > 0.0 ? cross2(b - a, p - a) / length : 0.0;
}

std::string vertex_name(std::size_t index) { return "vertex " + std::to_string(index + 1); }

// The polygon after merging repeated vertices, in 2D, counterclockwise, with each vertex's index
// in the caller's list.
struct Outline {
    std::vector<dvec2> q;
    std::vector<std::size_t> original;
    double noise = 0.0;     // distances up to this are 0 (see noise_roundings)
    double straight = 0.0;  // a vertex this close to its neighbours' line is on it (see straight_roundings)
    double touch = 0.0;     // a vertex this close to an ear's border is on it (see touch_roundings)
};

// Projects onto the coordinate plane most nearly parallel to the polygon (drops the normal's largest
// axis), choosing the two remaining axes' order so the polygon runs counterclockwise in 2D.
dvec2 project(const dvec3& p, int drop, bool swap)
{
    const double a = p[(drop + 1) % 3];
    const double b = p[(drop + 2) % 3];
    return swap ? dvec2(b, a) : dvec2(a, b);
}

double distance_to_segment(const dvec2& p, const dvec2& a, const dvec2& b)
{
    const dvec2 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double s = length2 > 0.0 ? glm::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * ab));
}

// A simple polygon: no two edges that do not share a vertex cross or touch. Ear clipping covers a
// simple polygon exactly; an outline that touches itself (a vertex on another edge, an edge run
// twice) could be covered twice over with the area still adding up, so it is refused.
void check_simple(const Outline& f)
{
    const std::size_t m = f.q.size();
    std::vector<dvec2> lo(m), hi(m);
    for (std::size_t i = 0; i < m; ++i) {
        lo[i] = glm::min(f.q[i], f.q[(i + 1) % m]) - f.noise;
        hi[i] = glm::max(f.q[i], f.q[(i + 1) % m]) + f.noise;
    }
    const auto edges = [&](std::size_t i, std::size_t j) {
        return "edges " + std::to_string(f.original[i] + 1) + " and " + std::to_string(f.original[j] + 1);
    };
    for (std::size_t i = 0; i < m; ++i) {
        const dvec2& a = f.q[i];
        const dvec2& b = f.q[(i + 1) % m];
        for (std::size_t j = i + 2; j < m; ++j) {
            if (i == 0 && j == m - 1)
                continue;  // adjacent through the closing edge
            if (hi[i].x < lo[j].x || hi[j].x < lo[i].x || hi[i].y < lo[j].y || hi[j].y < lo[i].y)
                continue;
            const dvec2& c = f.q[j];
            const dvec2& d = f.q[(j + 1) % m];
            const double c_side = side(a, b, c), d_side = side(a, b, d);
            const double a_side = side(c, d, a), b_side = side(c, d, b);
            const bool ab_splits_cd = (c_side > f.noise && d_side < -f.noise) || (c_side < -f.noise && d_side > f.noise);
            const bool cd_splits_ab = (a_side > f.noise && b_side < -f.noise) || (a_side < -f.noise && b_side > f.noise);
            if (ab_splits_cd && cd_splits_ab)
                throw InputError(edges(i, j) + " cross (NFF polygons are simple)");
            // Not across each other: they meet only if an end of one lies on the other.
            if (std::min({distance_to_segment(a, c, d), distance_to_segment(b, c, d), distance_to_segment(c, a, b),
                          distance_to_segment(d, a, b)}) <= f.noise)
                throw InputError(edges(i, j) + " touch (NFF polygons are simple)");
        }
    }
}

// Ear clipping over a doubly linked ring of the polygon's vertices.
class EarClipper {
public:
    explicit EarClipper(const Outline& f) : f_(f), m_(f.q.size()), prev_(m_), next_(m_), kind_(m_), ear_(m_)
    {
        for (std::size_t i = 0; i < m_; ++i) {
            prev_[i] = (i + m_ - 1) % m_;
            next_[i] = (i + 1) % m_;
        }
        remaining_ = m_;
        classify_all(0);
    }

    std::vector<TriangleIndices> run()
    {
        std::vector<TriangleIndices> triangles;
        triangles.reserve(m_ - 2);
        std::size_t cur = 0;
        std::size_t without_progress = 0;
        bool reclassified = false;
        while (remaining_ > 3) {
            if (kind_[cur] == Kind::degenerate || ear_[cur]) {
                if (kind_[cur] != Kind::degenerate)
                    triangles.push_back({f_.original[prev_[cur]], f_.original[cur], f_.original[next_[cur]]});
                const std::size_t after = next_[cur];
                remove(cur);
                cur = after;
                without_progress = 0;
                reclassified = false;
                continue;
            }
            cur = next_[cur];
            if (++without_progress <= remaining_)
                continue;
            // A full turn found no ear. In exact arithmetic a simple polygon always has one; here,
            // first look again with fresh statuses (in case rounding left one stale), then drop the
            // preferences: corners within straight_roundings of straight may be ears, and vertices
            // within touch_roundings of an ear's border no longer block it (thin triangles, but
            // triangles).
            without_progress = 0;
            if (!reclassified) {
                reclassified = true;
                classify_all(cur);
            } else if (straight_tolerance_ > 0.0 || touch_ > 0.0) {
                straight_tolerance_ = 0.0;
                touch_ = 0.0;
                classify_all(cur);
            } else {
                // What is left is no wider than noise (the final area check measures it), or the
                // polygon's edges touch.
                return triangles;
            }
        }
        // The last three corners are a triangle unless exactly straight: nothing is left to keep
        // a nearly straight corner for.
        straight_tolerance_ = 0.0;
        if (classify_kind(cur) == Kind::convex)
            triangles.push_back({f_.original[prev_[cur]], f_.original[cur], f_.original[next_[cur]]});
        return triangles;
    }

private:
    // convex: the interior angle is below 180 degrees; reflex: above; straight: the vertex lies on
    // the line between its neighbours (180 degrees), within rounding noise. It stays, and becomes a
    // corner of a triangle later: removing it would leave a T-junction, where a neighbouring
    // triangle's corner lies on an edge, and rays can slip through the crack between; cutting it off
    // as an ear would make a sliver whose winding rounding decides. degenerate: the vertex sits on a
    // neighbour, or the outline turns back on itself there (a spike of no width); removing it
    // changes no area.
    enum class Kind { convex, reflex, straight, degenerate };

    Kind classify_kind(std::size_t i) const
    {
        const dvec2& a = f_.q[prev_[i]];
        const dvec2& b = f_.q[i];
        const dvec2& c = f_.q[next_[i]];
        if (glm::length(b - c) <= f_.noise || glm::length(b - a) <= f_.noise || glm::length(c - a) <= f_.noise)
            return Kind::degenerate;
        const double height = side(a, c, b);  // negative: b lies right of a -> c, a convex corner
        const bool forward = glm::dot(b - a, c - b) > 0.0;
        // Only an exact reversal is a spike of no width. A sharp turn within noise of the line is
        // not: beside a long edge, a triangle thinner than noise still has area.
        if (height == 0.0 && !forward)
            return Kind::degenerate;
        if (std::abs(height) <= straight_tolerance_ && forward)
            return Kind::straight;
        return height < 0.0 ? Kind::convex : Kind::reflex;
    }

    // An ear: a convex vertex whose triangle with its neighbours holds no other vertex, not even on
    // its border (a vertex on the new edge would make a T-junction). Only vertices that are not
    // convex can lie there (of the vertices inside, the one farthest from the
    // new edge is reflex), so only they are tested; and since clipping an ear changes only its neighbours' corners, an
    // ear status once computed stays right until a neighbour is clipped (Eberly, "Triangulation by
    // Ear Clipping", Geometric Tools).
    bool is_ear(std::size_t i) const
    {
        if (kind_[i] != Kind::convex)
            return false;
        const std::size_t ia = prev_[i], ic = next_[i];
        const dvec2 &a = f_.q[ia], &b = f_.q[i], &c = f_.q[ic];
        for (std::size_t j = next_[ic]; j != ia; j = next_[j]) {
            if (kind_[j] == Kind::convex)
                continue;
            const dvec2& p = f_.q[j];
            if (glm::length(p - a) <= f_.noise || glm::length(p - b) <= f_.noise || glm::length(p - c) <= f_.noise)
                continue;  // the same point as a corner of the ear: it cannot lie inside
            // Counterclockwise corners a, b, c: inside or on the border is left of or on every edge.
            if (side(a, b, p) >= -touch_ && side(b, c, p) >= -touch_ && side(c, a, p) >= -touch_)
                return false;
        }
        return true;
    }

    // Every remaining vertex, going round from `start` (one that is still in the ring).
    void classify_all(std::size_t start)
    {
        std::size_t i = start;
        for (std::size_t k = 0; k < remaining_; ++k, i = next_[i])
            kind_[i] = classify_kind(i);
        for (std::size_t k = 0; k < remaining_; ++k, i = next_[i])
            ear_[i] = is_ear(i);
    }

    void remove(std::size_t i)
    {
        const std::size_t a = prev_[i], c = next_[i];
        next_[a] = c;
        prev_[c] = a;
        --remaining_;
        if (remaining_ < 3)
            return;
        // Only the neighbours' corners changed.
        kind_[a] = classify_kind(a);
        kind_[c] = classify_kind(c);
        ear_[a] = is_ear(a);
        ear_[c] = is_ear(c);
    }

    const Outline& f_;
    std::size_t m_, remaining_;
    std::vector<std::size_t> prev_, next_;
    std::vector<Kind> kind_;
    std::vector<bool> ear_;
    double straight_tolerance_ = f_.straight;
    double touch_ = f_.touch;
};

}  // namespace

dvec3 polygon_area_vector(const std::vector<point3>& vertices)
{
    // Relative to the first vertex, so far from the origin the products stay small.
    dvec3 sum(0.0);
    if (vertices.empty())
        return sum;
    const dvec3 origin(vertices[0]);
    for (std::size_t i = 1; i + 1 < vertices.size(); ++i)
        sum += glm::cross(dvec3(vertices[i]) - origin, dvec3(vertices[i + 1]) - origin);
    return sum;
}

PolygonTriangles triangulate_polygon(const std::vector<point3>& vertices)
{
    const std::size_t n = vertices.size();
    if (n < 3)
        throw InputError("needs at least 3 vertices, got " + std::to_string(n));
    if (n > polygon_max_vertices)
        throw InputError("has " + std::to_string(n) + " vertices; the reader takes at most " +
                         std::to_string(polygon_max_vertices));

    // The polygon's size and what double cannot tell from 0 at its coordinates.
    dvec3 lo(vertices[0]), hi(vertices[0]);
    for (const point3& v : vertices) {
        lo = glm::min(lo, dvec3(v));
        hi = glm::max(hi, dvec3(v));
    }
    const double size = glm::length(hi - lo);
    const double magnitude = std::max(glm::length(lo), glm::length(hi));
    const double noise = noise_roundings * double_rounding * magnitude;

    // Repeated vertices (a polygon closed by repeating its first vertex, say) are one vertex.
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < n; ++i)
        if (kept.empty() || glm::length(dvec3(vertices[i]) - dvec3(vertices[kept.back()])) > noise)
            kept.push_back(i);
    while (kept.size() > 1 && glm::length(dvec3(vertices[kept.back()]) - dvec3(vertices[kept.front()])) <= noise)
        kept.pop_back();
    if (kept.size() < 3)
        throw DegeneratePolygon("has fewer than 3 distinct vertices (its corners coincide)");

    std::vector<point3> distinct;
    for (const std::size_t i : kept)
        distinct.push_back(vertices[i]);
    const dvec3 area_vector = polygon_area_vector(distinct);
    const double area = 0.5 * glm::length(area_vector);
    // The area vector's rounding (gamma_double above), and the fan's areas without their signs.
    dvec3 products(0.0);
    double unsigned_area = 0.0;
    for (std::size_t k = 1; k + 1 < distinct.size(); ++k) {
        const dvec3 u = dvec3(distinct[k]) - dvec3(distinct[0]), v = dvec3(distinct[k + 1]) - dvec3(distinct[0]);
        const dvec3 au = glm::abs(u), av = glm::abs(v);
        products += dvec3(au.y * av.z + au.z * av.y, au.z * av.x + au.x * av.z, au.x * av.y + au.y * av.x);
        unsigned_area += 0.5 * glm::length(glm::cross(u, v));
    }
    const double rounding = 0.5 * gamma_double(distinct.size() + 2) * glm::length(products);
    if (!(area > rounding)) {
        if (!(unsigned_area > rounding))
            throw DegeneratePolygon("its vertices all lie on one line (no area)");
        throw DegeneratePolygon("its parts wind opposite ways and their areas cancel (a bowtie: no area)");
    }
    double perimeter = 0.0;
    for (std::size_t k = 0; k < distinct.size(); ++k)
        perimeter += glm::length(dvec3(distinct[(k + 1) % distinct.size()]) - dvec3(distinct[k]));
    const dvec3 normal = area_vector / (2.0 * area);

    // Planar: every vertex near the plane through the vertices' centroid.
    dvec3 centroid(0.0);
    for (const point3& v : distinct)
        centroid += dvec3(v);
    centroid /= static_cast<double>(distinct.size());
    const double plane_tolerance = planarity_tolerance * size + printed_rounding * magnitude + noise;
    for (std::size_t k = 0; k < distinct.size(); ++k) {
        const double off = std::abs(glm::dot(dvec3(distinct[k]) - centroid, normal));
        if (off > plane_tolerance) {
            std::ostringstream message;
            message << vertex_name(kept[k]) << " lies " << off << " off the plane of the others (NFF polygons are planar)";
            throw InputError(message.str());
        }
    }

    Outline outline;
    outline.noise = noise;
    outline.straight = straight_roundings * float_rounding * magnitude;
    outline.touch = touch_roundings * float_rounding * magnitude;
    outline.original = kept;
    const dvec3 a = glm::abs(normal);
    const int drop = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    const bool swap = normal[drop] < 0.0;
    for (const point3& v : distinct)
        outline.q.push_back(project(dvec3(v), drop, swap));

    check_simple(outline);

    PolygonTriangles result;
    result.normal = normal;
    result.area = area;
    result.triangles = EarClipper(outline).run();

    // The contract, checked: the triangles add up to the polygon. Ears lie inside the polygon, so
    // the same total area means they cover it exactly; a shortfall (a remainder no ear could cut)
    // is refused rather than drawn with a hole. Compared in the plane of projection, where a
    // polygon slightly off planar still adds up.
    double covered = 0.0, enclosed = 0.0;
    for (const TriangleIndices& t : result.triangles) {
        const dvec2 p0 = project(dvec3(vertices[t[0]]), drop, swap);
        covered += 0.5 * cross2(project(dvec3(vertices[t[1]]), drop, swap) - p0,
                                project(dvec3(vertices[t[2]]), drop, swap) - p0);
    }
    for (std::size_t k = 1; k + 1 < outline.q.size(); ++k)
        enclosed += 0.5 * cross2(outline.q[k] - outline.q[0], outline.q[k + 1] - outline.q[0]);
    if (std::abs(covered - enclosed) > area_sum_tolerance * enclosed + noise * perimeter)
        throw InputError("could not be cut into triangles (do its edges touch or overlap?)");
    return result;
}

}  // namespace rt
