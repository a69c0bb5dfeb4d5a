// Chapter 02's shapes: the slides' sphere (centre O, radius r) and triangle (corners a, b, c), and
// what a triangle test reports besides t.
//
// Geometry only, as plain structs: what an intersection test reads and nothing else, so arrays of
// them stay small and an accelerator (chapter 07 on) can hold them by index. Written over the
// scalar type T so that one formula serves float (the kit's type) and double (to measure float).
#pragma once

#include "common/vec.hpp"

namespace rt {

template <class T>
struct BasicSphere {
    vec3_t<T> centre;  // O on the slide
    T radius;          // r
};

template <class T>
struct BasicTriangle {
    vec3_t<T> a, b, c;  // the slide's corners; counter-clockwise seen from the front
};

// Where a ray meets a triangle: t along the ray, and the point's barycentric coordinates
// p = (1 - beta - gamma) a + beta b + gamma c (Shirley's names), each in [0, 1] inside.
template <class T>
struct TriangleHit {
    T t;
    T beta;   // the weight of corner b
    T gamma;  // the weight of corner c
};

using Sphere = BasicSphere<float>;
using Triangle = BasicTriangle<float>;

// An open cone or cylinder (equal radii) between two discs, NFF's `c`; the caps are not part of it.
// Scene files bring them (the figures have none); their test is given, in cone.hpp.
struct Cone {
    point3 base;
    float base_radius;  // >= 0
    point3 apex;        // != base
    float apex_radius;  // >= 0, not both radii 0
};

// The unit normals at a triangle's corners, for smooth shading: a mesh that approximates a curved
// surface gives each corner the surface's normal there, and the hit interpolates them.
struct CornerNormals {
    vec3 a, b, c;
};

// A point of a surface and the surface's unit outward normal there.
struct OnSurface {
    point3 p;
    vec3 n;
};

}  // namespace rt
