// EXERCISE 03.5: Whitted's recursion: local shade plus k_r S plus k_t T, with a depth limit and a
// cut-off on a ray's weight.
#include "tests/ch03/optics_reference.hpp"
#include "tests/ch03/picture.hpp"
#include "tests/ch03/trace_scenes.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::traces;

namespace {

// Between the facing mirrors with k_s = 0.5, whose reflected rays weigh exactly 0.5, 0.25, 0.125,
// ..., at max_depth 16: with `min_weight`, expects `rays` reflected rays and the colour sum x L (sum
// is 1 + 0.5 + ... over the bounces traced). `why`, where given, says which ray is on the boundary.
void check_cut_off_between_halving_mirrors(float min_weight, int rays, float sum, const char* why = nullptr)
{
    const color L = mirror_albedo * ambient;
    TraceSettings settings;
    settings.max_depth = 16;
    settings.min_weight = min_weight;
    const Traced got = run(facing_mirrors(0.5f), between_mirrors, settings);
    std::ostringstream boundary;
    if (why)
        boundary << std::setprecision(9) << " (min_weight " << min_weight << "; " << why << ")";
    INFO(got.report << boundary.str() << "; mirrors of k_s = 0.5: expected " << rays << " reflected rays and "
         << show(sum * L));
    CHECK(got.rays.reflected == static_cast<std::uint64_t>(rays));
    CHECK(near(got.colour, sum * L));
}

}  // namespace

GRADED_TEST("trace: a ray that misses sees the sky; one that hits a dull wall sees its local shade, and no secondary ray is traced", "03.5", 3)
{
    const WhittedScene scene = square_ahead(Material{});
    const TraceSettings settings;

    const Traced miss = run(scene, Ray{head_on.origin, {0, 0, 1}}, settings);
    INFO(miss.report << "; expected the sky " << show(sky));
    CHECK(near(miss.colour, sky));

    const color expected = lit(scene, square_albedo, {0, 0, 1});
    const Traced hit = run(scene, head_on, settings);
    INFO(hit.report << "; expected the wall's local shade " << show(expected) << " and no secondary rays");
    CHECK(near(hit.colour, expected));
    CHECK(hit.rays.reflected == 0);
    CHECK(hit.rays.refracted == 0);
}

GRADED_TEST("trace: a mirror adds k_s times what its reflected ray sees (Whitted's k_s S), and stops at max_depth = 0", "03.5", 3)
{
    // A mirror floor (k_s = 0.7, a dull grey of its own) before a red wall at z = -5: the ray comes
    // down at 45 degrees onto the floor at (0.3, 0, -1) and its reflection meets the wall at
    // (0.3, 4, -5).
    WhittedScene scene = empty_scene();
    const color floor_albedo{0.1f}, wall_albedo{0.9f, 0.2f, 0.1f};
    add_square(scene, {0, 0, -2}, {1, 0, 0}, {0, 0, -1}, 3.0f, floor_albedo, mirror(0.7f));
    add_square(scene, {0, 2, -5}, {1, 0, 0}, {0, 1, 0}, 3.0f, wall_albedo, Material{});
    const Ray ray{{0.3f, 1, 0}, glm::normalize(vec3(0, -1, -1))};
    const color floor_local = lit(scene, floor_albedo, {0, 1, 0}), wall_local = lit(scene, wall_albedo, {0, 0, 1});

    TraceSettings settings;
    const Traced once = run(scene, ray, settings);
    const color expected = floor_local + 0.7f * wall_local;
    INFO(once.report << "; expected the floor's local shade " << show(floor_local) << " + 0.7 x the wall's "
         << show(wall_local) << " = " << show(expected) << ", after 1 reflected ray");
    CHECK(near(once.colour, expected));
    CHECK(once.rays.reflected == 1);
    CHECK(once.rays.refracted == 0);

    settings.max_depth = 0;
    const Traced casting = run(scene, ray, settings);
    INFO(casting.report << "; at max_depth 0 expected the floor's local shade alone, " << show(floor_local));
    CHECK(near(casting.colour, floor_local));
    CHECK(casting.rays.reflected == 0);
}

GRADED_TEST("trace: between two facing mirrors the recursion stops after max_depth bounces", "03.5", 3)
{
    // Every bounce adds L = albedo * ambient, k_s times less each time: after d bounces the colour
    // is L (1 + k_s + ... + k_s^d), from d reflected rays.
    const float k_s = 0.8f;
    const WhittedScene scene = facing_mirrors(k_s);
    const color L = mirror_albedo * ambient;
    for (const int depth : {0, 1, 2, 5, 12}) {
        TraceSettings settings;
        settings.max_depth = depth;
        settings.min_weight = 0.0f;
        const Traced got = run(scene, between_mirrors, settings);
        color expected(0.0f);
        float k = 1.0f;
        for (int j = 0; j <= depth; ++j, k *= k_s)
            expected += k * L;
        INFO(got.report << "; expected " << show(expected) << " after " << depth << " reflected rays");
        CHECK(got.rays.reflected == static_cast<std::uint64_t>(depth));
        CHECK(near(got.colour, expected));
    }
}

GRADED_TEST("trace: a ray whose weight would fall below min_weight is not traced, whatever max_depth allows", "03.5", 3)
{
    // Mirrors with k_s = 0.5: the reflected rays weigh 0.5, 0.25, 0.125, 0.0625, ...
    check_cut_off_between_halving_mirrors(0.3f, 1, 1.5f);
    check_cut_off_between_halving_mirrors(0.1f, 3, 1.875f);
    check_cut_off_between_halving_mirrors(0.01f, 6, 1.984375f);
    // Glass head-on reflects F = 0.04: with min_weight 0.05 only the refracted rays are traced,
    // in and out, and 0.96^2 of the sky comes through.
    TraceSettings settings;
    settings.min_weight = 0.05f;
    const Traced glass = run(glass_sphere(1.5f), Ray{{0, 0, 0}, {0, 0, -1}}, settings);
    INFO(glass.report << "; through a glass sphere with min_weight 0.05: expected 0 reflected and 2 refracted rays and "
         << show(0.9216f * sky));
    CHECK(glass.rays.reflected == 0);
    CHECK(glass.rays.refracted == 2);
    CHECK(near(glass.colour, 0.9216f * sky));
    // With min_weight 0.97 the refracted share (0.96) is cut too: no secondary ray at all, and the
    // glass shows what it shows at max_depth 0.
    settings.min_weight = 0.97f;
    const Traced cut = run(glass_sphere(1.5f), Ray{{0, 0, 0}, {0, 0, -1}}, settings);
    TraceSettings no_depth;
    no_depth.max_depth = 0;
    const Traced flat = run(glass_sphere(1.5f), Ray{{0, 0, 0}, {0, 0, -1}}, no_depth);
    INFO(cut.report << "; through a glass sphere with min_weight 0.97: expected no secondary rays and "
         << show(flat.colour) << ", the colour at max_depth 0");
    CHECK(cut.rays.reflected == 0);
    CHECK(cut.rays.refracted == 0);
    CHECK(near(cut.colour, flat.colour));
}

GRADED_TEST("trace: glass splits its light by Fresnel; through the centre of a glass sphere the sky comes back F + (1 - F)^2 times", "03.5", 3)
{
    // Head-on, F = 0.04 at both surfaces. At max_depth 2: F S (the front's reflection, which sees
    // the sky behind the eye) + (1 - F) [F x 0 (the glass itself, at the depth limit) + (1 - F) S].
    TraceSettings settings;
    settings.max_depth = 2;
    settings.min_weight = 0.0f;
    const double F = optics::fresnel_reference(1.0, 1.5);
    const color expected = static_cast<float>(F + (1.0 - F) * (1.0 - F)) * sky;
    const Traced got = run(glass_sphere(1.5f), Ray{{0, 0, 0}, {0, 0, -1}}, settings);
    INFO(got.report << "; expected " << show(expected) << " after 2 reflected and 2 refracted rays");
    CHECK(near(got.colour, expected));
    CHECK(got.rays.reflected == 2);
    CHECK(got.rays.refracted == 2);
}

GRADED_TEST("trace: a surface that is both mirror and glass reflects k_s + k_t F and refracts k_t (1 - F)", "03.5", 2)
{
    // Whitted's k_s S + k_t T with both terms: a black sphere with mirror k_s = 0.3 and glass
    // k_t = 0.5, head-on. At max_depth 1 the reflected ray sees the sky behind the eye and the
    // refracted one the black inside of the back wall: (k_s + k_t F) S, after one ray of each.
    Material both = glass(1.5f);
    both.mirror = 0.3f;
    both.transparency = 0.5f;
    WhittedScene scene = empty_scene();
    scene.add_sphere({{0, 0, -3}, 1}, color(0.0f), both);
    TraceSettings settings;
    settings.max_depth = 1;
    settings.min_weight = 0.0f;
    const double F = optics::fresnel_reference(1.0, 1.5);
    const color expected = static_cast<float>(0.3 + 0.5 * F) * sky;
    const Traced got = run(scene, Ray{{0, 0, 0}, {0, 0, -1}}, settings);
    INFO(got.report << "; a black sphere, mirror 0.3 and glass 0.5 (F = " << F << "): expected " << show(expected)
         << " after 1 reflected and 1 refracted ray: the mirror's share and the glass's reflected share add");
    CHECK(near(got.colour, expected));
    CHECK(got.rays.reflected == 1);
    CHECK(got.rays.refracted == 1);
}

GRADED_TEST("trace: settings.fresnel picks the reflectance, and total internal reflection traces no refracted ray", "03.5", 2)
{
    // At max_depth 1 a ray that meets the glass at 60 degrees sees F S: the refracted ray finds
    // only the glass's far side (no colour of its own) at the depth limit.
    const WhittedScene scene = glass_sphere(1.5f);
    const float height = static_cast<float>(std::sin(optics::radians(60.0)));
    const Ray oblique{{0, height, 0}, {0, 0, -1}};
    const double cos_i = std::cos(optics::radians(60.0));
    for (const FresnelModel model : {FresnelModel::exact, FresnelModel::schlick}) {
        TraceSettings settings;
        settings.max_depth = 1;
        settings.fresnel = model;
        const double F = model == FresnelModel::exact ? optics::fresnel_reference(cos_i, 1.5)
                                                      : optics::schlick_reference(cos_i, 1.5);
        const Traced got = run(scene, oblique, settings);
        INFO(got.report << "; at 60 degrees expected F S = " << F << " x the sky = "
             << show(static_cast<float>(F) * sky));
        CHECK(near(got.colour, static_cast<float>(F) * sky, 2e-5f));
        CHECK(got.rays.reflected == 1);
        CHECK(got.rays.refracted == 1);
    }
    // From inside, 0.9 above the centre, along +x: the wall is met at 64 degrees, beyond the
    // critical 41.8: one reflected ray, no refracted one.
    TraceSettings settings;
    settings.max_depth = 1;
    const Traced tir = run(scene, Ray{{0, 0.9f, -3}, {1, 0, 0}}, settings);
    INFO(tir.report << "; expected black (the glass has no colour of its own) after 1 reflected and 0 refracted rays");
    CHECK(tir.rays.reflected == 1);
    CHECK(tir.rays.refracted == 0);
    CHECK(near(tir.colour, color(0.0f)));
}

STABILITY_TEST("trace: no NaN or infinity in the figure at depth 16 with no cut-off, grazing silhouettes included", "03.5", 1)
{
    RenderSettings s;
    s.width = 64;
    s.height = 36;
    s.show_progress = false;
    TraceSettings deep;
    deep.max_depth = 16;
    deep.min_weight = 0.0f;
    reset_counters();
    const Image image = ch03::render_figure(s, deep);
    const Rays rays = secondary_rays();
    INFO("chapter 03's figure at 64x36, " << show(deep) << ": " << count_non_finite(image)
         << " pixels with a NaN or infinity, after " << show(rays));
    CHECK(count_non_finite(image) == 0);
    CHECK(rays.reflected > 0);
    CHECK(rays.refracted > 0);
}

GRADED_TEST("trace: a secondary ray whose weight is exactly min_weight is traced (at least); one float step short of it is not", "03.5", 2)
{
    // Mirrors with k_s = 0.5: the reflected rays weigh exactly 0.5, 0.25, 0.125, ...
    check_cut_off_between_halving_mirrors(0.25f, 2, 1.75f, "the second ray weighs 0.25, exactly min_weight: traced");
    check_cut_off_between_halving_mirrors(std::nextafter(0.25f, 1.0f), 1, 1.5f,
                                          "the second ray weighs 0.25, one float step below min_weight: not traced");
    check_cut_off_between_halving_mirrors(std::nextafter(0.25f, 0.0f), 2, 1.75f,
                                          "the second ray weighs 0.25, one float step above min_weight: traced");
    check_cut_off_between_halving_mirrors(0.5f, 1, 1.5f, "the first ray weighs 0.5, exactly min_weight: traced");
    check_cut_off_between_halving_mirrors(std::nextafter(0.5f, 1.0f), 0, 1.0f,
                                          "the first ray weighs 0.5, just below min_weight: not traced");
}

GRADED_TEST("trace: with min_weight 0 a surface with no mirror or glass share (k = 0) still traces no secondary ray", "03.5", 2)
{
    // "Only when its k > 0": a dull wall has k_r = k_t = 0, and 0 >= min_weight = 0 must not let a
    // ray through.
    const WhittedScene scene = square_ahead(Material{});
    const color expected = lit(scene, square_albedo, {0, 0, 1});
    const Traced dull = run(scene, head_on, with_min_weight(0.0f));
    INFO(dull.report << "; a dull wall with min_weight 0: expected its local shade " << show(expected)
         << " and no secondary rays");
    CHECK(dull.rays.reflected == 0);
    CHECK(dull.rays.refracted == 0);
    CHECK(near(dull.colour, expected));
}

GRADED_TEST("trace: the search starts at secondary_t_min (1e-4): a surface nearer than that is not seen, one a little beyond it is", "03.5", 2)
{
    // A red wall across the ray at distance d, and a dull grey one behind it at 3. At d = 5e-5 the
    // red wall lies before secondary_t_min and the ray sees the grey one; at d = 2e-4 and beyond
    // it sees the red one. (A t_min of 0 sees red at 5e-5; one of 1e-3, Shirley's, grey at 2e-4.)
    const color red{0.9f, 0.1f, 0.1f}, grey{0.4f};
    for (const float d : {5e-5f, 2e-4f, 5e-4f}) {
        WhittedScene scene = empty_scene();
        add_square_across(scene, -d, red, Material{});
        add_square_across(scene, -3.0f, grey, Material{});
        const bool sees_red = d > secondary_t_min;
        const color expected = lit(scene, sees_red ? red : grey, {0, 0, 1});
        const Traced got = run(scene, head_on, TraceSettings{});
        INFO(got.report << "; a red wall " << d << " ahead and a grey one 3 ahead: expected the "
             << (sees_red ? "red" : "grey") << " wall's shade " << show(expected) << " (secondary_t_min = "
             << secondary_t_min << ")");
        CHECK(near(got.colour, expected));
    }
}

GRADED_TEST("trace: a ray that misses sees background(scene, ray.dir), the sky in its own direction, and a mirror shows the sky along its reflected ray", "03.5", 2)
{
    // A sky that is not one colour: its horizon (scene.shapes.background) and zenith differ, so the
    // colour a missing ray sees depends on its direction.
    WhittedScene scene = empty_scene();
    scene.zenith = color(0.05f, 0.1f, 0.6f);
    const color floor_albedo{0.1f};
    add_square(scene, {0, 0, -2}, {1, 0, 0}, {0, 0, -1}, 3.0f, floor_albedo, mirror(0.7f));

    const Ray up{{0.3f, 1, 0}, glm::normalize(vec3(0.3f, 0.6f, -1.0f))};
    const color sky_up = background(scene, up.dir);
    const Traced miss = run(scene, up, TraceSettings{});
    INFO(miss.report << "; expected the sky in the ray's direction, background(scene, ray.dir) = " << show(sky_up)
         << " (the horizon colour is " << show(scene.shapes.background) << ", the zenith's " << show(scene.zenith) << ")");
    CHECK(near(miss.colour, sky_up));

    // Down at 45 degrees onto the mirror floor at (0.3, 0, -1): the reflected ray leaves along
    // (0, 1, -1) / sqrt(2) and sees the sky there.
    const Ray down{{0.3f, 1, 0}, glm::normalize(vec3(0, -1, -1))};
    const color sky_reflected = background(scene, glm::normalize(vec3(0, 1, -1)));
    const color expected = lit(scene, floor_albedo, {0, 1, 0}) + 0.7f * sky_reflected;
    const Traced mirrored = run(scene, down, TraceSettings{});
    INFO(mirrored.report << "; expected the floor's local shade + 0.7 x the sky along (0, 1, -1) / sqrt(2), "
         << show(sky_reflected) << ": " << show(expected));
    CHECK(near(mirrored.colour, expected));
    CHECK(mirrored.rays.reflected == 1);
}

GRADED_TEST("trace: a glass share as small as the least float (transparency 2^-149) traces its refracted ray, with min_weight 0 and with min_weight 2^-149 (at least)", "03.5", 1)
{
    // "Only when its k > 0", one float step above 0: a pane of glass with transparency 2^-149 (a
    // denormal), met head-on, has k_t = 2^-149 (1 - F) = 2^-149 > 0 (F = 0.04): one refracted ray,
    // with min_weight 0 and with min_weight 2^-149 exactly (its weight is at least that). Its mirror
    // share 2^-149 F rounds to 0: no reflected ray.
    const WhittedScene scene = square_ahead(glass(1.5f, std::numeric_limits<float>::denorm_min()));
    for (const float min_weight : {0.0f, std::numeric_limits<float>::denorm_min()}) {
        const Traced faint = run(scene, head_on, with_min_weight(min_weight));
        INFO(faint.report << "; glass of transparency 2^-149 (k_t = 2^-149 > 0, its weight 2^-149 >= min_weight) met "
                             "head-on: expected one refracted ray and no reflected one");
        CHECK(faint.rays.refracted == 1);
        CHECK(faint.rays.reflected == 0);
    }
}

GRADED_TEST("trace: with min_weight 0 a mirror share as small as the least float (mirror 2^-149) still traces its reflected ray", "03.5", 1)
{
    // "Only when its k > 0", one float step above 0: a mirror with k_s = 2^-149 (a denormal) and
    // min_weight 0 sends its one reflected ray; it adds next to nothing to the colour.
    const WhittedScene scene = square_ahead(mirror(std::numeric_limits<float>::denorm_min()));
    const Traced faint = run(scene, head_on, with_min_weight(0.0f));
    INFO(faint.report << "; a mirror of k_s = 2^-149 (> 0), min_weight 0: expected one reflected ray and no "
                         "refracted one");
    CHECK(faint.rays.reflected == 1);
    CHECK(faint.rays.refracted == 0);
}

GRADED_TEST("trace: with min_weight 0 a glass share that rounds to exactly 0 (transparency 2^-149, ior 10 head-on) traces no refracted ray", "03.5", 1)
{
    // Head-on at ior 10, F = (9 / 11)^2 = 0.669: k_t = 2^-149 (1 - F) rounds to 0 and is no share
    // at all (k > 0 is the rule, and 0 >= min_weight = 0 must not let it through), while
    // k_r = 2^-149 F rounds to 2^-149 > 0: one reflected ray, no refracted one.
    const WhittedScene scene = square_ahead(glass(10.0f, std::numeric_limits<float>::denorm_min()));
    const Traced faint = run(scene, head_on, with_min_weight(0.0f));
    INFO(faint.report << "; glass of transparency 2^-149 and ior 10 met head-on (k_t rounds to 0, k_r to 2^-149), "
                         "min_weight 0: expected one reflected ray and no refracted one");
    CHECK(faint.rays.refracted == 0);
    CHECK(faint.rays.reflected == 1);
}

GRADED_TEST("trace: a refracted ray carries weight times k_t: through two panes of glass (k_t = 0.48) with min_weight 0.3 only the first refracts", "03.5", 1)
{
    // Two panes of glass (transparency 0.5, ior 1.5) across the ray, met head-on: F = 0.04, so
    // k_t = 0.48 and k_r = 0.02. The first refracted ray weighs 0.48 >= 0.3 and is traced; at the
    // second pane its own refracted ray would weigh 0.48 * 0.48 = 0.23 < 0.3: not traced.
    const Material pane = glass(1.5f, 0.5f);
    WhittedScene scene = square_ahead(pane);
    add_square_across(scene, -7.0f, square_albedo, pane);
    const Traced panes = run(scene, head_on, with_min_weight(0.3f));
    INFO(panes.report << "; two glass panes, k_t = 0.48 each, min_weight 0.3: expected one refracted ray (weight "
                         "0.48) and not a second (0.23), no reflected ray (0.02)");
    CHECK(panes.rays.refracted == 1);
    CHECK(panes.rays.reflected == 0);
}
