// Embree's own check of a watertight traversal: a tessellated sphere of radius 1000 centred near
// (148376, 1234, -223423), shot from within 200 of its centre in every direction; the tree's robust
// slab test and the watertight triangle test together must let no ray out.
#pragma once

#include "02_spheres_triangles/mesh_scene.hpp"
#include "common/random.hpp"
#include "tests/grader/graded.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rt::grader {

struct Escapes {
    int triangles = 0, escaped = 0;
    std::string first;  // the first ray that got out
    std::string scene;  // the sphere, in words
};

// Builds a Tree (an Accelerator made from Objects) over the sphere and shoots `rays` rays;
// `explain`, when given, adds its words on the first ray that got out (a diagnosis, suspect.hpp).
template <class Tree>
Escapes escapes_from_closed_sphere(int rays, std::uint64_t seed,
                                   const std::function<std::string(const Tree&, const Ray&, const Objects&)>& explain = {})
{
    const point3 centre(148376.0f, 1234.0f, -223423.0f);
    const IndexedMesh mesh = icosphere(centre, 1000.0f, 4);
    std::vector<Triangle> tris;
    for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
        tris.push_back(triangle_of(mesh, f));
    Objects o;
    o.triangles = tris.data();
    o.triangle_count = static_cast<int>(tris.size());
    o.tests = {SphereTest::precise, TriangleTest::watertight};
    const Tree tree(o);
    Rng rng(seed, 1);
    Escapes e;
    e.triangles = o.triangle_count;
    e.scene = "a sphere of radius 1000 and " + std::to_string(tris.size()) + " triangles centred at " + show(centre);
    for (int k = 0; k < rays; ++k) {
        const point3 from = centre + 200.0f * vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1);
        const vec3 d = glm::normalize(vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1));
        ObjectHit hit;
        if (!tree.closest({from, d}, {0.0f, infinity}, o, hit) && e.escaped++ == 0)
            e.first = show(Ray{from, d}) + (explain ? explain(tree, Ray{from, d}, o) : std::string());
    }
    return e;
}

}  // namespace rt::grader
