// A ray p(t) = u + v t (the slides' notation; E + t V in the sphere test).
#pragma once

#include "common/vec.hpp"

namespace rt {

struct Ray {
    point3 origin;  // u, or E
    vec3 dir;       // v, or V: unit length wherever the kit makes a ray

    point3 at(float t) const { return origin + t * dir; }
};

}  // namespace rt
