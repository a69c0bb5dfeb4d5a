// Renders tests/references/ from the solutions: the pictures the picture tests compare with.
// Run it through the `references` target after a deliberate change to a figure, look at every
// picture it writes, and commit them.
#include "common/png.hpp"
#include "tests/ch01/picture.hpp"
#include "tests/ch02/picture.hpp"
#include "tests/ch03/picture.hpp"
#include "tests/ch04/picture.hpp"
#include "tests/ch05/picture.hpp"
#include "tests/ch06/picture.hpp"
#include "tests/ch07/picture.hpp"
#include "tests/ch08/picture.hpp"
#include "tests/ch09/picture.hpp"
#include "tests/ch10/picture.hpp"
#include "tests/scenes/scene_pictures.hpp"

#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

int main()
{
    std::vector<std::pair<std::string, std::function<rt::Image()>>> pictures = {
        {"01_ray_casting", rt::pictures::ch01},
        {"02_spheres_triangles", rt::pictures::ch02},
        {"03_reflection_refraction", rt::pictures::ch03},
        {"04_shadow_feelers", rt::pictures::ch04},
        {"05_soft_shadows", [] { return rt::pictures::ch05(rt::pictures::ch05_reference_spp); }},
        {"06_depth_of_field", rt::pictures::ch06},
        {"07_uniform_grid", rt::pictures::ch07},
        {"08_mailboxing", rt::pictures::ch08},
        {"09_hashed_voxels", rt::pictures::ch09},
        {"10_hierarchies", rt::pictures::ch10},
    };
    for (const rt::pictures::ScenePicture& scene : rt::pictures::scene_pictures())
        pictures.emplace_back(scene.name, scene.render);
    for (const auto& [name, render] : pictures) {
        const std::string path = std::string(RT_REFERENCES_DIR) + "/" + name + ".png";
        rt::write_png(path, render());
        std::cout << "wrote " << path << '\n';
    }
    return 0;
}
