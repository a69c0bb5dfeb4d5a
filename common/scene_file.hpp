// --scene FILE.nff: what the chapter programs from 02 on render in place of their figure, and how
// an NFF file's view and lights become the kit's camera and lights (the reader is nff.hpp).
//
// Each chapter turns the file's objects and materials into its own scene type, with that
// chapter's features (chapters/NN_name/nff_scene.hpp); what every chapter shares is here.
#pragma once

#include "common/camera.hpp"
#include "common/cli.hpp"
#include "common/nff.hpp"
#include "common/ray.hpp"
#include "common/render.hpp"

#include <string>

namespace rt {

// The option every program from chapter 02 on has, and the one it excludes: --sweep measures the
// chapter's own scenes (an InputError when both are given).
void add_scene_option(CommandLine& cli, std::string& path);
void check_scene_without_sweep(const std::string& path, bool sweep);

// The file's view as the kit's camera, for an image of width x height pixels. NFF's angle is the
// full field of view between the outermost eye rays; the kit's window spans the angle edge to
// edge, so the classic mode's corner rays (chapter 04, --classic) run along exactly that angle.
// SPD's images are square; for another shape the angle spans the image's shorter side, so a scene
// framed for a square stays in view in a wide or a tall picture.
CameraSpec nff_camera_spec(const NffView& view, int width, int height);

// A scene file ready to render: the scene, its camera, and the render settings, whose size is the
// file's resolution unless --width or --height was given; given one, the other keeps the file's
// aspect ratio.
struct SceneRender {
    NffScene scene;
    Camera camera;
    RenderSettings settings;
};

// Reads the file (InputError "FILE:LINE: what is wrong" on bad input, as read_nff does).
SceneRender load_scene_render(const std::string& path, const CommonOptions& options, const CommandLine& cli);

// NFF's hither: nothing nearer the eye than the near plane is seen. The kit starts the eye ray on
// it, `hither` along the ray, which every chapter's tracer then takes as it is.
inline Ray beyond_hither(const Ray& ray, float hither)
{
    return {ray.at(hither), ray.dir};
}

// NFF gives lights "a non-zero intensity of no particular value". The kit's choice: each light's
// colour (white unless the file gives one) over sqrt(L) for L lights, so one light alone is full
// white and a scene of many lights does not wash out to white.
color nff_light_colour(const NffScene& scene, const NffLight& light);

// Why a tenth: NFF has no ambient light, and without one every surface a light cannot see (in
// shadow, or facing away) is black, where a scene's shape is lost. A tenth of white keeps those
// surfaces readable and stays well below the lights. The classic mode (--classic) follows NFF and
// has none.
constexpr float nff_ambient = 0.1f;

}  // namespace rt
