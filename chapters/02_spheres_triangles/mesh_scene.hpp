// The kit's meshes (common/mesh.hpp) as chapter 02's triangles: a face as a Triangle, and a whole
// mesh into a scene, smooth-shaded through its vertex normals when it has them.
#pragma once

#include "02_spheres_triangles/scene.hpp"
#include "common/mesh.hpp"

#include <array>

namespace rt {

inline Triangle triangle_of(const IndexedMesh& mesh, int face)
{
    const std::array<point3, 3> c = mesh.corners(face);
    return Triangle{c[0], c[1], c[2]};
}

// The mesh's faces into the scene: smooth (through the vertex normals) when it has them.
inline void add_mesh(ShapeScene& scene, const IndexedMesh& mesh, const color& albedo)
{
    for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
        if (mesh.normals.empty()) {
            scene.add_triangle(triangle_of(mesh, f), albedo);
            continue;
        }
        const std::array<int, 3>& c = mesh.faces[f];
        scene.add_triangle(triangle_of(mesh, f), CornerNormals{mesh.normals[c[0]], mesh.normals[c[1]], mesh.normals[c[2]]},
                           albedo);
    }
}

}  // namespace rt
