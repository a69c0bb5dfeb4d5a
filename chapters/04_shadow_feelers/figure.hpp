// Chapter 04's figure, the slides' "sphere with hard shadow, point sampling source": a shiny sphere
// floating over a floor, lit by one point light, with the crisp shadow a point light casts; beside
// it a small sphere resting on the floor and chapter 02's recursive tetrahedral pyramid, whose 256
// triangles cast a shadow of many holes. The program and the picture test both render it through
// the chapter's contract.
//
// The whole scene, camera and light can be scaled by S (--scale): the picture stays the same
// (the light's intensity grows with S^2, as its 1/d^2 falloff shrinks), except where a way of
// starting the feelers fails at that scale.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "02_spheres_triangles/mesh_scene.hpp"
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/radiance.hpp"
#include "common/render.hpp"

#include <array>

namespace rt::ch04 {

constexpr float figure_vfov_degrees = 40.0f;

inline CameraSpec figure_camera(int width, int height, float scale = 1.0f)
{
    // From, at, up, vertical field of view, size (common/camera.hpp).
    return CameraSpec{scale * point3(0.0f, 2.3f, 6.5f), scale * point3(0.3f, 0.8f, -0.6f),
                      {0.0f, 1.0f, 0.0f}, figure_vfov_degrees, width, height};
}

// The mesh's faces into the scene, each with `material`.
inline void add_mesh(LitScene& scene, const IndexedMesh& mesh, int material)
{
    for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
        scene.add_triangle(triangle_of(mesh, f), material);
}

inline LitScene figure_scene(float scale = 1.0f)
{
    const float s = scale;
    LitScene scene;
    scene.background = {0.62f, 0.76f, 0.92f};
    scene.ambient = color(0.10f);

    const int floor = scene.add_material({{0.80f, 0.80f, 0.74f}, color(0.0f), 1.0f});
    const int red = scene.add_material({{0.80f, 0.12f, 0.08f}, color(0.55f), 60.0f});
    const int white = scene.add_material({{0.85f, 0.85f, 0.85f}, color(0.30f), 20.0f});
    const int green = scene.add_material({{0.22f, 0.62f, 0.28f}, color(0.0f), 1.0f});

    // The floor: a square of two triangles, counter-clockwise seen from above.
    const point3 p00 = s * point3(-9.0f, 0.0f, -14.0f), p10 = s * point3(9.0f, 0.0f, -14.0f);
    const point3 p01 = s * point3(-9.0f, 0.0f, 5.0f), p11 = s * point3(9.0f, 0.0f, 5.0f);
    scene.add_triangle({p01, p11, p10}, floor);
    scene.add_triangle({p01, p10, p00}, floor);

    scene.add_sphere({s * point3(-0.5f, 1.4f, 0.0f), s * 0.8f}, red);       // floating: its shadow lies apart
    scene.add_sphere({s * point3(-2.0f, 0.35f, 1.6f), s * 0.35f}, white);  // resting: its shadow touches it
    add_mesh(scene, sierpinski_tetrahedron({s * point3(0.9f, 0.0f, -2.4f), s * point3(3.3f, 0.0f, -2.9f),
                                            s * point3(1.9f, 0.0f, -0.8f), s * point3(2.0f, 2.1f, -2.0f)}, 3),
             green);

    // One point light, up and to the left, in front: the shadows fall back and to the right.
    scene.lights.push_back({s * point3(-4.5f, 7.0f, 3.5f), color(50.0f * s * s)});
    return scene;
}

inline Image render_figure(const RenderSettings& settings, const FeelerSettings& feelers = {}, float scale = 1.0f)
{
    const Camera cam = make_camera(figure_camera(settings.width, settings.height, scale));
    const LitScene scene = figure_scene(scale);
    return render(settings, [&](float x, float y, Rng&) { return radiance(scene, primary_ray(cam, x, y), feelers); });
}

}  // namespace rt::ch04
