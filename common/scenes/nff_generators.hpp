// The kit's larger NFF scenes, made by program rather than shipped: each is as big as its --depth
// asks, so the acceleration chapters can measure how cost grows with the number of objects.
// They follow the ideas of three of Eric Haines' Standard Procedural Databases (SPD, 1987) -- a
// sphereflake ("balls"), a recursive tetrahedral pyramid ("tetra"), a branching tree -- but their
// shapes, views and materials are the kit's own.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace rt {

struct NffGenerator {
    std::string name;      // what `nff_generate NAME` calls it
    std::string summary;   // one line for --help
    int default_depth;
    int max_depth;         // the deepest that still writes a file of tens of megabytes, not gigabytes
    void (*write)(std::ostream& out, int depth);
};

// Sphereflake: a sphere with nine spheres a third its size on its surface, each with nine of its
// own, `depth` times; (9^(depth+1) - 1) / 8 spheres above a square floor.
void write_sphereflake(std::ostream& out, int depth);

// A tetrahedron replaced by four half-size tetrahedra at its corners, `depth` times: 4^depth
// tetrahedra, each four triangles facing out, above a square floor.
void write_pyramid(std::ostream& out, int depth);

// A trunk that splits into three thinner, shorter branches, `depth` times: each branch an open
// cone, each joint a sphere that closes the cones, each last branch ending in a leaf sphere:
// (3^(depth+1) - 1) / 2 cones and as many joint spheres, 3^depth leaves, above a square floor.
void write_tree(std::ostream& out, int depth);

// A fractal terrain by midpoint displacement (diamond-square), 2 x 4^depth triangles, with four
// balls above it, after SPD's "mount" (whose mountain is a fractal too); seeded, so the same
// everywhere.
void write_mountain(std::ostream& out, int depth);

// A pile of pick-up sticks: 250 x 2^depth long thin triangles (each 0.9 long, 0.012 wide) at
// random angles in a box 2 wide above a floor; seeded. Each stick crosses many cells of a grid,
// the case mailboxing (chapter 08) is for.
void write_sticks(std::ostream& out, int depth);

// The teapot in a stadium (Haines' name for the case): a small dense mesh, a sphere of
// 20 x 4^depth triangles 2 across, at the centre of a stadium 130 across whose field and stands
// are a few big triangles. No one uniform grid serves both: cells fine enough for the small mesh
// are far too many for the stadium, cells sized for the stadium put the whole mesh in one.
void write_stadium(std::ostream& out, int depth);

// The generators above, for the program and the tests.
const std::vector<NffGenerator>& nff_generators();

}  // namespace rt
