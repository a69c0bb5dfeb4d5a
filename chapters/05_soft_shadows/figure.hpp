// Chapter 05's figure, the slides' pair in one image: on the left "sphere with hard shadow, point
// sampling source", on the right "sphere with soft shadow, sampling wide light source". The same
// scene in both: a red sphere floating over a floor, a white one resting on it, a wall behind.
// On the right two area lights shine: a wide warm rectangle above and to the left, a smaller cool
// disc to the right; on the left each is shrunk to a point light at its centre (as_point_light,
// intensity L_e A). The points' shadows are hard; the area lights' shadows have a dark core (the
// umbra, where the whole light is hidden) inside a soft edge (the penumbra, where part of it is),
// widest below the floating sphere and narrow where the white sphere touches the floor.
// The program, the picture test and the trade table all render it through the chapter's contract.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "05_soft_shadows/shade.hpp"
#include "common/render.hpp"

#include <algorithm>

namespace rt::ch05 {

constexpr float figure_vfov_degrees = 42.0f;
// Where the back wall stands: far enough behind the spheres that their shadows stay on the floor.
constexpr float wall_z = -5.0f;

inline CameraSpec panel_camera(int width, int height)
{
    // From, at, up, vertical field of view, size (common/camera.hpp).
    return CameraSpec{{0.0f, 2.9f, 6.4f}, {0.3f, 0.75f, -0.6f},
                      {0.0f, 1.0f, 0.0f}, figure_vfov_degrees, width, height};
}

// The right panel's scene: the area lights.
inline AreaLitScene soft_scene()
{
    AreaLitScene scene;
    LitScene& lit = scene.lit;
    lit.background = {0.62f, 0.76f, 0.92f};
    lit.ambient = color(0.06f);

    const int floor = lit.add_material({{0.78f, 0.78f, 0.74f}, color(0.0f), 1.0f});
    const int red = lit.add_material({{0.75f, 0.14f, 0.10f}, color(0.12f), 40.0f});
    const int white = lit.add_material({{0.80f, 0.80f, 0.80f}, color(0.05f), 20.0f});

    // The floor, a square of two triangles counter-clockwise seen from above, and a wall behind,
    // facing the camera, high and wide enough to fill the view: no horizon. (A horizon is a
    // bright sliver of sky in a pixel of dark floor, which few samples can miss entirely, and then
    // its noise cannot be told from a wrong picture: the picture test needs none.)
    const point3 f00{-30.0f, 0.0f, wall_z}, f10{30.0f, 0.0f, wall_z}, f01{-30.0f, 0.0f, 8.0f}, f11{30.0f, 0.0f, 8.0f};
    lit.add_triangle({f01, f11, f10}, floor);
    lit.add_triangle({f01, f10, f00}, floor);
    const point3 w01{-30.0f, 20.0f, wall_z}, w11{30.0f, 20.0f, wall_z};
    lit.add_triangle({f00, f10, w11}, floor);
    lit.add_triangle({f00, w11, w01}, floor);

    lit.add_sphere({{-0.2f, 1.35f, -0.3f}, 0.85f}, red);  // floating: the penumbra widens below it
    lit.add_sphere({{1.9f, 0.4f, 0.9f}, 0.4f}, white);    // resting on the floor: sharp where it touches

    // A wide warm panel above and to the left, facing down (x cross z = -y), and a smaller cool
    // disc up to the right and in front, facing the red sphere. Each light's shadow is lit by the
    // other, so the panel's shadow is tinted blue and the disc's yellow.
    scene.area_lights.push_back(rectangle_light({-2.6f, 4.6f, 0.4f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f},
                                                {3.0f, 2.5f, 1.8f}));
    const point3 disc_centre{3.0f, 3.0f, 2.6f};
    scene.area_lights.push_back(disc_light(disc_centre, glm::normalize(point3(-0.2f, 1.35f, -0.3f) - disc_centre), 0.5f,
                                           {5.0f, 7.0f, 11.0f}));
    return scene;
}

// The left panel's scene: each area light shrunk to a point light of the same power straight ahead.
inline AreaLitScene hard_scene()
{
    AreaLitScene scene = soft_scene();
    for (const AreaLight& light : scene.area_lights)
        scene.lit.lights.push_back(as_point_light(light));
    scene.area_lights.clear();
    return scene;
}

// One panel, the whole image.
inline Image render_panel(const RenderSettings& settings, const AreaLitScene& scene, const LightSampling& sampling,
                          Image* variance_of_mean = nullptr)
{
    const Camera cam = make_camera(panel_camera(settings.width, settings.height));
    return render(
        settings, [&](float x, float y, Rng& rng) { return radiance(scene, primary_ray(cam, x, y), sampling, rng); },
        variance_of_mean);
}

// The pair side by side: the hard-shadow panel on the left, width / 2 pixels, the soft one on the
// right. One render, so every pixel keeps its own random stream.
inline Image render_figure(const RenderSettings& settings, const LightSampling& sampling,
                           Image* variance_of_mean = nullptr)
{
    const int left_width = settings.width / 2, right_width = settings.width - left_width;
    const Camera left = make_camera(panel_camera(std::max(1, left_width), settings.height));
    const Camera right = make_camera(panel_camera(right_width, settings.height));
    const AreaLitScene hard = hard_scene(), soft = soft_scene();
    // Pixel i lies in the left panel when i < left_width, and its samples at x within half a pixel.
    const float boundary = static_cast<float>(left_width) - 0.5f;
    return render(
        settings,
        [&](float x, float y, Rng& rng) {
            if (x < boundary)
                return radiance(hard, primary_ray(left, x, y), sampling, rng);
            return radiance(soft, primary_ray(right, x - static_cast<float>(left_width), y), sampling, rng);
        },
        variance_of_mean);
}

}  // namespace rt::ch05
