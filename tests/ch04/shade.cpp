// EXERCISE 04.4: the colour of a hit: ambient, plus every light its feeler reaches.
//
// These cases send their feelers with the given offset along the normal and the given closest-hit
// query, and compare with your own local_shading: they check how shade puts the pieces together,
// so a mistake in 04.1, 04.2 or 04.3 costs points there, not here again.
#include "tests/ch04/describe.hpp"

#include <cmath>
#include <limits>

using namespace rt;
using namespace rt::grader;

namespace {

const FeelerSettings given_feelers{Offset::normal, ShadowQuery::closest_hit};
const PhongMaterial plastic{{0.6f, 0.5f, 0.4f}, color(0.3f), 10.0f};

// A floor of two triangles (y = 0, facing up) in plastic, an ambient light of 0.1, and `lights`.
LitScene floor_scene(const std::vector<PointLight>& lights, const std::vector<Sphere>& spheres = {})
{
    LitScene scene;
    const int m = scene.add_material(plastic);
    for (const Sphere& s : spheres)
        scene.add_sphere(s, m);
    for (const Triangle& t : square_facing_up({0, 0, 0}, 10))
        scene.add_triangle(t, m);
    scene.ambient = color(0.1f);
    scene.lights = lights;
    return scene;
}

// The eye's ray to `target` and its hit, as the figure finds it.
std::pair<Ray, Hit> look_at(const LitScene& scene, const point3& eye, const point3& target)
{
    const Ray ray{eye, glm::normalize(target - eye)};
    const std::optional<Hit> hit = closest_hit(ray, scene, Interval{0.0f, infinity});
    REQUIRE(hit);
    return {ray, *hit};
}

// What one unblocked light adds at the hit, by your local_shading, with the normal facing the eye.
color lit_by(const Ray& ray, const Hit& hit, const vec3& n, const PointLight& light)
{
    const vec3 to_light = light.position - hit.p;
    const float d2 = glm::dot(to_light, to_light);
    return local_shading(plastic, n, -ray.dir, to_light / std::sqrt(d2), light.intensity / d2);
}

std::string describe(const LitScene& scene, const Ray& ray, const Hit& hit)
{
    std::ostringstream s;
    s << show(ray) << " hits " << show(scene) << " at " << show(hit.p) << " (normal " << show(hit.n) << "), "
      << show(plastic) << ", ambient light " << show(scene.ambient) << ", lights";
    for (const PointLight& l : scene.lights)
        s << " at " << show(l.position) << " of intensity " << show(l.intensity);
    return s.str();
}

std::uint64_t shadow_rays()
{
    return total_count(Counter::shadow_rays);
}

}  // namespace

GRADED_TEST("shade: ambient plus local_shading of a light the feeler reaches, the light divided by d^2", "04.4", 3)
{
    for (const PointLight& light : {PointLight{{1, 4, 2}, color(16.0f)}, PointLight{{-3, 1, -1}, {5.0f, 4.0f, 3.0f}},
                                    PointLight{{0.4f, 0.5f, 0.3f}, color(0.2f)}}) {
        const LitScene scene = floor_scene({light});
        const auto [ray, hit] = look_at(scene, {0, 2, 5}, {0.5f, 0, 0.3f});
        const color got = shade(scene, ray, hit, given_feelers);
        const color want = plastic.diffuse * scene.ambient + lit_by(ray, hit, {0, 1, 0}, light);
        INFO(describe(scene, ray, hit) << ": got " << show(got) << ", expected k_d ambient + local_shading(k_d, n, v, l, "
             "intensity / d^2) = " << show(want));
        CHECK(same_colour(got, want));
    }
}

GRADED_TEST("shade: a light whose feeler is blocked leaves only the ambient term; unblocked, it lights", "04.4", 2)
{
    const PointLight light{{0, 6, 0}, color(30.0f)};
    const LitScene scene = floor_scene({light}, {{{0, 3, 0}, 1}});  // a sphere over the floor's centre
    const point3 eye{0, 2, 8};
    {
        const auto [ray, hit] = look_at(scene, eye, {0.1f, 0, 0.2f});  // in the sphere's shadow
        const color got = shade(scene, ray, hit, given_feelers);
        const color want = plastic.diffuse * scene.ambient;
        INFO(describe(scene, ray, hit) << ": got " << show(got) << ", expected the ambient term alone " << show(want)
             << ": the sphere lies between the point and the light");
        CHECK(same_colour(got, want));
    }
    const auto [ray, hit] = look_at(scene, eye, {3.0f, 0, 1.0f});  // beside the shadow
    const color got = shade(scene, ray, hit, given_feelers);
    const color want = plastic.diffuse * scene.ambient + lit_by(ray, hit, {0, 1, 0}, light);
    INFO(describe(scene, ray, hit) << ": got " << show(got) << ", expected " << show(want) << ": nothing lies between");
    CHECK(same_colour(got, want));
}

GRADED_TEST("shade: two lights add up, a light below the floor adds nothing, and only the lights above get a feeler", "04.4", 2)
{
    const PointLight a{{2, 3, 1}, color(9.0f)}, b{{-2, 5, -1}, {4.0f, 8.0f, 12.0f}}, below{{0, -2, 0}, color(50.0f)};
    const LitScene scene = floor_scene({a, below, b});
    const auto [ray, hit] = look_at(scene, {0, 2, 5}, {0.3f, 0, -0.2f});
    reset_counters();
    const color got = shade(scene, ray, hit, given_feelers);
    const std::uint64_t feelers = shadow_rays();
    const color want = plastic.diffuse * scene.ambient + lit_by(ray, hit, {0, 1, 0}, a) + lit_by(ray, hit, {0, 1, 0}, b);
    INFO(describe(scene, ray, hit) << ": got " << show(got) << " after " << feelers << " shadow feelers, expected "
         << show(want) << " after 2 (one per light above the floor)");
    CHECK(same_colour(got, want));
    CHECK(feelers == 2);
}

GRADED_TEST("shade: a triangle seen from its back is shaded with its normal turned toward the eye", "04.4", 2)
{
    // One triangle wound clockwise seen from above: its normal points down, the eye and light are above.
    LitScene scene;
    const int m = scene.add_material(plastic);
    scene.add_triangle({{-5, 0, -5}, {5, 0, -5}, {0, 0, 5}}, m);
    scene.ambient = color(0.1f);
    const PointLight light{{1, 4, 2}, color(16.0f)};
    scene.lights = {light};
    {
        const auto [ray, hit] = look_at(scene, {0, 2, 5}, {0.5f, 0, 0.3f});
        REQUIRE(hit.n.y < 0.0f);
        const color got = shade(scene, ray, hit, given_feelers);
        const color want = plastic.diffuse * scene.ambient + lit_by(ray, hit, {0, 1, 0}, light);
        INFO(describe(scene, ray, hit) << ": got " << show(got) << ", expected " << show(want)
             << ": eye and light are on the same side, so the light falls on the side the eye sees");
        CHECK(same_colour(got, want));
    }
    // From below, the same light lies behind the surface the eye sees.
    const auto [below_ray, below_hit] = look_at(scene, {0, -2, 5}, {0.5f, 0, 0.3f});
    const color dark = shade(scene, below_ray, below_hit, given_feelers);
    INFO(describe(scene, below_ray, below_hit) << ": got " << show(dark) << ", expected the ambient term alone "
         << show(plastic.diffuse * scene.ambient) << ": the light is on the other side");
    CHECK(same_colour(dark, plastic.diffuse * scene.ambient));
}

STABILITY_TEST("shade: never a NaN, with a light exactly at the shaded point or in the surface's plane", "04.4", 1)
{
    const PointLight in_plane{{4, 0, -3}, color(1.0f)}, above{{0, 3, 0}, color(2.0f)};
    LitScene scene = floor_scene({in_plane, above});
    const auto [ray, hit] = look_at(scene, {0, 2, 5}, {0.5f, 0, 0.3f});
    scene.lights.push_back({hit.p, color(1.0f)});  // exactly at the point: d = 0
    const color got = shade(scene, ray, hit, given_feelers);
    const color want = plastic.diffuse * scene.ambient + lit_by(ray, hit, {0, 1, 0}, above);
    INFO(describe(scene, ray, hit) << ": got " << show(got) << ", expected " << show(want)
         << ": the light in the floor's plane and the one at the point itself add nothing");
    REQUIRE((std::isfinite(got.x) && std::isfinite(got.y) && std::isfinite(got.z)));
    CHECK(same_colour(got, want));
}

GRADED_TEST("shade: a light exactly in the surface's plane gets no feeler and adds nothing; a hair above it gets one", "04.4", 1)
{
    // The floor's hit point has y = 0 exactly (its corners do), so a light at y = 0 has n.l = 0:
    // it cannot light the point, and a feeler toward it is a wasted ray. At y = 1e-20 it can.
    for (const auto& [height, feelers] : {std::pair<float, std::uint64_t>{0.0f, 0}, {-1e-20f, 0}, {1e-20f, 1}}) {
        LitScene scene = floor_scene({PointLight{{4, height, -3}, color(5.0f)}});
        const auto [ray, hit] = look_at(scene, {0, 2, 5}, {0.5f, 0, 0.3f});
        REQUIRE(hit.p.y == 0.0f);
        reset_counters();
        const color got = shade(scene, ray, hit, given_feelers);
        const std::uint64_t sent = shadow_rays();
        const color want = plastic.diffuse * scene.ambient + (feelers ? lit_by(ray, hit, {0, 1, 0}, scene.lights[0]) : color(0.0f));
        INFO("shade: " << describe(scene, ray, hit) << ": n.l = " << glm::dot(vec3(0, 1, 0), glm::normalize(scene.lights[0].position - hit.p))
             << "; got " << show(got) << " after " << sent << " shadow feelers, expected " << show(want) << " after "
             << feelers << (feelers ? " (the light is above the floor)" : " (the light is not above the floor)"));
        CHECK(same_colour(got, want));
        CHECK(sent == feelers);
    }
}

GRADED_TEST("shade: passes its feeler settings to light_blocked as they are: with feelers off, a light behind an occluder lights the point", "04.4", 1)
{
    // ShadowQuery::off makes light_blocked answer "not blocked" and count no feeler; default
    // settings in its place would find the sphere and leave the point in shadow.
    const PointLight light{{0, 6, 0}, color(30.0f)};
    const LitScene scene = floor_scene({light}, {{{0, 3, 0}, 1}});
    const auto [ray, hit] = look_at(scene, {0, 2, 8}, {0.1f, 0, 0.2f});  // in the sphere's shadow
    const FeelerSettings off{Offset::robust, ShadowQuery::off};
    reset_counters();
    const color got = shade(scene, ray, hit, off);
    const color want = plastic.diffuse * scene.ambient + lit_by(ray, hit, {0, 1, 0}, light);
    INFO("shade: " << describe(scene, ray, hit) << ", feeler settings with query off (no shadows): got " << show(got) << " after "
         << shadow_rays() << " counted feelers, expected " << show(want)
         << " after 0: the settings go to light_blocked unchanged, and it answers not blocked");
    CHECK(same_colour(got, want));
    CHECK(shadow_rays() == 0);
}

GRADED_TEST("shade: a ray exactly along the surface (n.dir = 0) keeps the hit's normal; one the least bit upward (n.dir = the least float) turns it", "04.4", 1)
{
    // The normal is turned only when n.dir > 0. Along the floor (dir = (1, 0, 0)) it stays up: the
    // light above lights the point, the one below gets no feeler. A ray rising by the least float
    // came from below the floor: the normal turns down, and the light below lights the point.
    const float least = std::numeric_limits<float>::denorm_min();
    const LitScene floor = floor_scene({});
    const Hit found = look_at(floor, {0, 2, 5}, {0.5f, 0, 0.3f}).second;
    REQUIRE(found.p.y == 0.0f);
    const PointLight above{found.p + vec3(1, 4, 2), color(16.0f)}, below{found.p + vec3(-1, -3, 1), color(9.0f)};
    for (const float rise : {0.0f, least}) {
        LitScene scene = floor_scene({above, below});
        const vec3 dir{1.0f, rise, 0.0f};
        const Ray ray{found.p - 3.0f * dir, dir};
        Hit hit = found;
        hit.t = 3.0f;
        const vec3 seen = rise > 0.0f ? vec3(0, -1, 0) : vec3(0, 1, 0);
        reset_counters();
        const color got = shade(scene, ray, hit, given_feelers);
        const std::uint64_t sent = shadow_rays();
        const color want = plastic.diffuse * scene.ambient + lit_by(ray, hit, seen, rise > 0.0f ? below : above);
        INFO("shade: " << describe(scene, ray, hit) << ": n.dir = " << glm::dot(hit.n, ray.dir) << ", so the side seen faces "
             << show(seen) << "; got " << show(got) << " after " << sent << " shadow feelers, expected " << show(want)
             << " after 1 (only the light " << (rise > 0.0f ? "below" : "above") << " the floor lights it)");
        CHECK(same_colour(got, want));
        CHECK(sent == 1);
    }
}

GRADED_TEST("shade: a light exactly at the point gets no feeler; one the least bit away (d^2 = the least float) gets one and lights by intensity / d^2", "04.4", 1)
{
    // At the point there is no direction to the light: it adds nothing and costs no feeler. At
    // d = 2^-74.5 above it (rounded to float), d^2 is the least float, 2^-149, not 0: the light is
    // straight above, and an intensity of 1e-38 arrives as 1e-38 / 2^-149, about 7e6.
    const float d = static_cast<float>(std::ldexp(std::sqrt(2.0), -75));
    const LitScene floor = floor_scene({});
    const auto [ray, hit] = look_at(floor, {0, 2, 5}, {0.5f, 0, 0.3f});
    REQUIRE(hit.p.y == 0.0f);
    for (const float height : {0.0f, d}) {
        const LitScene scene = floor_scene({PointLight{hit.p + vec3(0.0f, height, 0.0f), color(1e-38f)}});
        const vec3 to_light = scene.lights[0].position - hit.p;
        const bool lights = height > 0.0f;
        reset_counters();
        const color got = shade(scene, ray, hit, given_feelers);
        const std::uint64_t sent = shadow_rays();
        const color want = plastic.diffuse * scene.ambient + (lights ? lit_by(ray, hit, {0, 1, 0}, scene.lights[0]) : color(0.0f));
        INFO("shade: " << describe(scene, ray, hit) << ": d^2 = " << glm::dot(to_light, to_light) << "; got " << show(got)
             << " after " << sent << " shadow feelers, expected " << show(want) << " after " << (lights ? 1 : 0)
             << (lights ? " (the light is above the point, however near)" : " (the light is at the point itself)"));
        REQUIRE(glm::dot(to_light, to_light) == (lights ? std::numeric_limits<float>::denorm_min() : 0.0f));
        CHECK(same_colour(got, want));
        CHECK(sent == (lights ? 1u : 0u));
    }
}

GRADED_TEST("shade: a light the least bit above the surface's plane (n.l = the least float) gets its feeler", "04.4", 1)
{
    // n.l > 0 is the test, nothing larger: a light 1 away whose height above the floor is the least
    // float has n.l = 2^-149. It gets its feeler and adds its (tiny) share; one at height 0 does not.
    const float least = std::numeric_limits<float>::denorm_min();
    const LitScene floor = floor_scene({});
    const auto [ray, hit] = look_at(floor, {0, 2, 5}, {0.5f, 0, 0.3f});
    REQUIRE(hit.p.y == 0.0f);
    for (const float height : {0.0f, least}) {
        const LitScene scene = floor_scene({PointLight{hit.p + vec3(0.6f, height, -0.8f), color(5.0f)}});
        const vec3 to_light = scene.lights[0].position - hit.p;
        const float n_dot_l = to_light.y / glm::length(to_light);
        const std::uint64_t feelers = height > 0.0f ? 1 : 0;
        reset_counters();
        const color got = shade(scene, ray, hit, given_feelers);
        const std::uint64_t sent = shadow_rays();
        const color want = plastic.diffuse * scene.ambient + (feelers ? lit_by(ray, hit, {0, 1, 0}, scene.lights[0]) : color(0.0f));
        INFO("shade: " << describe(scene, ray, hit) << ": n.l = " << n_dot_l << "; got " << show(got) << " after " << sent
             << " shadow feelers, expected " << show(want) << " after " << feelers
             << (feelers ? " (the light is above the floor, by the least float)" : " (the light is in the floor's plane)"));
        REQUIRE(n_dot_l == height);
        CHECK(same_colour(got, want));
        CHECK(sent == feelers);
    }
}
