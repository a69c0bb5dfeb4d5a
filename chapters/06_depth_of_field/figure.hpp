// Chapter 06's figure, the slides' "Realism: depth of field": a row of five spheres on a
// checkered floor, receding from near left to far right, seen through a thin lens focused on the
// middle one. It is sharp; the ones in front of it and behind it are blurred, each by its circle of
// confusion (lens.hpp), which grows with its distance from the plane of focus: the nearest most.
// The out-of-focus highlights spread into discs, the shape of the aperture. The program and the
// picture test both render it through the chapter's contract, shaded by chapter 04's shade (its
// point light casts the spheres' shadows) and found by chapter 04's closest_hit.
#pragma once

#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/radiance.hpp"
#include "06_depth_of_field/06_depth_of_field.hpp"
#include "06_depth_of_field/scene.hpp"
#include "common/render.hpp"

#include <array>

namespace rt::ch06 {

constexpr float figure_vfov_degrees = 36.0f;

inline CameraSpec figure_camera(int width, int height)
{
    // From, at, up, vertical field of view, size (common/camera.hpp).
    return CameraSpec{{0.0f, 1.6f, 6.6f}, {0.6f, 0.0f, -1.0f},
                      {0.0f, 1.0f, 0.0f}, figure_vfov_degrees, width, height};
}

// The spheres' centres, nearest first, all of radius 0.5 and resting on the floor. The middle one
// is the one in focus.
constexpr float sphere_radius = 0.5f;
constexpr std::array<point3, 5> sphere_centres = {
    point3{-1.15f, 0.5f, 3.2f}, point3{-0.35f, 0.5f, 1.2f}, point3{0.8f, 0.5f, -1.1f},
    point3{2.4f, 0.5f, -4.6f}, point3{4.6f, 0.5f, -9.6f}};
constexpr int focused_sphere = 2;

// How deep a point lies in front of the camera: its distance from the eye along -w, the distance
// the plane of focus is measured by.
inline float depth_of(const Camera& cam, const point3& p)
{
    return glm::dot(p - cam.eye, -cam.w);
}

// Why 0.1: at the figure's 640x360 this spreads the nearest sphere over a circle of confusion of
// about 18 pixels and the farthest over about 7, clearly blurred, and the middle one's neighbours
// over 4 to 6: a blur one can see grow with the distance from the plane of focus (the program's
// --stats prints each sphere's).
constexpr float figure_aperture_radius = 0.1f;

// The lens of the figure: focused on the middle sphere's centre.
inline ThinLens figure_lens(float aperture_radius = figure_aperture_radius)
{
    const Camera cam = make_camera(figure_camera(16, 9));
    return ThinLens{aperture_radius, depth_of(cam, sphere_centres[focused_sphere])};
}

inline FocusScene figure_scene()
{
    FocusScene scene;
    LitScene& lit = scene.lit;
    lit.background = {0.62f, 0.76f, 0.92f};
    lit.ambient = color(0.12f);

    const int floor = lit.add_material({{0.85f, 0.83f, 0.78f}, color(0.0f), 1.0f});  // diffuse only: the checker needs it
    const std::array<PhongMaterial, 5> shiny = {{
        {{0.80f, 0.15f, 0.10f}, color(0.3f), 60.0f},
        {{0.85f, 0.58f, 0.10f}, color(0.3f), 60.0f},
        {{0.20f, 0.65f, 0.25f}, color(0.3f), 60.0f},
        {{0.15f, 0.40f, 0.85f}, color(0.3f), 60.0f},
        {{0.55f, 0.25f, 0.70f}, color(0.3f), 60.0f},
    }};

    // The floor: a square of two triangles, counter-clockwise seen from above, reaching far back.
    const point3 p00{-30.0f, 0.0f, -60.0f}, p10{30.0f, 0.0f, -60.0f}, p01{-30.0f, 0.0f, 10.0f}, p11{30.0f, 0.0f, 10.0f};
    lit.add_triangle({p01, p11, p10}, floor);
    lit.add_triangle({p01, p10, p00}, floor);
    scene.checker = {floor, 1.0f, 0.3f};

    for (size_t k = 0; k < sphere_centres.size(); ++k)
        lit.add_sphere({sphere_centres[k], sphere_radius}, lit.add_material(shiny[k]));

    // One point light, up and to the left, in front: the shadows fall back and to the right.
    lit.lights.push_back({{-6.0f, 14.0f, 2.0f}, color(160.0f)});
    return scene;
}

// The slides' Render(ray): chapter 04's shade of the nearest hit, painted by the checkerboard, or
// the background. A camera ray starts on the lens, on no surface, so it accepts any t > 0.
inline color radiance(const FocusScene& scene, const Ray& ray)
{
    count(Counter::primary_rays);
    const std::optional<Hit> hit = closest_hit(ray, scene.lit, Interval{0.0f, infinity});
    if (!hit)
        return scene.lit.background;
    return checker_factor(scene, hit->object, hit->p) * shade(scene.lit, ray, *hit, FeelerSettings{});
}

// The figure through `lens`, each sample's lens point drawn from its pixel's own stream.
// With `variance_of_mean`, also each pixel's variance of the mean (for the noisy picture test).
inline Image render_figure(const RenderSettings& settings, const ThinLens& lens = figure_lens(),
                           Image* variance_of_mean = nullptr)
{
    const Camera cam = make_camera(figure_camera(settings.width, settings.height));
    const FocusScene scene = figure_scene();
    return render(
        settings, [&](float x, float y, Rng& rng) { return radiance(scene, thin_lens_ray(cam, lens, x, y, rng)); },
        variance_of_mean);
}

}  // namespace rt::ch06
