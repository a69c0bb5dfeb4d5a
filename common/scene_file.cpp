#include "common/scene_file.hpp"

#include "common/error.hpp"

#include <algorithm>
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

CameraSpec nff_camera_spec(const NffView& view, int width, int height)
{
    CameraSpec spec{view.from, view.at, view.up, view.angle_degrees, width, height};
    if (height > width) {
        // The angle spans the width: the vertical angle of the taller window.
        constexpr double degrees = 3.14159265358979323846 / 180.0;
        const double half = std::tan(0.5 * view.angle_degrees * degrees) * height / width;
        spec.vfov_degrees = static_cast<float>(2.0 * std::atan(half) / degrees);
    }
    return spec;
}

SceneRender load_scene_render(const std::string& path, const CommonOptions& options, const CommandLine& cli)
{
    SceneRender r{read_nff(path), {}, render_settings(options)};
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
    r.camera = make_camera(nff_camera_spec(r.scene.view, r.settings.width, r.settings.height));
    return r;
}

color nff_light_colour(const NffScene& scene, const NffLight& light)
{
    return light.rgb / std::sqrt(static_cast<float>(scene.lights.size()));
}

}  // namespace rt
