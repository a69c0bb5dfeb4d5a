#include "common/camera.hpp"

#include "common/error.hpp"

#include <cmath>
#include <string>

namespace rt {

Camera make_camera(const CameraSpec& spec)
{
    if (spec.width < 1 || spec.height < 1)
        throw InputError("image size must be at least 1x1 pixels, got " + std::to_string(spec.width) +
                         "x" + std::to_string(spec.height));
    if (!(spec.vfov_degrees > 0.0f && spec.vfov_degrees < 180.0f))
        throw InputError("field of view must lie strictly between 0 and 180 degrees, got " +
                         std::to_string(spec.vfov_degrees));
    const vec3 back = spec.from - spec.at;
    if (back == vec3(0.0f) || std::isnan(back.x) || std::isnan(back.y) || std::isnan(back.z))
        throw InputError("the camera looks from the point it looks at: no view direction");
    const vec3 w = unit_or_zero(back);
    const vec3 side = glm::cross(spec.up, w);
    if (!(glm::length(side) > 1e-6f * glm::length(spec.up)))
        throw InputError("the camera's up vector is parallel to its view direction (or zero)");

    Camera cam;
    cam.eye = spec.from;
    cam.w = w;
    cam.u = glm::normalize(side);
    cam.v = glm::cross(w, cam.u);
    // The window at distance 1 subtends the vertical field of view; its width follows the pixel
    // aspect ratio, so pixels are square.
    const double half_fov = 0.5 * static_cast<double>(spec.vfov_degrees) * 3.14159265358979323846 / 180.0;
    cam.t = static_cast<float>(std::tan(half_fov));
    cam.b = -cam.t;
    cam.r = cam.t * static_cast<float>(spec.width) / static_cast<float>(spec.height);
    cam.l = -cam.r;
    cam.nx = spec.width;
    cam.ny = spec.height;
    return cam;
}

}  // namespace rt
