// The benchmark without Embree (CMake did not find libembree-dev): the kit's structures only.
#include "benchmark/embree_accel.hpp"

#include "common/error.hpp"

namespace rt::bench {

bool have_embree() { return false; }

struct EmbreeAccel::State {};

EmbreeAccel::EmbreeAccel(const Objects&, EmbreeQuality, int)
{
    throw InputError("this build has no Embree: install libembree-dev and configure again");
}

EmbreeAccel::~EmbreeAccel() = default;
bool EmbreeAccel::closest(const Ray&, Interval, const Objects&, ObjectHit&) const { return false; }
bool EmbreeAccel::any(const Ray&, Interval, const Objects&) const { return false; }
std::size_t EmbreeAccel::bytes() const { return 0; }
double EmbreeAccel::build_seconds() const { return 0.0; }

}  // namespace rt::bench
