#include "tests/grader/picture.hpp"

#include "common/error.hpp"
#include "common/png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rt::grader {

std::string reference_path(const std::string& name)
{
    return std::string(RT_REFERENCES_DIR) + "/" + name + ".png";
}

PictureVerdict compare_with_reference(const Image& actual, const std::string& name, const PictureTolerance& tol)
{
    PictureVerdict verdict;
    std::ostringstream report;
    int width = 0, height = 0;
    std::vector<std::uint8_t> expected;
    try {
        expected = read_png_bytes(reference_path(name), width, height);
    } catch (const InputError& e) {
        verdict.report = std::string(e.what()) + " (regenerate with the `references` target)";
        return verdict;
    }
    if (width != actual.width || height != actual.height) {
        report << "the picture is " << actual.width << "x" << actual.height << " but the reference is " << width
               << "x" << height;
        verdict.report = report.str();
        return verdict;
    }
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
    if (!verdict.matches) {
        const std::string stem = artifacts_dir + "/" + name;
        write_png(stem + ".expected.png", from_srgb8(expected, width, height));
        write_png(stem + ".actual.png", actual);
        write_png(stem + ".diff.png", difference);
        report << "\n  expected:   " << stem << ".expected.png\n  actual:     " << stem
               << ".actual.png\n  difference: " << stem << ".diff.png (red where they differ)";
    }
    verdict.report = report.str();
    return verdict;
}

}  // namespace rt::grader
