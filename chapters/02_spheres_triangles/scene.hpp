// Chapter 02's scene: spheres and triangles, each with its colour; triangles also carry their
// corners' normals so meshes of curved surfaces can be shaded smoothly. That is all the figure
// needs (the kit models only what a scene requires). Scene files (NFF) also hold open cones and
// cylinders, so the scene has a third array for them (cone.hpp); the figure has none.
//
// The shapes sit in flat arrays of geometry only (what the intersection tests read); what shading
// reads sits in arrays beside them, index for index. A hit names its object by one number:
// spheres first, then triangles, then cones (objects.hpp's object_ref says which).
#pragma once

#include "02_spheres_triangles/objects.hpp"
#include "02_spheres_triangles/shapes.hpp"

#include <cassert>
#include <vector>

namespace rt {

struct ShapeScene {
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
    std::vector<CornerNormals> corner_normals;  // one per triangle; a flat one has its face normal thrice
    std::vector<Cone> cones;
    PerKind<color> albedo;  // albedo[ObjectKind::sphere][k] is the colour of spheres[k], and so on

    color background{0.0f};  // the slides' backgroundColour, for rays that hit nothing

    // The colour of the object a hit names.
    const color& albedo_of(int object) const
    {
        return albedo[object_ref(*this, object)];
    }

    void add_sphere(const Sphere& sphere, const color& colour)
    {
        spheres.push_back(sphere);
        albedo[ObjectKind::sphere].push_back(colour);
    }

    // A triangle shaded with its corners' normals.
    void add_triangle(const Triangle& tri, const CornerNormals& normals, const color& colour)
    {
        // The add_ functions are the only writers of the shape arrays and their lists: each list
        // stays as long as its array.
        assert(spheres.size() == albedo[ObjectKind::sphere].size() && triangles.size() == corner_normals.size() &&
               triangles.size() == albedo[ObjectKind::triangle].size());
        triangles.push_back(tri);
        corner_normals.push_back(normals);
        albedo[ObjectKind::triangle].push_back(colour);
    }

    void add_cone(const Cone& cone, const color& colour)
    {
        cones.push_back(cone);
        albedo[ObjectKind::cone].push_back(colour);
    }

    // A flat triangle: its face normal, (b - a) x (c - a) made unit, at every corner.
    void add_triangle(const Triangle& tri, const color& colour)
    {
        const vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
        add_triangle(tri, CornerNormals{n, n, n}, colour);
    }
};

}  // namespace rt
