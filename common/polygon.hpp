// Planar polygons cut into triangles: what the NFF reader does with `p` and `pp`, whose polygons
// may be concave and have many vertices.
//
// The NFF description (Eric Haines, "Standard Procedural Databases") defines a polygon as planar,
// one-sided, its vertices counterclockwise as you face its visible side. A fan from the first
// vertex covers a convex polygon only; a concave one needs the fan replaced by ear clipping
// (Meisters 1975, "Polygons have ears": every simple polygon of four or more vertices has two
// vertices whose triangle with their neighbours lies inside it; cutting one off leaves a simple
// polygon, so cutting ears until three vertices remain covers the polygon exactly).
//
// The contract: triangulate_polygon returns triangles that cover exactly the polygon's area, never
// outside it, each wound like the polygon (so its normal is the polygon's front), or throws
// InputError saying what is wrong with the polygon. The message names no file: the reader adds
// where the polygon stands.
#pragma once

#include "common/error.hpp"
#include "common/vec.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace rt {

// Indices into the vertex list given to triangulate_polygon.
using TriangleIndices = std::array<std::size_t, 3>;

struct PolygonTriangles {
    std::vector<TriangleIndices> triangles;
    dvec3 normal;  // unit, on the side from which the vertices run counterclockwise (the front)
    double area;   // the polygon's area
};

// Newell's area vector (Newell, in Sutherland, Sproull and Schumacker 1974; Filippo Tampieri,
// "Newell's Method for Computing the Plane Equation of a Polygon", Graphics Gems III): its direction
// is the front normal and its length twice the area, for concave polygons too; unlike the normal of
// the first three vertices, it does not depend on which vertex comes first.
dvec3 polygon_area_vector(const std::vector<point3>& vertices);

// The most vertices one polygon may have: ear clipping costs the square of the vertex count, so a
// count beyond this would take minutes. The classic databases' largest polygons (gear outlines)
// have a few hundred.
constexpr std::size_t polygon_max_vertices = 10000;

// Throws InputError when the polygon has fewer than three distinct vertices, more than
// polygon_max_vertices, all its vertices on one line, a vertex clearly off the plane of the others,
// or two edges that cross or touch (a vertex on another edge, an edge run twice, a keyhole cut:
// such an outline could be covered twice over). Repeated consecutive vertices count as one, and a
// vertex on the straight line between its neighbours stays a corner of the triangles (no
// T-junctions). Vertices and edges in messages are counted from 1 in the given order (edge k runs
// from vertex k to vertex k+1).
// The first two, no area at all, throw DegeneratePolygon: a file can still be rendered without such
// a polygon (it covers nothing), so the reader skips it with a warning; the others it refuses.
struct DegeneratePolygon : InputError {
    using InputError::InputError;
};

PolygonTriangles triangulate_polygon(const std::vector<point3>& vertices);

}  // namespace rt
