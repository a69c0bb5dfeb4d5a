// The slides' QueryScene for chapter 02's scene (chapter 01 taught it; here it is given): every
// sphere and every triangle is tested with one of your intersection tests, every cone (from scene
// files) with the given one (cone.hpp), the nearest hit wins, and the hit's normal comes from
// your normals (EXERCISE 02.6). The loop itself is the scene's brute-force query (scene_query.hpp),
// the one every chapter shares.
//
// Which sphere and which triangle test answer is a choice (`ShapeTests`, shape_tests.hpp), so the
// program can render the figure with any of them; the kit's default is the precise sphere and
// Moller-Trumbore.
#pragma once

#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "02_spheres_triangles/scene.hpp"
#include "02_spheres_triangles/scene_query.hpp"
#include "02_spheres_triangles/shape_tests.hpp"
#include "common/hit.hpp"

#include <optional>

namespace rt {

// The nearest hit over all spheres, triangles and cones with t strictly inside `range`. Its normal
// is the object's own at the hit (Objects::normal_at: the sphere's, the cone's), except a
// triangle's: the scene's corner normals interpolated at the hit (EXERCISE 02.6), which shade a
// mesh of a curved surface smoothly. `object` numbers the objects as objects.hpp does.
inline std::optional<Hit> closest_hit(const Ray& ray, const ShapeScene& scene, Interval range, ShapeTests tests = {})
{
    const Objects objects = objects_of(scene, tests);
    ObjectHit h;
    if (!brute_force().closest(ray, range, objects, h))
        return std::nullopt;
    const point3 p = ray.at(h.t);
    const ObjectRef o = objects.ref(h.object);
    if (o.kind == ObjectKind::triangle)
        return Hit{h.t, p, interpolated_normal(scene.corner_normals[o.index], {h.t, h.beta, h.gamma}), h.object};
    return Hit{h.t, p, objects.normal_at(h.object, p), h.object};
}

}  // namespace rt
