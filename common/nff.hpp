// Scenes from files: the reader of NFF, the Neutral File Format of Eric Haines' Standard Procedural
// Databases (SPD, 1987), in which the classic ray-tracing test scenes are written.
//
// The file is a sequence of commands, each a word followed by numbers; the reader takes it as
// whitespace-separated tokens, so a command's numbers may stand on one line or across several.
//   v            the view, then the six lines below, in any order, each once:
//     from x y z      the eye
//     at x y z        the point seen at the image centre
//     up x y z        which way is up; need not be perpendicular to at - from
//     angle deg       the full field of view in degrees
//     hither d        distance from the eye of the near plane
//     resolution w h  the image size in pixels
//   b r g b      background colour (black when absent)
//   l x y z [r g b]  point light, optionally coloured
//   f r g b Kd Ks Shine T ior  material of the objects after it
//   s x y z r    sphere
//   p n          polygon: n vertices (x y z), planar, possibly concave, counterclockwise seen from
//                its one visible side
//   pp n         patch: n lines x y z nx ny nz, a polygon with a normal per vertex (smooth shading)
//   c            open cone or cylinder, no caps: base x y z, base radius, apex x y z, apex radius
//   #            a comment, to the end of the line
//
// The contract: parse_nff and read_nff return a scene that holds a view, at least one light and
// one object, every number finite, every size positive; or they throw InputError with exactly one
// line, "FILE:LINE: what is wrong", for any malformed input. They never crash, hang, or return an
// empty scene.
#pragma once

#include "common/vec.hpp"

#include <array>
#include <istream>
#include <string>
#include <vector>

namespace rt {

struct NffView {
    point3 from{0.0f};
    point3 at{0.0f, 0.0f, -1.0f};
    vec3 up{0.0f, 1.0f, 0.0f};  // not zero, not parallel to at - from; not necessarily perpendicular
    // SPD: "from the center of top pixel row to bottom pixel row and left column to right column";
    // SPD images are square, so it is both the horizontal and the vertical angle. In (0, 180).
    float angle_degrees = 45.0f;
    float hither = 0.0f;  // >= 0
    int width = 512, height = 512;
    int line = 0;  // where `v` stands
};

// "f red green blue Kd Ks Shine T index_of_refraction"; the fill colour applies to every object
// after it until the next `f`.
struct NffMaterial {
    color rgb{1.0f};  // >= 0
    float kd = 1.0f;     // diffuse weight, in [0, 1]
    float ks = 0.0f;     // mirror reflection and highlight weight, in [0, 1]
    float shine = 0.0f;  // Phong exponent of the highlight, >= 0
    float t = 0.0f;      // transmittance in [0, 1]; T > 0 makes an object two-sided (NFF)
    float ior = 0.0f;    // index of refraction, >= 0; above 0 whenever t > 0 (0 is common for opaque)
    int line = 0;
};

struct NffLight {
    point3 position;
    // NFF gives lights "a non-zero intensity of no particular value" unless a colour is given; the
    // reader then stores white and says so in rgb_given, so a renderer may scale it.
    color rgb{1.0f};  // >= 0
    bool rgb_given = false;
    int line = 0;
};

struct NffSphere {
    point3 center;
    float radius;  // > 0
    int material;  // index into NffScene::materials
    int line;
};

// Polygons (`p`) and patches (`pp`) cut into triangles (polygon.hpp).
struct NffTriangle {
    std::array<point3, 3> p;  // wound like the polygon: counterclockwise seen from its front
    // Unit normals at p[0..2]: the file's vertex normals for a patch (`pp`, smooth), the polygon's
    // front normal at all three for a polygon (`p`, flat).
    std::array<vec3, 3> n;
    bool smooth;
    int material;
    int line;  // of the `p` or `pp` it came from
};

// An open cone or cylinder (equal radii) between two discs; the caps are not part of it.
struct NffCone {
    point3 base;
    float base_radius;  // >= 0
    point3 apex;        // != base
    float apex_radius;  // >= 0, not both radii 0
    int material;
    int line;
};

struct NffScene {
    std::string name;  // the file name, as used in messages
    NffView view;
    color background{0.0f};
    std::vector<NffLight> lights;
    std::vector<NffMaterial> materials;
    std::vector<NffSphere> spheres;
    std::vector<NffTriangle> triangles;
    std::vector<NffCone> cones;

    // Polygons and patches with no area (every vertex on one line, or fewer than three distinct
    // ones), as the SPD generators write a few of (the teapot at size 1 has four): they cover
    // nothing, so they are skipped, each with a warning "FILE:LINE: ...", rather than refused.
    std::vector<std::string> warnings;
    int skipped_polygons = 0;
};

// Reads a whole NFF text from `in`; `name` stands for the file in messages.
NffScene parse_nff(std::istream& in, const std::string& name);

// Opens and reads the file at `path` (a missing file is "PATH:1: no such file").
NffScene read_nff(const std::string& path);

// The numbers of an NFF file are floats below this size: beyond it the squares and products that
// intersection formulas form overflow a float's 3.4e38, and a scene is a typo long before that.
constexpr double nff_number_limit = 1e12;

// The largest image a view may ask for; the same as the programs' --width and --height.
constexpr int nff_max_resolution = 16384;

}  // namespace rt
