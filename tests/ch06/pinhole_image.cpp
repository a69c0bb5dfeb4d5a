// EXERCISE 06.3, the whole picture: an aperture of zero is chapter 01's pinhole camera, exactly.
#include "tests/ch06/describe.hpp"
#include "06_depth_of_field/figure.hpp"

#include <cstring>

using namespace rt;

GRADED_TEST("an aperture of 0 renders the figure exactly as chapter 01's pinhole camera, at 4 samples per pixel", "06.3", 2)
{
    // At 4 samples per pixel each sample's position in its pixel comes from the pixel's stream too:
    // a lens of radius 0 that drew numbers would move every later sample, and change the picture.
    RenderSettings s;
    s.width = 32;
    s.height = 18;
    s.spp = 4;
    s.show_progress = false;
    const ThinLens pinhole{0.0f, ch06::figure_lens().focus_distance};
    const Image got = ch06::render_figure(s, pinhole);
    const Camera cam = make_camera(ch06::figure_camera(s.width, s.height));
    const FocusScene scene = ch06::figure_scene();
    const Image want = render(s, [&](float x, float y, Rng&) { return ch06::radiance(scene, primary_ray(cam, x, y)); });
    int differing = 0, first = -1;
    for (size_t p = 0; p < got.pixels.size(); ++p)
        if (std::memcmp(&got.pixels[p], &want.pixels[p], sizeof got.pixels[p]) != 0 && differing++ == 0)
            first = static_cast<int>(p);
    INFO("the figure at " << s.width << "x" << s.height << ", 4 spp, through " << grader::show(pinhole) << ": "
         << differing << " of " << got.pixels.size() << " pixels differ from the pinhole picture rendered with "
         "primary_ray"
         << (first >= 0 ? ", the first at pixel (" + std::to_string(first % s.width) + ", " +
                              std::to_string(first / s.width) + "): got " + grader::show(got.pixels[first]) +
                              ", expected " + grader::show(want.pixels[first])
                        : std::string()));
    CHECK(differing == 0);
}
