// The parallel render loop: every pixel, `spp` samples each, averaged.
//
// The image is byte-identical at any thread count: a pixel's samples come from its own random
// stream (random.hpp) and are summed in a fixed order, so neither the schedule nor the number of
// threads can change a value.
#pragma once

#include "common/heatmap.hpp"
#include "common/image.hpp"
#include "common/parallel.hpp"
#include "common/progress.hpp"
#include "common/random.hpp"
#include "common/stats.hpp"

#include <glm/common.hpp>

#include <cstdint>
#include <string>

namespace rt {

struct RenderSettings {
    int width = 320;
    int height = 240;
    int spp = 1;              // samples per pixel: 1 samples the pixel centre, more are spread at random
    int threads = 0;          // 0: one a core
    std::uint64_t seed = 1;   // the same seed gives the same image
    bool show_progress = true;
};

// A small render with no progress line, as the picture tests and their references make.
inline RenderSettings quiet_render(int width, int height, int spp = 1)
{
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.spp = spp;
    s.show_progress = false;
    return s;
}

// Where sample s of pixel (i, j) lands, in the pixel coordinates of the slides' window transform:
// pixel centres at whole numbers, pixel (i, j) covering [i - 0.5, i + 0.5] x [j - 0.5, j + 0.5].
struct PixelSample {
    float x, y;
};

inline PixelSample sample_position(int i, int j, int spp, Rng& rng)
{
    if (spp == 1)
        return {static_cast<float>(i), static_cast<float>(j)};
    const float dx = rng.next_float() - 0.5f;
    const float dy = rng.next_float() - 0.5f;
    return {static_cast<float>(i) + dx, static_cast<float>(j) + dy};
}

// `radiance(x, y, rng)` returns the colour seen through pixel position (x, y); it may draw more
// numbers from rng (for lens or light samples in later chapters).
//
// With `variance_of_mean`, also the estimated variance of each pixel's mean, s^2 / spp from the
// spread of its samples (0 at 1 spp): what a noisy picture test needs to know how far a correct
// render may stray from the converged one (tests/grader/picture.hpp).
//
// With `cost`, also what each pixel cost (heatmap.hpp): the growth of the map's counter while the
// pixel's samples are traced. They are all traced on one thread, so no two threads touch a count.
template <class Radiance>
Image render(const RenderSettings& s, const Radiance& radiance, Image* variance_of_mean = nullptr,
             CostMap* cost = nullptr)
{
    Image image(s.width, s.height);
    if (variance_of_mean)
        *variance_of_mean = Image(s.width, s.height);
    Progress progress("rendering", s.show_progress ? s.height : 0);
    const int threads = parallel_for(s.height, s.threads, 1, [&](long row) {
        const int j = static_cast<int>(row);
        for (int i = 0; i < s.width; ++i) {
            Rng rng = pixel_rng(s.seed, i, j, s.width);
            const std::uint64_t counted_before = cost ? counted(local_counts(), cost->counter) : 0;
            color sum(0.0f), sum_sq(0.0f);
            for (int k = 0; k < s.spp; ++k) {
                const PixelSample ps = sample_position(i, j, s.spp, rng);
                const color c = radiance(ps.x, ps.y, rng);
                sum += c;
                sum_sq += c * c;
            }
            if (cost)
                cost->at(i, j) += counted(local_counts(), cost->counter) - counted_before;
            const float n = static_cast<float>(s.spp);
            image.at(i, j) = sum / n;
            if (variance_of_mean && s.spp > 1) {
                // Unbiased sample variance, then divided by n for the variance of the mean.
                const color var = glm::max(sum_sq - sum * sum / n, color(0.0f)) / (n - 1.0f);
                variance_of_mean->at(i, j) = var / n;
            }
        }
        if (s.show_progress)
            progress.tick();
    }, flush_counters);
    // --stats says how many threads drew the picture.
    note_stat("threads", std::to_string(threads));
    return image;
}

}  // namespace rt
