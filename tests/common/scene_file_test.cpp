// Scene files in the programs (common/scene_file.hpp): the NFF view as the kit's camera, the
// image's size, the near plane, the lights; and the chapters' scenes made from a file
// (chapters/NN_name/nff_scene.hpp), which keep every object's order, material and colour.
#include "03_reflection_refraction/nff_scene.hpp"
#include "05_soft_shadows/nff_scene.hpp"
#include "common/scene_file.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rt;
using namespace rt::grader;

namespace {

const char* const two_lights_three_shapes = R"(v
from 0 1 6
at 0 1 0
up 0 1 0
angle 40
hither 0.5
resolution 200 100
l -3 5 4
l 4 1 0 0.5 0.5 0.5
f 0.9 0.2 0.1 0.8 0.3 20 0 0
s 0 1 0 1
f 0.5 0.5 0.5 1 0.6 5 0.7 1.5
p 3
-2 0 -2
2 0 -2
0 0 2
f 0.1 0.8 0.2 0.6 0 0 0 0
c 2 0 0 0.5 2 2 0 0.25
)";

NffScene parse(const std::string& text)
{
    std::istringstream in(text);
    return parse_nff(in, "two_lights.nff");
}

// The file above on disk, for load_scene_render.
std::string write_scene_file()
{
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "rt_scene_file_test.nff";
    std::ofstream(path) << two_lights_three_shapes;
    return path.string();
}

constexpr double degrees = pi / 180.0;

}  // namespace

TEST_CASE("an NFF view's angle spans the image's shorter side, edge to edge", "[common]")
{
    NffView view;
    view.from = {0, 0, 5};
    view.at = {0, 0, 0};
    view.angle_degrees = 40.0f;
    const float half = static_cast<float>(std::tan(20.0 * degrees));
    for (const auto& [w, h] : {std::pair{400, 400}, std::pair{800, 400}, std::pair{400, 800}}) {
        const Camera cam = nff_camera(view, w, h);
        const float shorter_half = std::min(cam.r, cam.t);
        INFO("a " << w << " x " << h << " image with NFF angle 40: the window reaches " << cam.r << " across and "
                  << cam.t << " up at distance 1, expected tan(20 degrees) = " << half << " on the shorter side");
        CHECK(std::abs(shorter_half - half) <= 1e-6f * half);
        CHECK(std::abs(cam.r / cam.t - static_cast<float>(w) / static_cast<float>(h)) <= 1e-5f);
    }
}

TEST_CASE("an NFF view of 179.9 degrees across a 1 x 16384 image still makes a camera, its window finite", "[common]")
{
    NffView view;
    view.from = {0, 0, 5};
    view.at = {0, 0, 0};
    view.angle_degrees = 179.9f;
    const Camera cam = nff_camera(view, 1, 16384);
    const double half = std::tan(0.5 * static_cast<double>(view.angle_degrees) * degrees);  // of the float 179.9
    INFO("the window reaches " << cam.r << " across and " << cam.t << " up; expected " << half << " and "
                               << half * 16384);
    CHECK(std::abs(cam.r - half) <= 1e-6 * half);
    CHECK(std::abs(cam.t - half * 16384) <= 1e-6 * half * 16384);
    CHECK(std::isfinite(cam.t));
}

TEST_CASE("a scene file's image is its resolution, unless the command line gives a size", "[common]")
{
    const std::string path = write_scene_file();
    struct Case {
        std::vector<const char*> args;
        int width, height;
    };
    for (const Case& c : {Case{{}, 200, 100}, Case{{"--width", "50"}, 50, 25}, Case{{"--height", "30"}, 60, 30},
                          Case{{"--width", "7", "--height", "9"}, 7, 9}, Case{{"--width", "1"}, 1, 1}}) {
        CommonOptions o;
        CommandLine cli("prog", "test");
        add_common_options(cli, o);
        std::vector<const char*> argv{"prog"};
        argv.insert(argv.end(), c.args.begin(), c.args.end());
        std::ostringstream out;
        REQUIRE(cli.parse(static_cast<int>(argv.size()), argv.data(), out));
        const SceneRender r = load_scene_render(path, o, cli);
        std::string args;
        for (const char* a : c.args)
            args += std::string(" ") + a;
        INFO("a 200 x 100 scene file with the options '" << args << "': got " << r.settings.width << " x "
                                                          << r.settings.height << ", expected " << c.width << " x " << c.height);
        CHECK(r.settings.width == c.width);
        CHECK(r.settings.height == c.height);
        CHECK(r.camera.nx == c.width);
        CHECK(r.camera.ny == c.height);
    }
    std::filesystem::remove(path);
}

TEST_CASE("an eye ray starts on NFF's near plane, hither in front of the eye, whatever its slant", "[common]")
{
    NffView view;
    view.from = {1, 2, 3};
    view.at = {2, 1, -4};
    view.angle_degrees = 60.0f;
    const Camera cam = nff_camera(view, 64, 48);
    for (const vec3& toward : {-cam.w, glm::normalize(-cam.w + 0.5f * cam.u), glm::normalize(-cam.w - 0.4f * cam.u + 0.3f * cam.v)}) {
        const Ray camera_ray{cam.eye, toward};
        const Ray r = from_near_plane(camera_ray, cam, 0.5f);
        const float depth = glm::dot(r.origin - cam.eye, -cam.w);
        INFO("the camera " << show(camera_ray) << " from the near plane at 0.5: " << show(r) << ", at depth " << depth);
        CHECK(std::abs(depth - 0.5f) <= 1e-6f);
        CHECK(r.dir == camera_ray.dir);
        CHECK(glm::length(glm::cross(r.origin - cam.eye, toward)) <= 1e-6f);  // still on the ray
    }
    // A lens point (chapter 06) beside the eye starts on the same plane.
    const Ray lens_ray{cam.eye + 0.2f * cam.u, glm::normalize(-cam.w + 0.2f * cam.v)};
    CHECK(std::abs(glm::dot(from_near_plane(lens_ray, cam, 2.0f).origin - cam.eye, -cam.w) - 2.0f) <= 1e-6f);
}

TEST_CASE("a scene file's lights: colour over sqrt(L), and in chapter 04 that colour arrives at the view's at", "[common]")
{
    const NffScene nff = parse(two_lights_three_shapes);
    const float root2 = std::sqrt(2.0f);
    CHECK(nff_light_colour(nff, nff.lights[0]) == color(1.0f / root2));
    CHECK(nff_light_colour(nff, nff.lights[1]) == color(0.5f / root2));
    const LitScene lit = lit_scene(nff);
    REQUIRE(lit.lights.size() == 2);
    for (size_t k = 0; k < 2; ++k) {
        const vec3 to_at = nff.view.at - lit.lights[k].position;
        const color arriving = lit.lights[k].intensity / glm::dot(to_at, to_at);
        const color want = nff_light_colour(nff, nff.lights[k]);
        INFO("light " << k << " at " << show(lit.lights[k].position) << ": arrives at the view's at "
                      << show(nff.view.at) << " as " << show(arriving) << ", expected " << show(want));
        CHECK(glm::length(arriving - want) <= 1e-5f * glm::length(want));
    }
}

TEST_CASE("a scene file's light in chapter 05 is a disc facing the view's at, as powerful as chapter 04's point", "[common]")
{
    const NffScene nff = parse(two_lights_three_shapes);
    const LitScene lit = lit_scene(nff);
    const AreaLitScene soft = area_lit_scene(nff, 0.05f);
    CHECK(soft.lit.lights.empty());
    REQUIRE(soft.area_lights.size() == 2);
    for (size_t k = 0; k < 2; ++k) {
        const AreaLight& disc = soft.area_lights[k];
        const float d = glm::length(nff.view.at - disc.centre);
        const PointLight point = as_point_light(disc);
        INFO("light " << k << ": a disc at " << show(disc.centre) << " of radius " << glm::length(disc.axis_u)
                      << " facing " << show(light_normal(disc)) << ", as a point " << show(point.intensity)
                      << "; chapter 04's point " << show(lit.lights[k].intensity));
        CHECK(disc.shape == LightShape::disc);
        CHECK(std::abs(glm::length(disc.axis_u) - 0.05f * d) <= 1e-5f * d);
        CHECK(glm::dot(light_normal(disc), glm::normalize(nff.view.at - disc.centre)) >= 1.0f - 1e-5f);
        CHECK(glm::length(point.intensity - lit.lights[k].intensity) <= 1e-4f * glm::length(lit.lights[k].intensity));
    }
}

TEST_CASE("a scene file's objects keep their order, spheres then triangles then cones, each its own material", "[common]")
{
    const NffScene nff = parse(two_lights_three_shapes);
    const ShapeScene shapes = shape_scene(nff);
    REQUIRE(shapes.spheres.size() == 1);
    REQUIRE(shapes.triangles.size() == 1);
    REQUIRE(shapes.cones.size() == 1);
    // Object 0 the sphere, 1 the triangle, 2 the cone.
    CHECK(object_ref(shapes, 0).kind == ObjectKind::sphere);
    CHECK(object_ref(shapes, 1).kind == ObjectKind::triangle);
    CHECK(object_ref(shapes, 2).kind == ObjectKind::cone);
    CHECK(object_ref(shapes, 2).index == 0);
    CHECK(shapes.albedo_of(0) == nff.materials[0].rgb);
    CHECK(shapes.albedo_of(1) == nff.materials[1].rgb);
    CHECK(shapes.albedo_of(2) == nff.materials[2].rgb);
    CHECK(shapes.cones[0].apex_radius == 0.25f);

    const LitScene lit = lit_scene(nff);
    for (int object = 0; object < 3; ++object) {
        const NffMaterial& m = nff.materials[object];
        const PhongMaterial& p = lit.material_of(object);
        INFO("object " << object << ": " << show(p.diffuse) << " k_s " << show(p.specular) << " p " << p.shininess);
        CHECK(lit.material_index(object) == object);
        CHECK(p.diffuse == m.kd * m.rgb);
        CHECK(p.specular == color(m.ks));
        CHECK(p.shininess == m.shine);
    }

    const WhittedScene whitted = whitted_scene(nff);
    CHECK(whitted.material(0).mirror == 0.3f);
    CHECK(whitted.material(0).transparency == 0.0f);
    CHECK(whitted.material(0).ior == 1.0f);  // opaque: the file's 0 stands for "none"
    CHECK(whitted.material(1).transparency == 0.7f);
    CHECK(whitted.material(1).ior == 1.5f);
    CHECK(whitted.material(2).mirror == 0.0f);
    CHECK(whitted.shapes.albedo_of(2) == nff.materials[2].kd * nff.materials[2].rgb);
    // The sun stands where the first light does, seen from the view's at.
    CHECK(glm::length(whitted.sun.to_sun - glm::normalize(nff.lights[0].position - nff.view.at)) <= 1e-6f);
}
