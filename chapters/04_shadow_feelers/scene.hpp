// Chapter 04's scene: chapter 02's spheres and triangles (and cones, from scene files), a material
// per object, point lights and an ambient light. That is all local shading with shadow feelers
// reads (the kit models only what a scene requires): a material has only the fields the shading
// formula uses.
//
// The shapes sit in flat arrays of geometry only (what the intersection tests read); each shape
// names its material by index, in an array beside it. A hit names its object by one number:
// spheres first, then triangles, then cones, as in chapter 02.
#pragma once

#include "02_spheres_triangles/objects.hpp"
#include "02_spheres_triangles/shapes.hpp"

#include <cassert>
#include <vector>

namespace rt {

class Accelerator;  // 02_spheres_triangles/scene_query.hpp

// What the local shading of EXERCISE 04.1 reads: the parameters of Phong's reflection model
// (Phong 1975), which 04.1 evaluates with Blinn's halfway vector (Blinn 1977), as Shirley's
// Fundamentals of Computer Graphics writes it. The ambient term reflects with `diffuse` too.
struct PhongMaterial {
    color diffuse{0.0f};     // k_d: the fraction of light reflected in every direction, per channel
    color specular{0.0f};    // k_s: the highlight's colour (white for plastic, the metal's own for metal)
    float shininess = 1.0f;  // p: the highlight's exponent; larger is smaller and sharper
};

// A point light: all its light leaves one point (the slides' "point sampling source"), so a
// shadow is either there or not: hard. `intensity` is the light arriving 1 unit away; at distance
// d it is intensity / d^2.
struct PointLight {
    point3 position;
    color intensity;
};

struct LitScene {
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
    // The corner normals of the smooth patches (NFF's `pp`), as chapter 02 shades them; a flat
    // triangle (none given, or a triangle added before any patch) is shaded with its face normal.
    std::vector<CornerNormals> triangle_normals;
    std::vector<bool> triangle_smooth;
    std::vector<Cone> cones;
    // material_indices[ObjectKind::sphere][k] indexes `materials` for spheres[k], and so on.
    PerKind<int> material_indices;
    std::vector<PhongMaterial> materials;

    std::vector<PointLight> lights;
    color ambient{0.0f};     // light arriving from everywhere, with no direction and no shadow
    color background{0.0f};  // the slides' backgroundColour, for rays that hit nothing

    // What answers the scene's queries (radiance.hpp's closest hit and shadow feelers): none,
    // brute force, in chapters 04-06; from chapter 07 on, the program's grid or hierarchy, built
    // over these arrays (it does not own them, nor they it).
    const Accelerator* accelerator = nullptr;

    // The index into `materials` of the object a hit names.
    int material_index(int object) const
    {
        return material_indices[object_ref(*this, object)];
    }

    const PhongMaterial& material_of(int object) const { return materials[material_index(object)]; }

    int add_material(const PhongMaterial& m)
    {
        materials.push_back(m);
        return static_cast<int>(materials.size()) - 1;
    }

    void add_sphere(const Sphere& sphere, int material)
    {
        assert(material >= 0 && material < static_cast<int>(materials.size()));
        spheres.push_back(sphere);
        material_indices[ObjectKind::sphere].push_back(material);
    }

    void add_triangle(const Triangle& tri, int material)
    {
        assert(material >= 0 && material < static_cast<int>(materials.size()));
        triangles.push_back(tri);
        material_indices[ObjectKind::triangle].push_back(material);
    }

    // A triangle shaded smooth: its corners' normals interpolated at each hit (EXERCISE 02.6).
    void add_smooth_triangle(const Triangle& tri, const CornerNormals& normals, int material)
    {
        add_triangle(tri, material);
        triangle_normals.resize(triangles.size());
        triangle_smooth.resize(triangles.size(), false);
        triangle_normals.back() = normals;
        triangle_smooth.back() = true;
    }

    // The corner normals of triangle k when it is a smooth patch, else nullptr.
    const CornerNormals* smooth_normals(int k) const
    {
        return k < static_cast<int>(triangle_smooth.size()) && triangle_smooth[k] ? &triangle_normals[k] : nullptr;
    }

    void add_cone(const Cone& cone, int material)
    {
        assert(material >= 0 && material < static_cast<int>(materials.size()));
        cones.push_back(cone);
        material_indices[ObjectKind::cone].push_back(material);
    }
};

}  // namespace rt
