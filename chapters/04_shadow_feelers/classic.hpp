// The classic NFF test rules as a render mode (`04_shadow_feelers --scene FILE.nff --classic`):
// the conventions under which the ray tracers of these lectures' era reported what a scene of
// Haines' Standard Procedural Databases (SPD, 1987) cost them, so that two tracers' counts can be
// compared ray for ray:
//   - eye rays through the pixels' corners: a w x h image shoots (w + 1) x (h + 1) eye rays, and
//     a pixel is the mean of its four corners;
//   - a path is at most 5 rays deep, the eye ray counting as 1;
//   - a reflection ray wherever the surface reflects or transmits (Ks > 0 or T > 0: SPD's rule 8,
//     "all rays hitting reflective and transmitting objects spawn reflection rays"), and a
//     refraction ray wherever T > 0; under total internal reflection only the reflection ray, which
//     then also carries T (no light gets through). A glass of Ks = 0 still sends its reflection
//     ray, of weight 0: SPD's statistics count it, and a tracer compared with them must too;
//   - no shadow feeler toward a light the surface faces away from;
//   - polygons one-sided, except where their material transmits (T > 0): a ray that meets an
//     opaque polygon's back passes through it. Every object casts shadows, either side. SPD's rule
//     2 makes one exception, the teapot, whose loose lid shows back faces: `two_sided` (the
//     programs' --two-sided) sees every polygon from both sides.
// The shading is NFF's, with no falloff and no ambient term: for each light the surface sees,
// Kd rgb (n.l) plus a white highlight Ks (n.h)^Shine (Blinn-Phong, EXERCISE 04.1), in the light's
// colour; then Ks times the reflected colour and T times the refracted one.
//
// It uses the chapters before it: the watertight triangle and precise sphere (02), reflect and
// refract (03), local_shading, occluded through light_blocked, and the robust offset (04).
// `--stats` reports the SPD counts (print_classic_stats).
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/radiance.hpp"
#include "04_shadow_feelers/nff_scene.hpp"
#include "common/error.hpp"
#include "common/heatmap.hpp"
#include "common/render.hpp"
#include "common/scene_file.hpp"

#include <string>
#include <vector>

namespace rt::classic {

// The eye ray is ray 1 of its path.
constexpr int max_depth = 5;

// What --classic needs of the other options (InputError otherwise): a scene file, and one sample
// per pixel, since its eye rays go through the pixels' corners.
inline void check_classic_options(bool classic, const std::string& scene, int spp, bool two_sided = false)
{
    if (two_sided && !classic)
        throw InputError("--two-sided is a rule of --classic (every polygon seen from both sides); the other modes "
                         "already see both sides");
    if (classic && scene.empty())
        throw InputError("--classic renders a scene file by the classic NFF rules: it needs --scene FILE.nff");
    if (classic && spp != 1)
        throw InputError("--classic shoots one eye ray through each pixel corner: --spp must be 1, got " +
                         std::to_string(spp));
}

struct ClassicScene {
    LitScene lit;                        // shapes and Phong materials; its lights are not used
    std::vector<NffMaterial> materials;  // the file's, index for index with lit.materials: Ks, T, ior
    std::vector<bool> one_sided;         // per triangle: opaque, so seen from its front only
    std::vector<color> light_colours;    // per light of lit.lights: NFF's, with no falloff
};

inline ClassicScene classic_scene(const NffScene& nff, bool two_sided = false)
{
    ClassicScene scene{lit_scene(nff), nff.materials, {}, {}};
    scene.lit.ambient = color(0.0f);
    for (const NffTriangle& t : nff.triangles)
        scene.one_sided.push_back(!two_sided && !(nff.materials[t.material].t > 0.0f));
    for (const NffLight& light : nff.lights)
        scene.light_colours.push_back(nff_light_colour(nff, light));
    return scene;
}

// The colour along `ray`, the depth-th ray of its path.
inline color trace(const ClassicScene& scene, const Ray& ray, int depth)
{
    const std::optional<Hit> hit = closest_hit(ray, scene.lit, Interval{0.0f, infinity}, &scene.one_sided);
    if (!hit)
        return scene.lit.background;
    count(depth == 1 ? Counter::primary_hits : Counter::secondary_hits);
    const int material = scene.lit.material_index(hit->object);
    const NffMaterial& m = scene.materials[material];
    const vec3 n = glm::dot(hit->n, ray.dir) > 0.0f ? -hit->n : hit->n;  // toward the ray's side

    // The local term: every light the surface faces and no object hides.
    color c(0.0f);
    for (size_t k = 0; k < scene.lit.lights.size(); ++k) {
        const vec3 to_light = scene.lit.lights[k].position - hit->p;
        const float d = glm::length(to_light);
        if (!(d > 0.0f) || glm::dot(n, to_light) <= 0.0f)
            continue;  // faces away: no feeler
        if (light_blocked(scene.lit, *hit, scene.lit.lights[k].position, FeelerSettings{})) {
            count(Counter::shadow_blocked);
            continue;
        }
        c += local_shading(scene.lit.materials[material], n, -ray.dir, to_light / d, scene.light_colours[k]);
    }
    if (depth >= max_depth)
        return c;

    // The secondary rays, each leaving from the robust offset of the hit point (EXERCISE 04.3).
    const auto follow = [&](const vec3& dir) {
        return trace(scene, Ray{offset_ray_origin(hit->p, hit->ng, dir), dir}, depth + 1);
    };
    const std::optional<vec3> refracted = m.t > 0.0f ? refract(ray.dir, hit->n, m.ior) : std::nullopt;
    const float k_reflect = m.ks + (m.t > 0.0f && !refracted ? m.t : 0.0f);  // total internal reflection
    if (m.ks > 0.0f || m.t > 0.0f) {
        count(Counter::reflected_rays);
        c += k_reflect * follow(reflect(ray.dir, hit->n));
    }
    if (refracted) {
        count(Counter::refracted_rays);
        c += m.t * follow(*refracted);
    }
    return c;
}

// The image under the classic rules: the corners' grid of eye rays, one render of (w + 1) x (h + 1)
// "pixels" whose centres are the image's pixel corners, then each pixel the mean of its four.
// With `corner_cost` (chapter 07 on: a heat map), also what each corner's ray cost, on a map of
// (w + 1) x (h + 1) whose counter the caller chose (pixel_cost_of_corners averages it per pixel).
inline Image render_classic(const SceneRender& file, const ClassicScene& scene, CostMap* corner_cost = nullptr)
{
    const RenderSettings& settings = file.settings;
    RenderSettings grid = settings;
    grid.width = settings.width + 1;
    grid.height = settings.height + 1;
    grid.spp = 1;
    const auto corner = [&](float x, float y, Rng&) {
        count(Counter::primary_rays);
        return trace(scene, file.eye_ray(primary_ray(file.camera, x - 0.5f, y - 0.5f)), 1);
    };
    const Image corners = render(grid, corner, nullptr, corner_cost);
    Image image(settings.width, settings.height);
    for (int j = 0; j < settings.height; ++j)
        for (int i = 0; i < settings.width; ++i)
            image.at(i, j) = 0.25f * (corners.at(i, j) + corners.at(i + 1, j) + corners.at(i, j + 1) +
                                      corners.at(i + 1, j + 1));
    return image;
}

// A map of the corners' costs as the pixels' costs: the mean of each pixel's four corners.
inline CostMap pixel_cost_of_corners(const CostMap& corners)
{
    CostMap pixels(corners.width - 1, corners.height - 1, corners.counter);
    const auto at = [&](int i, int j) { return corners.cost[static_cast<size_t>(j) * corners.width + i]; };
    for (int j = 0; j < pixels.height; ++j)
        for (int i = 0; i < pixels.width; ++i)
            pixels.cost[static_cast<size_t>(j) * pixels.width + i] =
                (at(i, j) + at(i + 1, j) + at(i, j + 1) + at(i + 1, j + 1) + 2) / 4;
    return pixels;
}

}  // namespace rt::classic
