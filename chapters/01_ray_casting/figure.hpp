// Chapter 01's figure: discs at several depths over a checkered floor that reaches the horizon.
// Nearer discs hide farther ones (visible surfaces) and equal squares shrink with distance
// (perspective). The program and the picture test both render it through the chapter's contract.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "common/render.hpp"

#include <cmath>

namespace rt::ch01 {

constexpr float figure_vfov_degrees = 50.0f;

inline CameraSpec figure_camera(int width, int height, float vfov_degrees = figure_vfov_degrees)
{
    // From, at, up, vertical field of view, size (common/camera.hpp).
    return CameraSpec{{0.0f, 1.3f, 4.0f}, {0.0f, 1.0f, 0.0f},
                      {0.0f, 1.0f, 0.0f}, vfov_degrees, width, height};
}

inline DiscScene figure_scene()
{
    const auto facing = [](float x, float y, float z) { return glm::normalize(vec3(x, y, z)); };
    DiscScene scene;
    scene.background = {0.62f, 0.76f, 0.92f};
    scene.discs = {
        {{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, infinity, {0.85f, 0.85f, 0.80f}, 1.0f},  // the floor
        {{{-1.1f, 0.9f, 1.2f}, facing(0.3f, 0.1f, 1.0f)}, 0.7f, {0.85f, 0.20f, 0.15f}},
        {{{0.1f, 1.2f, -0.6f}, facing(-0.2f, 0.0f, 1.0f)}, 1.0f, {0.20f, 0.65f, 0.25f}},
        {{{1.6f, 1.6f, -3.5f}, facing(-0.4f, 0.1f, 1.0f)}, 1.5f, {0.20f, 0.35f, 0.85f}},
        {{{-2.8f, 2.4f, -9.0f}, facing(0.2f, -0.1f, 1.0f)}, 2.2f, {0.95f, 0.75f, 0.15f}},
        {{{9.0f, 3.0f, -18.0f}, facing(-0.3f, 0.0f, 1.0f)}, 3.0f, {0.60f, 0.30f, 0.70f}},
    };
    return scene;
}

// Colour a hit: the disc's albedo (checkered where it asks), lit by a headlight so that surfaces
// seen edge-on darken, which is enough to read their orientation.
inline color shade(const DiscScene& scene, const Ray& ray, const Hit& hit)
{
    const Disc& disc = scene.discs[hit.object];
    color albedo = disc.albedo;
    if (disc.checker > 0.0f) {
        // Square (cx, cz) is dark when cx + cz is odd; fmod keeps this exact for far squares,
        // where casting the index to an integer would overflow.
        const float cx = std::floor(hit.p.x / disc.checker);
        const float cz = std::floor(hit.p.z / disc.checker);
        if (std::fmod(cx + cz, 2.0f) != 0.0f)
            albedo *= 0.25f;
    }
    const float headlight = std::abs(glm::dot(hit.n, ray.dir));
    return albedo * (0.3f + 0.7f * headlight);
}

// The slides' Render(ray): the nearest object's shade, or the background.
inline color radiance(const DiscScene& scene, const Ray& ray)
{
    count(Counter::primary_rays);
    const std::optional<Hit> hit = closest_hit(ray, scene, Interval{});
    return hit ? shade(scene, ray, *hit) : scene.background;
}

inline Image render_figure(const RenderSettings& settings, float vfov_degrees = figure_vfov_degrees)
{
    const Camera cam = make_camera(figure_camera(settings.width, settings.height, vfov_degrees));
    const DiscScene scene = figure_scene();
    return render(settings, [&](float x, float y, Rng&) { return radiance(scene, primary_ray(cam, x, y)); });
}

}  // namespace rt::ch01
