// Schlick's approximation against Fresnel's exact reflectance, measured: for each index of
// refraction and each direction (entering the denser medium, leaving it), the largest absolute
// difference over the angles of incidence from 0 to 90 degrees, the angle where it occurs, and
// what each formula costs per call (the median of several passes). Leaving, it is measured twice:
// with the cosine the approximation asks for (cos_t, EXERCISE 03.4), and with cos_i, the classic
// bug of a popular ray-tracing book (its error reaches 0.96 for glass just below the critical angle).
#pragma once

#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "03_reflection_refraction/rounds.hpp"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace rt::fresnel_table {

// The classic bug: Schlick's curve of cos_i on either side. Only total internal reflection is
// still caught (everything reflects there), as the book with the bug has it.
inline float schlick_of_cos_i(float cos_i, float ior)
{
    const float c = std::abs(cos_i);
    const float eta = cos_i < 0.0f ? ior : 1.0f / ior;
    if (eta * eta * (1.0f - c * c) >= 1.0f)
        return 1.0f;
    const float r0 = (ior - 1.0f) / (ior + 1.0f), m = 1.0f - c;
    return r0 * r0 + (1.0f - r0 * r0) * (m * m) * (m * m) * m;
}

using Reflectance = float (*)(float cos_i, float ior);

struct Row {
    float ior;
    std::string side;     // "entering" or "leaving"
    std::string formula;  // "exact", "schlick_cos_i" or "schlick_cos_t" (the right cosine of each side),
                          // or "schlick_cos_i_bug" (cos_i when leaving)
    Reflectance reflectance;
    double max_error;     // largest |formula - exact| over the angles
    double at_degrees;    // the angle of incidence where it occurs
    Timing seconds;       // one pass over all the angles
    std::uint64_t calls;
};

// The cosines of `samples` angles of incidence evenly spaced over [0, 90] degrees, negative when
// the ray arrives from inside (leaving).
inline std::vector<float> cosines(int samples, bool leaving)
{
    std::vector<float> c(samples);
    for (int k = 0; k < samples; ++k) {
        const double degrees = 90.0 * k / (samples - 1);
        c[k] = static_cast<float>((leaving ? -1.0 : 1.0) * std::cos(degrees * 3.14159265358979323846 / 180.0));
    }
    return c;
}

// One row's error: the largest difference from the exact reflectance over the angles.
inline Row measure_error(float ior, bool leaving, const std::string& formula, Reflectance reflectance, int samples)
{
    const std::vector<float> c = cosines(samples, leaving);
    Row row{ior, leaving ? "leaving" : "entering", formula, reflectance, 0.0, 0.0, Timing{}, c.size()};
    for (size_t k = 0; k < c.size(); ++k) {
        const double error = std::abs(static_cast<double>(reflectance(c[k], ior)) - fresnel_dielectric(c[k], ior));
        if (error > row.max_error) {
            row.max_error = error;
            row.at_degrees = 90.0 * static_cast<double>(k) / (samples - 1);
        }
    }
    return row;
}

// Every index and side: the exact formula (its cost; its error is 0 by definition), Schlick's,
// and leaving also Schlick's of cos_i. The times are one pass over the angles, the median of
// `repeat` rounds (rounds.hpp).
inline std::vector<Row> measure_all(const std::vector<float>& iors, int samples, int repeat)
{
    std::vector<Row> rows;
    for (const float ior : iors)
        for (const bool leaving : {false, true}) {
            rows.push_back(measure_error(ior, leaving, "exact", &fresnel_dielectric, samples));
            rows.push_back(measure_error(ior, leaving, leaving ? "schlick_cos_t" : "schlick_cos_i", &fresnel_schlick,
                                         samples));
            if (leaving)
                rows.push_back(measure_error(ior, leaving, "schlick_cos_i_bug", &schlick_of_cos_i, samples));
        }
    const std::vector<float> entering = cosines(samples, false), leaving = cosines(samples, true);
    std::vector<float> got(entering.size());
    std::vector<std::function<void()>> passes;
    for (const Row& r : rows)
        passes.push_back([&, r] {
            const std::vector<float>& c = r.side == "leaving" ? leaving : entering;
            for (size_t k = 0; k < c.size(); ++k)
                got[k] = r.reflectance(c[k], r.ior);
        });
    const std::vector<Timing> seconds = time_in_rounds(repeat, passes);
    for (size_t k = 0; k < rows.size(); ++k)
        rows[k].seconds = seconds[k];
    return rows;
}

}  // namespace rt::fresnel_table
