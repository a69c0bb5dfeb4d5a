// The benchmark's rays: the same set for every structure of one scene. Primary rays from the
// scene's view, one through each pixel centre; incoherent rays, one diffuse bounce from each
// primary hit (a cosine-weighted direction about the normal on the side the eye sees, from the
// robust origin of chapter 04), seeded, so every structure and every run traces the same rays.
#pragma once

#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/radiance.hpp"
#include "02_spheres_triangles/extremes.hpp"
#include "common/random.hpp"
#include "common/scene_file.hpp"

#include <string>
#include <vector>

namespace rt::bench {

struct RaySet {
    std::string name;  // "primary" or "incoherent"
    std::vector<Ray> rays;
    std::vector<Interval> ranges;
};

inline RaySet primary_rays(const SceneRender& file)
{
    RaySet set{"primary", {}, {}};
    for (int j = 0; j < file.settings.height; ++j)
        for (int i = 0; i < file.settings.width; ++i) {
            set.rays.push_back(file.eye_ray(primary_ray(file.camera, static_cast<float>(i), static_cast<float>(j))));
            set.ranges.push_back({0.0f, infinity});
        }
    return set;
}

// One bounce from each primary ray that hits (found through `scene`'s accelerator).
inline RaySet incoherent_rays(const LitScene& scene, const RaySet& primary, std::uint64_t seed)
{
    RaySet set{"incoherent", {}, {}};
    for (size_t k = 0; k < primary.rays.size(); ++k) {
        const std::optional<Hit> hit = closest_hit(primary.rays[k], scene, primary.ranges[k]);
        if (!hit)
            continue;
        Rng rng(seed, k);
        const vec3 n = glm::dot(hit->ng, primary.rays[k].dir) < 0.0f ? hit->ng : -hit->ng;
        // n plus a uniform unit vector, normalised, is cosine-distributed about n (Shirley).
        vec3 d = n + extremes::random_unit_vector(rng);
        d = glm::dot(d, d) > 1e-12f ? glm::normalize(d) : n;
        set.rays.push_back({offset_ray_origin(hit->p, n, d), d});
        set.ranges.push_back({0.0f, infinity});
    }
    return set;
}

}  // namespace rt::bench
