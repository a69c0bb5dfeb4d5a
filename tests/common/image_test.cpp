#include "common/error.hpp"
#include "common/png.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
#include <filesystem>

using namespace rt;

TEST_CASE("sRGB encoding and decoding invert each other on every 8-bit level", "[common]")
{
    for (int level = 0; level <= 255; ++level) {
        const float linear = srgb_decode(level / 255.0f);
        INFO("level " << level << " decodes to " << linear);
        CHECK(std::lround(255.0f * srgb_encode(linear)) == level);
    }
    CHECK(srgb_encode(0.5f) == Approx(0.7353569f).epsilon(1e-5));  // the curve, not a gamma of 2.2
}

TEST_CASE("a PNG written and read back keeps every byte, and a NaN pixel shows magenta", "[common]")
{
    Image image(7, 3);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 7; ++i)
            image.at(i, j) = color(i / 6.0f, j / 2.0f, 0.25f);
    image.at(6, 2) = color(std::nanf(""), 0.0f, 0.0f);
    image.at(5, 2) = color(3.0f, -1.0f, 0.5f);  // out of range: clamped
    const std::string path = (std::filesystem::temp_directory_path() / "rt_kit_png_test/round_trip.png").string();
    write_png(path, image);
    int w = 0, h = 0;
    const std::vector<std::uint8_t> bytes = read_png_bytes(path, w, h);
    REQUIRE(w == 7);
    REQUIRE(h == 3);
    CHECK(bytes == to_srgb8(image));
    CHECK(bytes[3 * (2 * 7 + 6) + 0] == 255);
    CHECK(bytes[3 * (2 * 7 + 6) + 1] == 0);
    CHECK(bytes[3 * (2 * 7 + 6) + 2] == 255);
    CHECK(bytes[3 * (2 * 7 + 5) + 0] == 255);
    CHECK(bytes[3 * (2 * 7 + 5) + 1] == 0);
    CHECK(count_non_finite(image) == 1);
}

TEST_CASE("reading a missing or broken PNG names the file", "[common]")
{
    CHECK_THROWS_WITH(read_png("/no/such/file.png"), rt::grader::starts_with_text("/no/such/file.png: cannot read"));
    CHECK_THROWS_WITH(write_png("/proc/no/such/dir/x.png", Image(1, 1)), rt::grader::contains_text("cannot write"));
}
