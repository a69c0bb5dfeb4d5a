// Embree 3 (Intel's production ray tracing kernels, Debian's libembree-dev) behind the kit's scene
// query: the same closest and any queries as every structure of chapters 07-10, so the benchmark
// times and checks it exactly as it does them. Built only when CMake finds Embree (RT_HAVE_EMBREE).
//
// Triangles and spheres are Embree's own geometry (its triangle and point-sphere intersectors, the
// ones a production renderer uses); cones, which Embree does not have, are user geometry that calls
// the kit's cone test. Hits come back as the kit's object numbers (spheres, triangles, cones).
#pragma once

#include "02_spheres_triangles/scene_query.hpp"

#include <cstddef>
#include <memory>

namespace rt::bench {

enum class EmbreeQuality { medium, high };

// Whether this build has Embree (false: EmbreeAccel cannot be made, and the benchmark says so).
bool have_embree();

class EmbreeAccel final : public Accelerator {
public:
    // threads: Embree's own build threads (1 for the single-thread rows; 0 for all).
    EmbreeAccel(const Objects& objects, EmbreeQuality quality, int threads);
    ~EmbreeAccel() override;
    EmbreeAccel(const EmbreeAccel&) = delete;
    EmbreeAccel& operator=(const EmbreeAccel&) = delete;

    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override;
    bool any(const Ray& ray, Interval range, const Objects& objects) const override;
    // What Embree allocated for the scene, by its memory monitor (the device's own few KB excluded).
    std::size_t bytes() const override;
    double build_seconds() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace rt::bench
