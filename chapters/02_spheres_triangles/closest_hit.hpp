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
// is the sphere's, the triangle's corner normals interpolated at the hit, or the cone's; `object`
// counts the spheres first, then the triangles, then the cones (object_ref, objects.hpp).
inline std::optional<Hit> closest_hit(const Ray& ray, const ShapeScene& scene, Interval range, ShapeTests tests = {})
{
    ObjectHit h;
    if (!brute_force().closest(ray, range, objects_of(scene, tests), h))
        return std::nullopt;
    const point3 p = ray.at(h.t);
    const ObjectRef o = object_ref(scene, h.object);
    switch (o.kind) {
    case ObjectKind::sphere:
        return Hit{h.t, p, sphere_normal(scene.spheres[o.index], p), h.object};
    case ObjectKind::triangle:
        return Hit{h.t, p, interpolated_normal(scene.corner_normals[o.index], {h.t, h.beta, h.gamma}), h.object};
    case ObjectKind::cone:
        break;
    }
    return Hit{h.t, p, cone_normal(scene.cones[o.index], p), h.object};
}

}  // namespace rt
