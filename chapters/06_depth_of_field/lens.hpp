// The thin lens: the two numbers that turn chapter 01's pinhole into a camera with depth of field,
// and what they do to a picture.
//
// A pinhole lets through one ray per point of the image, so everything is sharp. A real lens has
// an opening, the aperture, and every point of it sends light to the same image point from one
// plane of the scene only, the plane of sharp focus; a point nearer or farther is spread over a
// small disc of the image, its circle of confusion. Cook, Porter and Carpenter ("Distributed ray
// tracing", SIGGRAPH 1984) render this by sending each pixel's samples from different points of
// the lens toward the point where the pinhole ray meets the plane of focus; Shirley's
// Fundamentals of Computer Graphics and pbrt (Pharr, Jakob, Humphreys, "Realistic Cameras" and
// "Projective Camera Models") write the same thin-lens model.
#pragma once

#include "common/camera.hpp"
#include "common/error.hpp"

#include <glm/vec2.hpp>

#include <cmath>
#include <sstream>
#include <string>

namespace rt {

// A point in a plane: two random numbers of the unit square, or a point of the unit disc.
using point2 = glm::vec2;

// The lens sits at the eye, in the plane spanned by the camera's u and v; the plane of sharp focus
// lies focus_distance in front of it, perpendicular to the view direction (at -w), as the film of
// a real camera is. R = 0 is chapter 01's pinhole.
struct ThinLens {
    float aperture_radius = 0.0f;  // R: the lens's radius, in scene units
    float focus_distance = 1.0f;   // F: how far in front of the eye, along -w, everything is sharp
};

// Throws InputError naming the problem for a negative or non-finite aperture, or a focus distance
// that is not a positive finite number; the message calls them by the names given (a program
// passes its flags, "--aperture" and "--focus").
inline void check_thin_lens(const ThinLens& lens, const std::string& aperture_name = "the aperture radius",
                            const std::string& focus_name = "the focus distance")
{
    std::ostringstream message;
    if (!(std::isfinite(lens.aperture_radius) && lens.aperture_radius >= 0.0f))
        message << aperture_name << " must be 0 (a pinhole) or more, got " << lens.aperture_radius;
    else if (!(std::isfinite(lens.focus_distance) && lens.focus_distance > 0.0f))
        message << focus_name << " must be more than 0, got " << lens.focus_distance;
    else
        return;
    throw InputError(message.str());
}

// The circle of confusion, by similar triangles: a point at depth d (measured along -w) is seen
// through every point of the lens, and those rays cross the plane of focus over a disc of diameter
//     2 R |d - F| / d,
// which the pinhole projection shrinks by F onto the window at distance 1, 2 R |d - F| / (F d).
// This is that diameter in pixels of the image: 0 on the plane of focus, growing without bound as
// d nears the lens, and toward 2 R / F of the window as d goes to infinity.
inline float circle_of_confusion_pixels(const Camera& cam, const ThinLens& lens, float depth)
{
    const float on_window = 2.0f * lens.aperture_radius * std::abs(depth - lens.focus_distance) /
                            (lens.focus_distance * depth);
    const float pixel = (cam.t - cam.b) / static_cast<float>(cam.ny);  // one pixel's height on the window
    return on_window / pixel;
}

}  // namespace rt
