#include "tests/grader/picture.hpp"

#include "common/error.hpp"
#include "common/png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rt::grader {

std::string references_dir = RT_REFERENCES_DIR;

std::string reference_path(const std::string& name)
{
    return references_dir + "/" + name + ".png";
}

namespace {

// Reads the reference's bytes; on a missing file or a size mismatch says why in `verdict`.
bool read_reference(const std::string& name, const Image& actual, std::vector<std::uint8_t>& expected,
                    PictureVerdict& verdict)
{
    int width = 0, height = 0;
    try {
        expected = read_png_bytes(reference_path(name), width, height);
    } catch (const InputError& e) {
        verdict.report = std::string(e.what()) + " (regenerate with the `references` target)";
        return false;
    }
    if (width != actual.width || height != actual.height) {
        verdict.report = "the picture is " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                         " but the reference is " + std::to_string(width) + "x" + std::to_string(height);
        return false;
    }
    return true;
}

// Writes expected, actual and difference PNGs and returns the lines that name them.
std::string write_failure_images(const std::string& name, const Image& expected, const Image& actual,
                                 const Image& difference)
{
    const std::string stem = artifacts_dir + "/" + name;
    write_png(stem + ".expected.png", expected);
    write_png(stem + ".actual.png", actual);
    write_png(stem + ".diff.png", difference);
    return "\n  expected:   " + stem + ".expected.png\n  actual:     " + stem + ".actual.png\n  difference: " +
           stem + ".diff.png (red where they differ)";
}

}  // namespace

PictureVerdict compare_with_reference(const Image& actual, const std::string& name, const PictureTolerance& tol)
{
    PictureVerdict verdict;
    std::ostringstream report;
    std::vector<std::uint8_t> expected;
    if (!read_reference(name, actual, expected, verdict))
        return verdict;
    const int width = actual.width, height = actual.height;
    const std::vector<std::uint8_t> got = to_srgb8(actual);
    Image difference(width, height);
    long differing = 0;
    int worst = 0;
    for (size_t p = 0; p < got.size() / 3; ++p) {
        int d = 0;
        for (int k = 0; k < 3; ++k)
            d = std::max(d, std::abs(int(got[3 * p + k]) - int(expected[3 * p + k])));
        worst = std::max(worst, d);
        if (d > tol.levels) {
            ++differing;
            difference.pixels[p] = color(1.0f, 0.1f, 0.1f) * std::min(1.0f, 0.25f + d / 64.0f);
        }
    }
    const long allowed = static_cast<long>(tol.pixels_fraction * width * height);
    verdict.matches = differing <= allowed;
    report << differing << " of " << width * height << " pixels differ from the reference by more than "
           << tol.levels << " level(s) (at most " << allowed << " may); the largest difference is " << worst
           << " levels of 255";
    if (!verdict.matches)
        report << write_failure_images(name, from_srgb8(expected, width, height), actual, difference);
    verdict.report = report.str();
    return verdict;
}

PictureVerdict compare_noisy_with_reference(const Image& mean, const Image& variance_of_mean, const std::string& name,
                                            const NoisyTolerance& tol)
{
    PictureVerdict verdict;
    std::vector<std::uint8_t> bytes;
    if (!read_reference(name, mean, bytes, verdict))
        return verdict;
    const int width = mean.width, height = mean.height;
    const Image reference = from_srgb8(bytes, width, height);
    // The reference's samples spread as the render's do, over reference_spp samples instead of spp.
    const double reference_share = static_cast<double>(tol.spp) / tol.reference_spp;

    Image difference(width, height);
    int blocks = 0, failing = 0;
    double worst_z = 0.0;
    int worst_i = 0, worst_j = 0;
    for (int j0 = 0; j0 < height; j0 += tol.block)
        for (int i0 = 0; i0 < width; i0 += tol.block) {
            const int j1 = std::min(height, j0 + tol.block), i1 = std::min(width, i0 + tol.block);
            const double n = static_cast<double>((j1 - j0) * (i1 - i0));
            double block_z = 0.0;
            for (int k = 0; k < 3; ++k) {
                double got = 0.0, want = 0.0, var = 0.0, rounding = 0.0;
                for (int j = j0; j < j1; ++j)
                    for (int i = i0; i < i1; ++i) {
                        got += mean.at(i, j)[k];
                        want += reference.at(i, j)[k];
                        var += variance_of_mean.at(i, j)[k];
                        // Half an 8-bit level of the reference's sRGB rounding, in linear terms.
                        const int level = bytes[3 * (static_cast<size_t>(j) * width + i) + k];
                        rounding += 0.5 * (srgb_decode(std::min(255, level + 1) / 255.0f) -
                                           srgb_decode(std::max(0, level - 1) / 255.0f)) / 2.0;
                    }
                const double sigma = std::sqrt(var * (1.0 + reference_share)) / n;
                const double off = std::max(0.0, std::abs(got - want) / n - rounding / n);
                const double z = off > 0.0 ? (sigma > 0.0 ? off / sigma : INFINITY) : 0.0;
                block_z = std::max(block_z, z);
            }
            ++blocks;
            if (block_z > tol.z)
                ++failing;
            if (block_z > worst_z) {
                worst_z = block_z;
                worst_i = i0;
                worst_j = j0;
            }
            const float shade = block_z > tol.z ? std::min(1.0f, 0.3f + static_cast<float>(block_z / (4 * tol.z))) : 0.0f;
            for (int j = j0; j < j1; ++j)
                for (int i = i0; i < i1; ++i)
                    difference.at(i, j) = color(shade, 0.1f * shade, 0.1f * shade);
        }
    verdict.matches = failing == 0;
    std::ostringstream report;
    report << failing << " of " << blocks << " blocks of " << tol.block << "x" << tol.block
           << " pixels stray from the reference by more than " << tol.z << " standard errors (" << tol.spp
           << " spp against a " << tol.reference_spp << "-spp reference); the worst is " << worst_z
           << " standard errors at pixel (" << worst_i << ", " << worst_j << ")";
    if (!verdict.matches)
        report << write_failure_images(name, reference, mean, difference);
    verdict.report = report.str();
    return verdict;
}

}  // namespace rt::grader
