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

#include <glm/geometric.hpp>

#include <string>

namespace rt {

// The option every program from chapter 02 on has, and the one it excludes: --sweep measures the
// chapter's own scenes (an InputError when both are given).
void add_scene_option(CommandLine& cli, std::string& path);
void check_scene_without_sweep(const std::string& path, bool sweep);

// The file's view as the kit's camera, for an image of width x height pixels. NFF's angle is the
// full field of view; the kit's window spans it edge to edge, so the classic mode's corner rays
// (chapter 04, --classic) run along exactly that angle. (SPD measures it between the outermost
// pixel centres, so the kit's other renders see (w - 1) / w of SPD's angle's tangent: a 400-pixel
// image 0.25% less.) SPD's images are square; for another shape the angle spans the image's
// shorter side, so a scene framed for a square stays in view in a wide or a tall picture.
Camera nff_camera(const NffView& view, int width, int height);

// NFF's hither: nothing nearer the eye than the near plane, `hither` in front of the eye (along
// -w), is seen. The camera's ray, from the eye or from a point of chapter 06's lens (both in the
// plane through the eye across the view), starts on that plane instead, and every chapter's
// tracer takes it from there.
inline Ray from_near_plane(const Ray& ray, const Camera& cam, float hither)
{
    // The ray climbs dir.(-w) of depth per unit of t; a camera ray always points in front.
    const float depth_rate = glm::dot(ray.dir, -cam.w);
    return depth_rate > 0.0f ? Ray{ray.at(hither / depth_rate), ray.dir} : ray;
}

// A scene file ready to render: the scene, its camera, and the render settings, whose size is the
// file's resolution unless --width or --height was given; given one, the other keeps the file's
// aspect ratio.
struct SceneRender {
    NffScene scene;
    Camera camera;
    RenderSettings settings;

    // The eye ray of a camera ray: started on the file's near plane.
    Ray eye_ray(const Ray& camera_ray) const { return from_near_plane(camera_ray, camera, scene.view.hither); }
};

// A scene already in memory (a generated one) at the settings' size, with the camera of its view.
SceneRender scene_render(NffScene scene, const RenderSettings& settings);

// Reads the file (InputError "FILE:LINE: what is wrong" on bad input, as read_nff does).
SceneRender load_scene_render(const std::string& path, const CommonOptions& options, const CommandLine& cli);

// NFF gives lights "a non-zero intensity of no particular value". The kit's choice: each light's
// colour (white unless the file gives one) over sqrt(L) for L lights, so one light alone is full
// white and a scene of many lights does not wash out to white.
color nff_light_colour(const NffScene& scene, const NffLight& light);

// Where a light stands as seen from the scene's centre of interest, the view's `at`: the offset
// from `at` to the light, which the chapters light by (its direction for chapter 03's sun, its
// length for chapter 04's falloff, its reverse for chapter 05's disc). A light at `at` itself is
// taken to stand at the eye, so the offset is never zero.
vec3 nff_light_offset(const NffScene& scene, const NffLight& light);

// Why a tenth: NFF has no ambient light, and without one every surface a light cannot see (in
// shadow, or facing away) is black, where a scene's shape is lost. A tenth of white keeps those
// surfaces readable and stays well below the lights. The classic mode (--classic) follows NFF and
// has none.
constexpr float nff_ambient = 0.1f;

}  // namespace rt
