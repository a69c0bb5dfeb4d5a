// Chapter 03's scene: chapter 02's spheres and triangles (and cones, from scene files), each with
// what Whitted's shading reads of it (a mirror's share, a glass's share and index of refraction, a
// floor's checkers), one directional light, and an ambient term. That is all the figure needs
// (the kit models only what a scene requires): no point lights and no shadows yet, those are
// chapter 04's lesson.
//
// The geometry and the diffuse colours stay in chapter 02's ShapeScene, so chapter 02's
// closest_hit answers every query; what chapter 03 adds sits in arrays beside them, index for
// index, as ShapeScene keeps its colours.
#pragma once

#include "02_spheres_triangles/scene.hpp"

#include <cassert>
#include <cmath>
#include <vector>

namespace rt {

// What a surface does with the light that reaches it, besides its diffuse colour: Whitted's
// (1980, "An Improved Illumination Model for Shaded Display") k_s and k_t.
struct Material {
    float mirror = 0.0f;        // k_s of a mirror: the share of the reflected ray's colour, whatever the angle
    float transparency = 0.0f;  // k_t of glass: the share that meets a clear interface, which Fresnel's
                                // reflectance then splits between the reflected and the refracted ray
    float ior = 1.0f;           // index of refraction of the inside (where the normal points away from),
                                // relative to the outside: 1.5 for glass in air
    float checker = 0.0f;       // > 0: a checkerboard of squares this wide in x and z...
    color odd{0.0f};            // ... whose odd squares have this colour instead of the albedo
};

// A directional light: parallel rays from a direction, like the sun's. The sky shows it as a small
// bright glow, so mirrors and glass, which only show what their rays see, show its highlight.
struct Sun {
    vec3 to_sun{0.0f, 1.0f, 0.0f};  // unit, from the scene toward the sun
    color colour{1.0f};             // what a surface facing the sun receives
    float glow = 0.0f;              // how bright the sun's disc is in the sky, as a multiple of colour
    float glow_exponent = 1000.0f;  // the glow falls off as cos^exponent of the angle from the sun
};

struct WhittedScene {
    ShapeScene shapes;  // geometry and diffuse colours (chapter 02); shapes.background is the sky at the horizon
    PerKind<Material> materials;  // materials[ObjectKind::sphere][k] is the material of shapes.spheres[k], and so on
    color zenith{0.0f};  // the sky straight up; it blends into shapes.background toward the horizon
    Sun sun;
    color ambient{0.0f};  // Whitted's I_a: the light that reaches every surface from everywhere

    // The material of the object a hit names (Hit::object: spheres first, then triangles, then cones).
    const Material& material(int object) const
    {
        return materials[object_ref(shapes, object)];
    }

    // The diffuse colour of the object at point p: its albedo, or a checker square's colour.
    color albedo(int object, const point3& p) const;

    void add_sphere(const Sphere& sphere, const color& albedo, const Material& material)
    {
        shapes.add_sphere(sphere, albedo);
        materials[ObjectKind::sphere].push_back(material);
    }

    // A flat triangle (its face normal at every corner).
    void add_triangle(const Triangle& tri, const color& albedo, const Material& material)
    {
        assert(shapes.triangles.size() == materials[ObjectKind::triangle].size());
        shapes.add_triangle(tri, albedo);
        materials[ObjectKind::triangle].push_back(material);
    }
};

inline color WhittedScene::albedo(int object, const point3& p) const
{
    const Material& m = material(object);
    const color& base = shapes.albedo_of(object);
    if (m.checker <= 0.0f)
        return base;
    // Square (cx, cz) is odd when cx + cz is odd; fmod keeps this exact for far squares, where
    // casting the index to an integer would overflow.
    const float cx = std::floor(p.x / m.checker), cz = std::floor(p.z / m.checker);
    return std::fmod(cx + cz, 2.0f) != 0.0f ? m.odd : base;
}

}  // namespace rt
