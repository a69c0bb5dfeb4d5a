// Triangle meshes the kit makes itself: an icosphere (a sphere of triangles, smooth-shaded through
// its corner normals) and the recursive tetrahedral pyramid (Sierpinski's tetrahedron, flat).
//
// A mesh is indexed: each corner is a number into one vertex array, so the triangles around a
// vertex share its coordinates bit for bit. That is what makes "a ray through a shared vertex or
// edge" a sharp question for the watertightness tests, and it keeps jittering (moving every vertex
// a little, for those tests) from opening gaps of its own.
#pragma once

#include "common/random.hpp"
#include "common/vec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace rt {

struct IndexedMesh {
    std::vector<point3> vertices;
    std::vector<vec3> normals;               // one unit normal per vertex, or empty: shade it flat
    std::vector<std::array<int, 3>> faces;   // counter-clockwise seen from outside

    // A face's corners a, b, c (chapter 02's Triangle is made from them: triangle_of in mesh_scene.hpp).
    std::array<point3, 3> corners(int face) const
    {
        const std::array<int, 3>& f = faces[face];
        return {vertices[f[0]], vertices[f[1]], vertices[f[2]]};
    }
};

namespace mesh_detail {

// Turns a face around when its normal points toward `inside`, so every face is counter-clockwise
// seen from outside whatever order a table listed its corners in.
inline void face_outward(const std::vector<point3>& v, std::array<int, 3>& f, const point3& inside)
{
    const vec3 n = glm::cross(v[f[1]] - v[f[0]], v[f[2]] - v[f[0]]);
    if (glm::dot(n, v[f[0]] - inside) < 0.0f)
        std::swap(f[1], f[2]);
}

// The vertex halfway along edge (i, j), pushed out onto the unit sphere; made once per edge so
// both faces along the edge share it.
inline int midpoint(std::vector<point3>& unit, std::map<std::pair<int, int>, int>& made, int i, int j)
{
    const std::pair<int, int> key{std::min(i, j), std::max(i, j)};
    if (const auto found = made.find(key); found != made.end())
        return found->second;
    unit.push_back(glm::normalize(unit[i] + unit[j]));
    made[key] = static_cast<int>(unit.size()) - 1;
    return made[key];
}

}  // namespace mesh_detail

// The regular icosahedron's 12 corners on the unit sphere, each face split into 4 `subdivisions`
// times with the new vertices pushed out onto the sphere: 20 * 4^subdivisions faces. The vertex
// normals point straight out from the centre, as the sphere's would.
inline IndexedMesh icosphere(const point3& centre, float radius, int subdivisions)
{
    const float g = 0.5f * (1.0f + std::sqrt(5.0f));  // the golden ratio: corners (0, +-1, +-g) and turns
    std::vector<point3> unit = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (point3& p : unit)
        p = glm::normalize(p);
    std::vector<std::array<int, 3>> faces = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
        {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<int, int>, int> made;
        std::vector<std::array<int, 3>> finer;
        for (const std::array<int, 3>& f : faces) {
            const int ab = mesh_detail::midpoint(unit, made, f[0], f[1]);
            const int bc = mesh_detail::midpoint(unit, made, f[1], f[2]);
            const int ca = mesh_detail::midpoint(unit, made, f[2], f[0]);
            finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
        }
        faces = std::move(finer);
    }
    IndexedMesh mesh;
    for (const point3& p : unit) {
        mesh.vertices.push_back(centre + radius * p);
        mesh.normals.push_back(p);
    }
    mesh.faces = std::move(faces);
    for (std::array<int, 3>& f : mesh.faces)
        mesh_detail::face_outward(mesh.vertices, f, centre);
    return mesh;
}

// Sierpinski's tetrahedron: a tetrahedron replaced by the four half-size tetrahedra at its
// corners, `levels` times over: 4^levels tetrahedra of 4 faces each, shaded flat.
inline IndexedMesh sierpinski_tetrahedron(const std::array<point3, 4>& corners, int levels)
{
    IndexedMesh mesh;
    if (levels == 0) {
        const point3 inside = 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
        mesh.vertices.assign(corners.begin(), corners.end());
        mesh.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
        for (std::array<int, 3>& f : mesh.faces)
            mesh_detail::face_outward(mesh.vertices, f, inside);
        return mesh;
    }
    for (int k = 0; k < 4; ++k) {
        std::array<point3, 4> half;
        for (int j = 0; j < 4; ++j)
            half[j] = 0.5f * (corners[k] + corners[j]);
        const IndexedMesh part = sierpinski_tetrahedron(half, levels - 1);
        const int offset = static_cast<int>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
        for (const std::array<int, 3>& f : part.faces)
            mesh.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    }
    return mesh;
}

// Moves every vertex by a random offset in [-amount, amount]^3 (the normals stay): shared
// vertices stay shared, so the mesh stays closed, but no edge lies along an axis any more.
inline void jitter(IndexedMesh& mesh, float amount, Rng& rng)
{
    for (point3& p : mesh.vertices)
        for (int k = 0; k < 3; ++k)
            p[k] += amount * (2.0f * rng.next_float() - 1.0f);
}

}  // namespace rt
