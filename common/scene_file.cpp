#include "common/scene_file.hpp"

#include "common/error.hpp"
#include "common/stats.hpp"

#include <algorithm>
#include <iostream>
#include <utility>
#include <cmath>

namespace rt {

void add_scene_option(CommandLine& cli, std::string& path)
{
    cli.option("--scene", path, "render this NFF scene file instead of the figure (size from the file)");
}

void check_scene_without_sweep(const std::string& path, bool sweep)
{
    if (!path.empty() && sweep)
        throw InputError("--sweep measures the chapter's own scenes; it does not take --scene");
}

Camera nff_camera(const NffView& view, int width, int height)
{
    Camera cam = make_camera({view.from, view.at, view.up, view.angle_degrees, width, height});
    if (height > width) {
        // make_camera spans the angle up the window; a tall window takes it across instead. Set
        // from the tangent, since the vertical angle it implies may lie within a float step of 180
        // degrees (an angle of 179.9 over a 1 x 16384 image), which no angle can say.
        constexpr double degrees = 3.14159265358979323846 / 180.0;
        const double half_width = std::tan(0.5 * static_cast<double>(view.angle_degrees) * degrees);
        cam.r = static_cast<float>(half_width);
        cam.t = static_cast<float>(half_width * height / width);
        cam.l = -cam.r;
        cam.b = -cam.t;
    }
    return cam;
}

SceneRender scene_render(NffScene scene, const RenderSettings& settings)
{
    SceneRender r{std::move(scene), {}, settings};
    r.camera = nff_camera(r.scene.view, settings.width, settings.height);
    return r;
}

SceneRender load_scene_render(const std::string& path, const CommonOptions& options, const CommandLine& cli)
{
    SceneRender r{read_nff(path), {}, render_settings(options)};
    for (const std::string& warning : r.scene.warnings)
        std::cerr << "warning: " << warning << '\n';
    note_stat("skipped_polygons", std::to_string(r.scene.skipped_polygons));
    const NffView& view = r.scene.view;
    const bool width_given = cli.given("--width"), height_given = cli.given("--height");
    // One side given: the other keeps the file's aspect ratio.
    const auto scaled = [](int side, int to, int from) {
        return std::clamp(static_cast<int>(std::lround(static_cast<double>(side) * to / from)), 1, nff_max_resolution);
    };
    if (!width_given)
        r.settings.width = height_given ? scaled(r.settings.height, view.width, view.height) : view.width;
    if (!height_given)
        r.settings.height = width_given ? scaled(r.settings.width, view.height, view.width) : view.height;
    check_image_size(r.settings.width, r.settings.height);
    r.camera = nff_camera(r.scene.view, r.settings.width, r.settings.height);
    return r;
}

vec3 nff_light_offset(const NffScene& scene, const NffLight& light)
{
    const vec3 offset = light.position - scene.view.at;
    return glm::length(offset) > 0.0f ? offset : scene.view.from - scene.view.at;
}

color nff_light_colour(const NffScene& scene, const NffLight& light)
{
    return light.rgb / std::sqrt(static_cast<float>(scene.lights.size()));
}

}  // namespace rt
