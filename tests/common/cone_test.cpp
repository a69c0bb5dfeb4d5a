// The open cone and cylinder, NFF's `c` (chapters/02_spheres_triangles/cone.hpp): the side between
// the two discs and nothing else, a t as accurate as a float can hold even 1e4 units away, and the
// side's normal and nearest point.
#include "02_spheres_triangles/cone.hpp"
#include "tests/grader/graded.hpp"

#include <glm/mat3x3.hpp>

#include <cfloat>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace rt;
using rt::grader::rel_error;

namespace {

using rt::grader::show;

std::string show(const Cone& c)
{
    std::ostringstream s;
    s.precision(9);
    s << "cone from " << show(c.base) << " radius " << c.base_radius << " to " << show(c.apex) << " radius "
      << c.apex_radius;
    return s.str();
}

// A cylinder of radius 1 around the y axis, 0 <= y <= 2.
const Cone cylinder{{0, 0, 0}, 1.0f, {0, 2, 0}, 1.0f};
// A pointed cone: radius 1 at y = 0 down to 0 at the apex (0, 1, 0); its mirror nappe is y > 1.
const Cone pointed{{0, 0, 0}, 1.0f, {0, 1, 0}, 0.0f};

void check_hit(const Ray& ray, const Cone& cone, double expected, double tolerance = 1e-6)
{
    const std::optional<float> t = hit_cone(ray, cone, Interval{});
    INFO(show(ray) << ", " << show(cone) << ": expected t " << expected << ", got " << show(t));
    REQUIRE(t);
    CHECK(rel_error(*t, expected) <= tolerance);
}

void check_miss(const Ray& ray, const Cone& cone)
{
    const std::optional<float> t = hit_cone(ray, cone, Interval{});
    INFO(show(ray) << ", " << show(cone) << ": expected no hit, got " << show(t));
    CHECK_FALSE(t);
}

// Uniform in [lo, hi) from the generator's raw bits: std's distributions differ between standard
// libraries, and the cases must be the same everywhere.
float uniform(std::mt19937& rng, float lo, float hi)
{
    return lo + (hi - lo) * float(rng() >> 8) * 0x1p-24f;
}

vec3 random_unit(std::mt19937& rng)
{
    for (;;) {
        const vec3 v(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
        const float length2 = glm::dot(v, v);
        if (length2 > 0.01f && length2 <= 1.0f)
            return v / std::sqrt(length2);
    }
}

// Random cones within a few units of centre: a quarter each cylinders, pointed at the apex, pointed at
// the base, and neither.
Cone random_cone(std::mt19937& rng, const point3& centre)
{
    Cone c;
    c.base = centre + vec3(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
    c.apex = c.base + uniform(rng, 0.3f, 3.0f) * random_unit(rng);
    c.base_radius = uniform(rng, 0.05f, 1.5f);
    c.apex_radius = uniform(rng, 0.05f, 1.5f);
    const std::uint32_t kind = rng() % 4;
    if (kind == 0)
        c.apex_radius = c.base_radius;
    else if (kind == 1)
        c.apex_radius = 0.0f;
    else if (kind == 2)
        c.base_radius = 0.0f;
    return c;
}

// The side in double, to measure the function's float answers against.
struct Frame {
    dvec3 base, k;
    double H, r_b, s;
};

Frame frame(const Cone& c)
{
    const dvec3 axis = dvec3(c.apex) - dvec3(c.base);
    const double H = glm::length(axis);
    return {dvec3(c.base), axis / H, H, double(c.base_radius), (double(c.apex_radius) - c.base_radius) / H};
}

// A point of the side: height h, radial direction rho (unit, across the axis).
dvec3 side_point(const Frame& f, double h, const dvec3& rho)
{
    return f.base + h * f.k + (f.r_b + f.s * h) * rho;
}

// A unit direction across the axis at angle phi.
dvec3 across(const Frame& f, double phi)
{
    const dvec3 u = glm::normalize(glm::cross(f.k, std::abs(f.k.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    return std::cos(phi) * u + std::sin(phi) * glm::cross(f.k, u);
}

// The distance of p from the side's infinite surface, along the normal of its meridian line, for
// p between the discs.
double distance_to_side(const Cone& cone, const vec3& p)
{
    const Frame f = frame(cone);
    const dvec3 d = dvec3(p) - f.base;
    const double h = glm::dot(d, f.k);
    return std::abs(glm::length(d - h * f.k) - (f.r_b + f.s * h)) / std::sqrt(1.0 + f.s * f.s);
}

double ulp(double x)
{
    const float a = std::abs(static_cast<float>(x));
    return std::nextafter(a, FLT_MAX) - a;
}

double max_abs(const vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// The reference: in long double, the line's roots on the whole double cone (both nappes, any h) by
// the textbook quadratic formula, each polished by Newton's method on F(t) = |x_perp|^2 - r(h)^2
// evaluated at the point x itself, where nothing of size D^2 cancels, with about 11 more bits. It
// shares hit_cone's model of the side (the same a, b, c from the same frame), so it checks the
// roots, the precision and the choice of root, not the model: the analytic cases above check that.
using ld = long double;
using lvec3 = glm::vec<3, long double>;

struct RefRoot {
    ld t, h;
};

std::vector<RefRoot> reference_roots(const Ray& ray, const Cone& cone)
{
    const lvec3 base(cone.base), axis = lvec3(cone.apex) - base;
    const ld H = glm::length(axis);
    const lvec3 k = axis / H;
    const ld r_b = cone.base_radius, s = (ld(cone.apex_radius) - ld(cone.base_radius)) / H;
    const lvec3 E(ray.origin), V(ray.dir);
    const ld V_k = glm::dot(V, k);
    const lvec3 V_perp = V - V_k * k;

    const lvec3 f = E - base;
    const ld f_k = glm::dot(f, k);
    const lvec3 f_perp = f - f_k * k;
    const ld A = glm::dot(V_perp, V_perp) - s * s * V_k * V_k;
    const ld B = 2 * (glm::dot(f_perp, V_perp) - (r_b + s * f_k) * s * V_k);
    const ld C = glm::dot(f_perp, f_perp) - (r_b + s * f_k) * (r_b + s * f_k);
    std::vector<ld> ts;
    if (A == 0) {
        if (B != 0)
            ts.push_back(-C / B);
    } else if (const ld disc = B * B - 4 * A * C; disc >= 0) {
        ts.push_back((-B - std::sqrt(disc)) / (2 * A));
        ts.push_back((-B + std::sqrt(disc)) / (2 * A));
    }
    std::vector<RefRoot> roots;
    for (ld t : ts) {
        ld h = 0;
        for (int i = 0; i < 6; ++i) {
            const lvec3 x = E + t * V - base;
            h = glm::dot(x, k);
            const lvec3 x_perp = x - h * k;
            const ld r = r_b + s * h;
            const ld F = glm::dot(x_perp, x_perp) - r * r;
            const ld dF = 2 * (glm::dot(x_perp, V_perp) - r * s * V_k);
            if (dF == 0)
                break;
            t -= F / dF;
        }
        h = glm::dot(E + t * V - base, k);
        roots.push_back({t, h});
    }
    return roots;
}

// Counts over a batch of rays compared with the reference.
struct Agreement {
    int rays = 0;
    int ambiguous = 0;  // within rounding of the outline, a disc, or range.min: either answer is right
    int hits = 0;
    int wrong = 0;      // hit against miss, or a hit on another wall
    double max_rel_error = 0;
};

// Why 2^-23: the returned t is hit_cone's double t rounded to float, at most 2^-24 relative; the
// double t's own error is about kappa 2^-53 for a root of condition kappa ~ (D / r)^2, under 2^-26
// for D / r <= 1e4 (the distances of chapter 02's sphere table) away from the outline. One more 2^-24 covers it.
constexpr double t_bound = 0x1p-23;

// What every run of random rays must show against the reference: no wrong answer, few rays within
// rounding of an edge, t within t_bound, and at least `min_hit_fraction` of the rays hitting (so
// that a test which always misses cannot pass).
void check_agreement(const std::string& what, const Agreement& a, double min_hit_fraction)
{
    INFO(what << ": " << a.rays << " rays, " << a.hits << " hits, " << a.ambiguous << " ambiguous, " << a.wrong
              << " wrong; max relative error of t " << a.max_rel_error << " (allowed " << t_bound << ")");
    CHECK(a.wrong == 0);
    CHECK(a.hits > min_hit_fraction * a.rays);
    CHECK(a.ambiguous < a.rays / 1000);
    CHECK(a.max_rel_error <= t_bound);
}

// Why 1e-9 of the ray's scale: hit_cone decides in double (about 1e-16 of the scale squared over the
// root's separation), the reference in long double; rays closer than this to the outline, a disc or
// range.min may be decided either way, and are far fewer than 1 in 1000.
constexpr double ambiguity = 1e-9;

void compare(const Ray& ray, const Cone& cone, Agreement& agreement)
{
    ++agreement.rays;
    const Interval range{};
    const std::vector<RefRoot> roots = reference_roots(ray, cone);
    const ld H = glm::length(dvec3(cone.apex) - dvec3(cone.base));
    const ld scale =
        glm::length(dvec3(ray.origin) - dvec3(cone.base)) + H + cone.base_radius + cone.apex_radius;
    const ld speed = glm::length(dvec3(ray.dir));
    std::optional<ld> expected;
    bool ambiguous = roots.size() == 2 && std::abs(roots[0].t - roots[1].t) * speed < ambiguity * scale;
    for (const RefRoot& r : roots) {
        const ld eps = ambiguity * scale;
        if (std::abs(r.h) < eps || std::abs(r.h - H) < eps || std::abs(r.t - range.min) * speed < eps)
            ambiguous = true;
        if (r.h >= 0 && r.h <= H && r.t > range.min && (!expected || r.t < *expected))
            expected = r.t;
    }
    if (ambiguous) {
        ++agreement.ambiguous;
        return;
    }
    const std::optional<float> t = hit_cone(ray, cone, range);
    INFO(show(ray) << ", " << show(cone) << ": expected "
                   << (expected ? std::to_string(double(*expected)) : "no hit") << ", got " << show(t));
    if (bool(t) != bool(expected)) {
        ++agreement.wrong;
        CHECK(bool(t) == bool(expected));
        return;
    }
    if (!t)
        return;
    ++agreement.hits;
    const double error = rel_error(*t, double(*expected));
    agreement.max_rel_error = std::max(agreement.max_rel_error, error);
    CHECK(error <= t_bound);
}

}  // namespace

TEST_CASE("a ray through a cylinder's side hits the near wall at the analytic t", "[common][cone]")
{
    check_hit({{0, 1, -5}, {0, 0, 1}}, cylinder, 4.0);
    // t is in lengths of dir.
    check_hit({{0, 1, -5}, {0, 0, 2}}, cylinder, 2.0);
    check_hit({{0, 1, -5}, {0, 0, 1e-30f}}, cylinder, 4e30);
    // Off centre: the wall is at z = -sqrt(1 - 0.6^2) = -0.8.
    check_hit({{0.6f, 1.5f, -5}, {0, 0, 1}}, cylinder, 4.2);
}

TEST_CASE("a ray along an open cylinder's axis misses: it has no caps", "[common][cone]")
{
    check_miss({{0, -5, 0}, {0, 1, 0}}, cylinder);
    check_miss({{0, 1, 0}, {0, 1, 0}}, cylinder);
    check_miss({{0.5f, 5, 0}, {0, -1, 0}}, cylinder);
    // Through the open top onto the inner wall at x = 1, y = 1.5.
    check_hit({{0, 2.5f, 0}, {1, -1, 0}}, cylinder, 1.0);
}

TEST_CASE("a ray that starts inside the cone hits the far wall", "[common][cone]")
{
    check_hit({{0, 1, 0}, {1, 0, 0}}, cylinder, 1.0);
    check_hit({{0.5f, 1, 0}, {-1, 0, 0}}, cylinder, 1.5);
    // Inside the pointed cone at height 0.5 (radius 0.5).
    check_hit({{0, 0.5f, 0}, {0, 0, -1}}, pointed, 0.5);
}

TEST_CASE("a ray passing above the top disc or below the base misses", "[common][cone]")
{
    // The infinite cylinder would be hit at t = 4 and 6, at heights 2.5 and -0.5.
    check_miss({{0, 2.5f, -5}, {0, 0, 1}}, cylinder);
    check_miss({{0, -0.5f, -5}, {0, 0, 1}}, cylinder);
    // Just inside the discs, the same rays hit.
    check_hit({{0, 1.99f, -5}, {0, 0, 1}}, cylinder, 4.0);
    check_hit({{0, 0.01f, -5}, {0, 0, 1}}, cylinder, 4.0);
}

TEST_CASE("a ray aimed at a pointed cone's mirror nappe beyond the apex misses", "[common][cone]")
{
    // At y = 2 the mirror nappe has radius 1: roots at t = 4 and 6, both with h > H.
    check_miss({{0, 2, -5}, {0, 0, 1}}, pointed);
    // Down at radius 0.2 from the axis: the mirror nappe at y = 1.2 comes first, the cone at y = 0.8.
    const float r = 0.2f;
    check_hit({{r, 5, 0}, {0, -1, 0}}, pointed, 5.0 - (1.0 - double(r)));
}

TEST_CASE("a tangent ray misses", "[common][cone]")
{
    // Touching the cylinder's side at (1, 0.5, 0): a double root.
    check_miss({{1, 0.5f, -5}, {0, 0, 1}}, cylinder);
    // Touching the cone of radius 1 at y = 0 to 0.5 at y = 1 at (0.75, 0.5, 0), along a direction
    // of the tangent plane there that is not the slant line; every number exact, disc exactly 0.
    const Cone frustum{{0, 0, 0}, 1.0f, {0, 1, 0}, 0.5f};
    check_miss({{3.25f, -4.5f, -10}, {-0.5f, 1, 2}}, frustum);
    // Moved a little towards the axis, the same rays cross the side.
    check_hit({{0.999f, 0.5f, -5}, {0, 0, 1}}, cylinder, 5.0 - std::sqrt(1.0 - 0.999 * 0.999), 1e-5);
    CHECK(hit_cone({{3.24f, -4.5f, -10}, {-0.5f, 1, 2}}, frustum, Interval{}));
}

TEST_CASE("a ray parallel to a slant line gets its single hit", "[common][cone]")
{
    // Slant line from (1, 0, 0) to the apex (0, 1, 0); a ray along (-1, 1, 0) makes a = 0 exactly.
    // |(0.5 - t, 0.25)| = 1 - (-0.5 + t) gives t = 0.96875, at radius 0.53125 = r(h = 0.46875).
    const Ray ray{{0.5f, -0.5f, 0.25f}, {-1, 1, 0}};
    check_hit(ray, pointed, 0.96875);
    // The same, turned about an oblique axis: a is now within rounding of 0, not 0.
    const glm::dmat3 turn(dvec3(0.36, 0.48, -0.8), dvec3(-0.8, 0.6, 0), dvec3(0.48, 0.64, 0.6));
    const auto rotate = [&](const vec3& v) { return vec3(turn * dvec3(v)); };
    const Cone turned{rotate(pointed.base), 1.0f, rotate(pointed.apex), 0.0f};
    check_hit({rotate(ray.origin), rotate(ray.dir)}, turned, 0.96875, 1e-5);
}

TEST_CASE("NaN and infinite rays give no hit", "[common][cone]")
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Cone cones[] = {cylinder, pointed, {{1, 2, 3}, 0.5f, {2, 4, 1}, 1.5f}};
    const vec3 bad[] = {{nan, 0, 0}, {0, nan, 0}, {infinity, 0, 0}, {0, 0, -infinity},
                        {infinity, infinity, infinity}};
    for (const Cone& cone : cones)
        for (const vec3& v : bad) {
            check_miss({v, {0, 0, 1}}, cone);
            check_miss({{0, 1, -5}, v}, cone);
            check_miss({{0, 1, -5}, vec3(0, 0, 1) + v}, cone);
        }
    // A zero direction meets nothing either.
    check_miss({{0, 1, -5}, {0, 0, 0}}, cylinder);
}

TEST_CASE("random rays against random cones agree with a long double reference", "[common][cone]")
{
    std::mt19937 rng(20240611u);
    Agreement agreement;
    for (int i = 0; i < 200000; ++i) {
        const Cone cone = random_cone(rng, point3(0));
        // From up to 8 units away (some inside the cone), aimed within 2 units of the cone's middle;
        // directions of any length.
        const point3 origin = vec3(uniform(rng, -8, 8), uniform(rng, -8, 8), uniform(rng, -8, 8));
        const point3 target = 0.5f * (cone.base + cone.apex) + 2.0f * random_unit(rng) * uniform(rng, 0, 1);
        const vec3 dir = glm::normalize(target - origin) * uniform(rng, 0.1f, 10.0f);
        compare({origin, dir}, cone, agreement);
    }
    check_agreement("random rays at random cones", agreement, 0.25);
}

TEST_CASE("a cone 1e4 units away is still hit with an accurate t", "[common][cone]")
{
    // Here the quadratic's c cancels 1e8 against 1e8: the same steps in float get 44% of hit/miss wrong.
    std::mt19937 rng(7u);
    const Cone far{{3000, -1, -1e4f}, 1.0f, {3000.3f, 1, -1e4f + 0.4f}, 0.5f};
    const Frame f = frame(far);
    Agreement aimed, around;
    for (int i = 0; i < 20000; ++i) {
        // Aimed at a point of the side facing the eye: must be hit there.
        const dvec3 to_eye = -f.base - glm::dot(-f.base, f.k) * f.k;
        const dvec3 u = glm::normalize(to_eye), w = glm::cross(f.k, u);
        const double phi = uniform(rng, -1.0f, 1.0f);
        const double h = uniform(rng, 0.1f, 0.9f) * f.H;
        const dvec3 target = side_point(f, h, std::cos(phi) * u + std::sin(phi) * w);
        // One draw a statement, last first, as GCC computes a call's arguments: the rays are the
        // same whatever compiles the test.
        const float ez = uniform(rng, -1, 1), ey = uniform(rng, -1, 1), ex = uniform(rng, -1, 1);
        const point3 eye(ex, ey, ez);
        compare({eye, vec3(glm::normalize(target - dvec3(eye)))}, far, aimed);
        // Aimed anywhere within 2 units of the cone: hit or miss as the reference says.
        const point3 near = 0.5f * (far.base + far.apex) + 2.0f * random_unit(rng) * uniform(rng, 0, 1);
        compare({eye, glm::normalize(near - eye)}, far, around);
    }
    // Every ray aimed at the side hits it, but for those within rounding of an edge (ambiguous).
    INFO("aimed at the side facing the eye: " << aimed.hits << " of " << aimed.rays << " hit, " << aimed.ambiguous
                                              << " within rounding of an edge");
    CHECK(aimed.hits + aimed.ambiguous == aimed.rays);
    check_agreement("aimed at the side facing the eye", aimed, 0.999);
    check_agreement("aimed within 2 units of the cone", around, 0.1);
}

TEST_CASE("the normal is unit, across the slant line and away from the axis", "[common][cone]")
{
    std::mt19937 rng(11u);
    for (int i = 0; i < 10000; ++i) {
        const Cone cone = random_cone(rng, point3(0));
        const Frame f = frame(cone);
        const dvec3 rho = across(f, uniform(rng, 0, 6.2831853f));
        const double h = uniform(rng, 0.05f, 0.95f) * f.H;
        const vec3 n = cone_normal(cone, vec3(side_point(f, h, rho)));
        // The slant line through the point, and the circle's tangent there.
        const dvec3 slant = glm::normalize(side_point(f, f.H, rho) - side_point(f, 0, rho));
        const dvec3 circle = glm::cross(f.k, rho);
        INFO(show(cone) << " at h " << h << ": normal " << show(n));
        CHECK(std::abs(glm::length(n) - 1.0f) <= 1e-6f);
        CHECK(std::abs(glm::dot(dvec3(n), slant)) <= 1e-5);
        CHECK(std::abs(glm::dot(dvec3(n), circle)) <= 1e-5);
        CHECK(glm::dot(dvec3(n), rho) > 0.0);
    }
}

TEST_CASE("the normal at a pointed tip is the axis out of the tip, never NaN", "[common][cone]")
{
    CHECK(cone_normal(pointed, pointed.apex) == vec3(0, 1, 0));
    const Cone down{{0, 1, 0}, 0.0f, {0, 3, 0}, 2.0f};
    CHECK(cone_normal(down, down.base) == vec3(0, -1, 0));
    const Cone oblique{{1, 2, 3}, 1.5f, {-2, 4, 1}, 0.0f};
    const vec3 n = cone_normal(oblique, oblique.apex);
    const vec3 k = glm::normalize(oblique.apex - oblique.base);
    INFO(show(oblique) << ": normal at the apex " << show(n));
    CHECK(glm::length(n - k) <= 1e-6f);
}

TEST_CASE("the surface point keeps a point of the side and moves another point onto it", "[common][cone]")
{
    std::mt19937 rng(13u);
    for (int i = 0; i < 10000; ++i) {
        // Cones near the origin and 1e4 away: "within rounding" scales with the coordinates.
        const Cone cone = random_cone(rng, point3(i % 2 == 0 ? 0.0f : 1e4f, 0, 0));
        const Frame f = frame(cone);
        const dvec3 rho = across(f, uniform(rng, 0, 6.2831853f));
        const double h = uniform(rng, 0.0f, 1.0f) * f.H;
        const point3 on = vec3(side_point(f, h, rho));
        const point3 kept = cone_surface_point(cone, on);
        const double few_ulps = 4 * ulp(max_abs(on));
        INFO(show(cone) << ": point of the side " << show(on) << " -> " << show(kept));
        CHECK(glm::length(dvec3(kept) - dvec3(on)) <= few_ulps);
        CHECK(distance_to_side(cone, kept) <= few_ulps);

        // Off the side, inside or out, and beyond a disc: back onto it, at the clamped height.
        const double across_by = uniform(rng, -0.5f, 0.5f), along_by = uniform(rng, -0.5f, 0.5f);
        const point3 off = on + vec3(across_by * rho + along_by * f.k);
        const point3 moved = cone_surface_point(cone, off);
        const double h_off = std::clamp(glm::dot(dvec3(off) - f.base, f.k), 0.0, f.H);
        INFO("off the side " << show(off) << " -> " << show(moved));
        CHECK(distance_to_side(cone, off) > 0.0);
        CHECK(distance_to_side(cone, moved) <= few_ulps);
        CHECK(std::abs(glm::dot(dvec3(moved) - f.base, f.k) - h_off) <= few_ulps);
    }
}

TEST_CASE("the surface point of a point on the axis is on the side, never NaN", "[common][cone]")
{
    const Cone oblique{{1, 2, 3}, 1.5f, {-2, 4, 1}, 0.5f};
    for (const Cone& cone : {cylinder, pointed, oblique}) {
        for (double u : {0.0, 0.25, 0.5, 1.0}) {
            const Frame f = frame(cone);
            const dvec3 axis_point = f.base + u * f.H * f.k;
            const point3 p = cone_surface_point(cone, vec3(axis_point));
            INFO(show(cone) << ": axis point at h " << u * f.H << " -> " << show(p));
            REQUIRE(std::isfinite(p.x + p.y + p.z));
            CHECK(std::abs(glm::length(dvec3(p) - axis_point) - (f.r_b + f.s * u * f.H)) <= 1e-6);
            CHECK(distance_to_side(cone, p) <= 1e-6);
        }
    }
}
