// The kit's larger NFF scenes, made by program rather than shipped: each is as big as its --depth
// asks, so the acceleration chapters can measure how cost grows with the number of objects.
// They follow the ideas of Eric Haines' Standard Procedural Databases (SPD, 1987) -- a sphereflake
// ("balls"), a recursive tetrahedral pyramid ("tetra"), a branching tree, a fractal mountain
// ("mount"), gears, rings, and the lattice Antonio Costa added in 1993 -- but their shapes, views
// and materials are the kit's own. The last three are measured by SPD's size factor (gears and
// rings: depth + 1, so that depth 0 is one gear or one object; the lattice: depth), and at their
// default depth hold as many objects as SPD's at its default size.
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

// Gears after SPD's "gears": (depth + 1)^3 of them, in depth + 1 layers of (depth + 1)^2 whose
// teeth interleave, above a square floor. Each has 36 teeth; its top and bottom faces are concave
// polygons of 144 corners (142 triangles each) and its sides 144 quads (2 triangles each):
// 572 (depth + 1)^3 triangles and the floor's 2. Depth 3 is SPD's size factor 4: 64 gears,
// 128 faces and 9216 quads, 36608 triangles.
void write_gears(std::ostream& out, int depth);

// Rings after SPD's "rings": objects of six pentagonal rings each, a sphere at every ring's corner
// and a cylinder along every edge, stacked in a square pyramid depth + 1 levels high (n^2 objects
// at the level n from the top) above a square floor. With n = depth + 1: n (n + 1) (2n + 1) / 6
// objects, 5 n (n + 1) (2n + 1) spheres and as many cylinders. Depth 6 is SPD's size factor 7:
// 140 objects, 4200 spheres and 4200 cylinders.
void write_rings(std::ostream& out, int depth);

// A lattice after SPD's "lattice" (Antonio Costa): a cube of depth^3 cells, a sphere at each of its
// (depth + 1)^3 joints and a thin cylinder along each of its 3 depth (depth + 1)^2 edges, above a
// square floor. Depth 12 is SPD's default size factor: 2197 spheres and 6084 cylinders.
void write_lattice(std::ostream& out, int depth);

// The generators above, for the program and the tests.
const std::vector<NffGenerator>& nff_generators();

}  // namespace rt
