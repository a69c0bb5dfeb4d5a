// Chapter 03's figure, an homage to the picture of Whitted's 1979 paper: a mirror sphere and a
// glass sphere over a red and yellow checkered floor, under a blue sky. The glass sphere shows the
// floor behind it upside down (it is a lens), the mirror sphere shows the glass sphere, the floor
// and the sun's highlight. The program and the picture test both render it through the chapter's
// contract.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "common/render.hpp"

namespace rt::ch03 {

constexpr float figure_vfov_degrees = 38.0f;

inline CameraSpec figure_camera(int width, int height)
{
    // From, at, up, vertical field of view, size (common/camera.hpp).
    return CameraSpec{{0.0f, 1.6f, 5.6f}, {0.0f, 0.95f, -0.6f},
                      {0.0f, 1.0f, 0.0f}, figure_vfov_degrees, width, height};
}

inline WhittedScene figure_scene()
{
    WhittedScene scene;
    scene.shapes.background = {0.20f, 0.36f, 0.85f};
    scene.zenith = {0.01f, 0.04f, 0.30f};
    scene.ambient = color(0.30f);
    scene.sun.to_sun = glm::normalize(vec3(-0.5f, 0.9f, 0.6f));
    scene.sun.colour = color(0.75f);
    scene.sun.glow = 40.0f;
    scene.sun.glow_exponent = 1500.0f;

    // The floor: a checkered rectangle of two triangles, counter-clockwise seen from above; its far
    // edge shows against the sky, as in Whitted's picture.
    Material checkers;
    checkers.checker = 1.0f;
    checkers.odd = {0.85f, 0.10f, 0.06f};
    const color yellow{0.95f, 0.78f, 0.12f};
    const point3 p00{-7.0f, 0.0f, -18.0f}, p10{7.0f, 0.0f, -18.0f}, p01{-7.0f, 0.0f, 4.0f}, p11{7.0f, 0.0f, 4.0f};
    scene.add_triangle({p01, p11, p10}, yellow, checkers);
    scene.add_triangle({p01, p10, p00}, yellow, checkers);

    // The mirror sphere behind, a little dull (a trace of its own colour shows).
    Material mirror;
    mirror.mirror = 0.8f;
    scene.add_sphere({{0.85f, 1.0f, -1.2f}, 1.0f}, color(0.10f), mirror);

    // The glass sphere in front, clear: no colour of its own, all it shows comes through Fresnel.
    Material glass;
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    scene.add_sphere({{-0.75f, 1.25f, 0.6f}, 0.8f}, color(0.0f), glass);
    return scene;
}

// The slides' Render(ray), recursive now: everything the ray's tree of secondary rays sees.
inline color radiance(const WhittedScene& scene, const Ray& ray, const TraceSettings& settings)
{
    count(Counter::primary_rays);
    return trace(scene, ray, settings);
}

inline Image render_figure(const RenderSettings& settings, const TraceSettings& trace_settings = {})
{
    const Camera cam = make_camera(figure_camera(settings.width, settings.height));
    const WhittedScene scene = figure_scene();
    return render(settings,
                  [&](float x, float y, Rng&) { return radiance(scene, primary_ray(cam, x, y), trace_settings); });
}

}  // namespace rt::ch03
