// The pinhole camera at an arbitrary viewpoint (Shirley ch. 4; the slides' "Arbitrary view point").
//
// The eye sits at `from` and looks at `at`. The orthonormal basis u, v, w has w pointing *back*
// from the view direction, u to the right and v up, so the image window lies on the plane one unit
// in front of the eye, at -w, spanning [l, r] x [b, t] in u and v.
//
// make_camera checks the specification and builds the basis and window; chapter 01's exercise maps
// a pixel position to a ray through that window.
#pragma once

#include "common/vec.hpp"

namespace rt {

struct CameraSpec {
    point3 from{0.0f, 0.0f, 0.0f};
    point3 at{0.0f, 0.0f, -1.0f};
    vec3 up{0.0f, 1.0f, 0.0f};
    float vfov_degrees = 60.0f;  // vertical field of view, the full angle
    int width = 320;             // nx, pixels across
    int height = 240;            // ny, pixels down
};

struct Camera {
    point3 eye;
    vec3 u, v, w;          // right, up, backward; orthonormal
    float l, r, b, t;      // the window on the plane at distance 1 in front of the eye
    int nx, ny;            // image size in pixels
};

// Throws InputError naming the problem for a width or height below 1, a field of view outside
// (0, 180) degrees, `from` equal to `at`, or `up` parallel to the view direction.
Camera make_camera(const CameraSpec& spec);

}  // namespace rt
