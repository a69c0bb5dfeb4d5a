// A ray p(t) = u + v t (the slides' notation; E + t V in the sphere test).
//
// Written once over the scalar type T so that a chapter can run the same formula in float and in
// double and measure what float costs (chapter 02's trade); the kit's rays are
// float, `Ray`.
#pragma once

#include "common/vec.hpp"

namespace rt {

template <class T>
struct BasicRay {
    vec3_t<T> origin;  // u, or E
    vec3_t<T> dir;     // v, or V: unit length wherever the kit makes a ray

    vec3_t<T> at(T t) const { return origin + t * dir; }
};

using Ray = BasicRay<float>;

}  // namespace rt
