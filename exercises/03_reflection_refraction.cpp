// Chapter 03, reflection and refraction: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/03_reflection_refraction/03_reflection_refraction.hpp and the lesson in that
// folder's README.md. Each stub compiles and returns a harmless value, so the chapter's program
// always runs (until 03.5 is written it shows only the sky).
// Check your work with:  cmake --build --preset grade --target check_03
// Stuck? Hints in tiers you open one at a time: chapters/03_reflection_refraction/hints.md, or
// ./build/grade/hint 03.1 (tier 1, the idea), ./build/grade/hint 03.1 2 (the trap), ... 3 (the walk-through).
#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include <algorithm>
#include <cmath>

namespace rt {

vec3 reflect(const vec3& v, const vec3& n)
{
    // EXERCISE 03.1: the mirror direction
    // Return the direction v takes after a mirror whose unit normal is n: its part along the surface
    // kept, its part along the normal reversed. Either sign of n gives the same answer, and a ray
    // skimming the surface (v.n = 0) goes on unchanged.
    // Lesson: "Reflection (EXERCISE 03.1)"
    // Stuck? hint 03.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("03.1", v);
}

std::optional<vec3> refract(const vec3& v, const vec3& n, float ior)
{
    // EXERCISE 03.2: the refracted direction, by Snell's law
    // Return the unit direction in which v goes on through the interface (n: the object's outward
    // normal; ior: inside relative to outside), for a ray entering or leaving: the sign of v.n says
    // which. No direction (std::nullopt) under total internal reflection. It must hold in float too:
    // at ior = 1 a ray a hair from grazing still gets through. Lesson: "Refraction (EXERCISE 03.2)"
    // Stuck? hint 03.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("03.2", std::nullopt);
}

float fresnel_dielectric(float cos_i, float ior)
{
    // EXERCISE 03.3: Fresnel's reflectance, exact
    // Return R in [0, 1], the share of unpolarised light that a clear interface of index ior
    // reflects, for cos_i (that is, -v.n): negative when the ray is inside, and the indices swap.
    // Exactly 1 under total internal reflection; never a NaN, even at grazing incidence, ior = 1.
    // Lesson: "Fresnel's reflectance (EXERCISE 03.3)"
    // Stuck? hint 03.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("03.3", 0.0f);
}

float fresnel_schlick(float cos_i, float ior)
{
    // EXERCISE 03.4: Schlick's approximation
    // Return Schlick's polynomial for the reflectance of 03.3 (same cos_i and ior), with R0 the
    // reflectance head-on. Its cosine is the one on the less dense side, which is not always the
    // ray's own (and ior may be below 1). Exactly 1 under total internal reflection.
    // Lesson: "Schlick's approximation (EXERCISE 03.4)"
    // Stuck? hint 03.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("03.4", 0.0f);
}

color trace(const WhittedScene& scene, const Ray& ray, const TraceSettings& settings, int depth, float weight)
{
    // EXERCISE 03.5: Whitted's recursion
    // Return the colour seen along ray: the sky if it hits nothing, else the hit's local shade plus,
    // while depth is below the settings' limit, k_r times what the reflected ray sees and k_t times
    // what the refracted one sees (glass's share split by Fresnel). A secondary ray is traced, and
    // counted, only if its share of the pixel is worth it. Lesson: "The recursion (EXERCISE 03.5)"
    // Stuck? hint 03.5 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("03.5", background(scene, ray.dir));
}

}  // namespace rt
