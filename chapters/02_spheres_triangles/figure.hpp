// Chapter 02's figure: spheres beside triangle meshes the kit makes itself, on a floor of two
// triangles. Two equal icospheres: the left one shaded smoothly through its interpolated corner
// normals, the right one flat, so its facets show; behind them stands the recursive tetrahedral
// pyramid. The program and the picture test both render it through the chapter's
// contract.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "02_spheres_triangles/closest_hit.hpp"
#include "02_spheres_triangles/mesh_scene.hpp"
#include "common/render.hpp"

namespace rt::ch02 {

constexpr float figure_vfov_degrees = 40.0f;

inline CameraSpec figure_camera(int width, int height)
{
    // From, at, up, vertical field of view, size (common/camera.hpp).
    return CameraSpec{{0.0f, 1.7f, 5.0f}, {0.0f, 0.75f, -0.6f},
                      {0.0f, 1.0f, 0.0f}, figure_vfov_degrees, width, height};
}

inline ShapeScene figure_scene()
{
    ShapeScene scene;
    scene.background = {0.62f, 0.76f, 0.92f};

    // The floor: a square of two triangles, counter-clockwise seen from above.
    const point3 p00{-9.0f, 0.0f, -14.0f}, p10{9.0f, 0.0f, -14.0f}, p01{-9.0f, 0.0f, 4.0f}, p11{9.0f, 0.0f, 4.0f};
    const color floor{0.80f, 0.80f, 0.76f};
    scene.add_triangle({p01, p11, p10}, floor);
    scene.add_triangle({p01, p10, p00}, floor);

    scene.add_sphere({{-2.6f, 0.8f, -1.6f}, 0.8f}, {0.85f, 0.20f, 0.15f});
    scene.add_sphere({{2.1f, 0.4f, 0.9f}, 0.4f}, {0.90f, 0.55f, 0.85f});
    for (int k = 0; k < 5; ++k)  // a row of small spheres in front
        scene.add_sphere({{-1.6f + 0.8f * static_cast<float>(k), 0.18f, 1.5f}, 0.18f}, {0.95f, 0.95f, 0.95f});

    // The same 80-triangle icosphere twice: smooth through its interpolated normals (only its
    // outline shows the triangles), and flat, where every facet shows.
    add_mesh(scene, icosphere({-1.0f, 0.7f, 0.1f}, 0.7f, 1), {0.95f, 0.70f, 0.15f});
    IndexedMesh flat = icosphere({1.4f, 0.7f, -0.3f}, 0.7f, 1);
    flat.normals.clear();
    add_mesh(scene, flat, {0.20f, 0.40f, 0.90f});
    add_mesh(scene, sierpinski_tetrahedron({point3{-1.3f, 0.0f, -3.6f}, point3{1.9f, 0.0f, -4.2f},
                                            point3{0.5f, 0.0f, -2.0f}, point3{0.3f, 2.7f, -3.3f}}, 3),
             {0.25f, 0.70f, 0.30f});
    return scene;
}

// A headlight: light from the eye, Lambert's cosine between the normal and the ray, so surfaces
// seen edge-on darken and each facet of a flat mesh gets its own shade.
inline color shade(const ShapeScene& scene, const Ray& ray, const Hit& hit)
{
    const color& albedo = scene.albedo_of(hit.object);
    const float headlight = std::abs(glm::dot(hit.n, ray.dir));
    return albedo * (0.2f + 0.8f * headlight);
}

// The slides' Render(ray): the nearest object's shade, or the background.
inline color radiance(const ShapeScene& scene, const Ray& ray, ShapeTests tests)
{
    count(Counter::primary_rays);
    const std::optional<Hit> hit = closest_hit(ray, scene, Interval{}, tests);
    return hit ? shade(scene, ray, *hit) : scene.background;
}

inline Image render_figure(const RenderSettings& settings, ShapeTests tests = {})
{
    const Camera cam = make_camera(figure_camera(settings.width, settings.height));
    const ShapeScene scene = figure_scene();
    return render(settings, [&](float x, float y, Rng&) { return radiance(scene, primary_ray(cam, x, y), tests); });
}

}  // namespace rt::ch02
