// Chapter 01's scene: discs, and planes as discs of infinite radius. That is all the figure needs
// (the kit models only what a scene requires).
#pragma once

#include "common/vec.hpp"

#include <vector>

namespace rt {

// The points p with n.(p - b) = 0: the slides' plane through point b with normal n.
struct Plane {
    point3 b;
    vec3 n;  // unit length
};

// The points of the plane within `radius` of b. A floor is a disc of infinite radius.
struct Disc {
    Plane plane;
    float radius;
    color albedo;
    float checker = 0.0f;  // > 0: a checkerboard of squares this wide, on planes facing +y
};

struct DiscScene {
    std::vector<Disc> discs;
    color background{0.0f};  // the slides' backgroundColour, for rays that hit nothing
};

}  // namespace rt
