// libFuzzer target for the acceleration structures: any bytes make a small legal scene (spheres and
// triangles, coincident, degenerate, huge beside tiny, flat in a plane, far from the origin) and a
// few rays, and every structure of the registry (chapter 10's list, programs/structures.hpp), at a
// density the bytes choose, must answer every ray as brute force does: the same object at the same
// t, bit for bit, and the same any-hit answer.
// A crash, a sanitizer report, an exception or a disagreement is a finding.
#include "10_hierarchies/figure.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace rt;

// Reads the fuzzer's bytes as small numbers, zeros once they run out.
class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    std::uint8_t next() { return at_ < size_ ? data_[at_++] : 0; }
    bool done() const { return at_ >= size_; }

    // A coordinate from a palette that reaches the hard cases: 0, small integers, halves, tiny
    // and huge values, a value far from the origin, and the bytes' own floats.
    float coordinate(float far)
    {
        const std::uint8_t b = next();
        switch (b % 8) {
        case 0: return 0.0f;
        case 1: return static_cast<float>(static_cast<int>(next() % 9) - 4);
        case 2: return 0.5f * static_cast<float>(static_cast<int>(next() % 9) - 4);
        case 3: return 1e-6f * static_cast<float>(static_cast<int>(next() % 9) - 4);
        case 4: return 1e4f * static_cast<float>(static_cast<int>(next() % 9) - 4);
        case 5: return far + static_cast<float>(static_cast<int>(next() % 9) - 4);
        default: {
            std::uint32_t u = 0;
            for (int k = 0; k < 4; ++k)
                u = (u << 8) | next();
            float f;
            std::memcpy(&f, &u, sizeof f);
            return std::isfinite(f) && std::abs(f) < 1e6f ? f : static_cast<float>(b) / 16.0f;
        }
        }
    }

    point3 point(float far) { return {coordinate(far), coordinate(far), coordinate(far)}; }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

void finding(const std::string& what, const LitScene& scene)
{
    std::fprintf(stderr, "accelerator contract broken: %s\nthe scene:\n", what.c_str());
    for (const Sphere& s : scene.spheres)
        std::fprintf(stderr, "  sphere (%.9g %.9g %.9g) radius %.9g\n", s.centre.x, s.centre.y, s.centre.z, s.radius);
    for (const Triangle& t : scene.triangles)
        std::fprintf(stderr, "  triangle (%.9g %.9g %.9g) (%.9g %.9g %.9g) (%.9g %.9g %.9g)\n", t.a.x, t.a.y, t.a.z, t.b.x,
                     t.b.y, t.b.z, t.c.x, t.c.y, t.c.z);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Bytes bytes(data, size);
    const float far = (bytes.next() & 1) ? 1e5f : 0.0f;
    LitScene scene;
    scene.add_material({});
    const int objects = 1 + bytes.next() % 24;
    for (int k = 0; k < objects && !bytes.done(); ++k) {
        const std::uint8_t kind = bytes.next();
        if (kind % 3 == 0) {
            const float radius = std::abs(bytes.coordinate(0.0f));
            if (radius > 0.0f && std::isfinite(radius))
                scene.add_sphere({bytes.point(far), radius}, 0);
        } else {
            const point3 a = bytes.point(far);
            // Another object's copy, a sliver, or three free corners.
            const point3 b = kind % 3 == 1 ? a + vec3(1e-6f, 0.0f, 0.0f) : bytes.point(far);
            scene.add_triangle({a, b, bytes.point(far)}, 0);
        }
        if (kind & 0x80 && !scene.triangles.empty())  // a coincident copy: ties go to the lower number
            scene.add_triangle(scene.triangles.back(), 0);
    }
    const Objects list = objects_of(scene, lit_tests);
    if (list.size() == 0)
        return 0;
    const float lambda = 0.25f * static_cast<float>(1 + bytes.next() % 32);
    // Every structure of the registry (programs/structures.hpp) but brute force, the reference, at
    // the density the bytes choose relative to its default, with a leaf size they choose.
    StructureTuning tuning;
    tuning.leaf_size = 1 + static_cast<int>(bytes.next() % 4);
    std::vector<std::pair<std::string, std::unique_ptr<Accelerator>>> structures;
    for (const Structure& s : beside_brute_force(ch10::structures())) {
        tuning.lambda = s.default_lambda * lambda / ch07::default_lambda;
        structures.emplace_back(s.name, s.make(list, tuning));
    }
    const int rays = 1 + bytes.next() % 16;
    for (int r = 0; r < rays; ++r) {
        const point3 origin = bytes.point(far);
        // Unit directions, as every ray of the kit has (the sphere tests measure t in lengths of it).
        const vec3 toward = bytes.point(0.0f) - point3(0.0f);
        const vec3 dir = glm::normalize(toward);
        if (toward == vec3(0.0f) || !std::isfinite(dir.x) || !std::isfinite(dir.y) || !std::isfinite(dir.z))
            continue;
        const Ray ray{origin, dir};
        const Interval range{(bytes.next() & 1) ? 0.0f : 1e-4f, (bytes.next() & 1) ? infinity : 10.0f};
        ObjectHit want;
        const bool want_found = brute_force().closest(ray, range, list, want);
        const bool want_any = brute_force().any(ray, range, list);
        for (const auto& [name, accel] : structures) {
            ObjectHit got;
            const bool got_found = accel->closest(ray, range, list, got);
            const bool got_any = accel->any(ray, range, list);
            if (got_found != want_found || (want_found && (got.object != want.object || got.t != want.t)) ||
                got_any != want_any) {
                char text[512];
                std::snprintf(text, sizeof text,
                              "%s, %d objects, lambda %g: ray (%.9g %.9g %.9g) along (%.9g %.9g %.9g): brute force %s "
                              "object %d t %.9g (any %d), the structure %s object %d t %.9g (any %d)",
                              name.c_str(), list.size(), static_cast<double>(lambda), origin.x, origin.y, origin.z,
                              dir.x, dir.y, dir.z, want_found ? "hits" : "misses", want.object,
                              static_cast<double>(want.t), want_any, got_found ? "hits" : "misses", got.object,
                              static_cast<double>(got.t), got_any);
                finding(text, scene);
            }
        }
    }
    return 0;
}
