// The triangulation's contract (common/polygon.hpp) on a small integer grid, shared by the polygon
// fuzz target and the fuzz regression tests. On the grid every area is a multiple of 1/2, exact in
// double, so "the triangles add up to the polygon" is checked exactly; and small grids are full of
// what breaks triangulations: collinear vertices, repeated vertices, edges that touch.
#pragma once

#include "common/polygon.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace rt::polygon_contract {

// Two bytes a vertex, each a coordinate in -8..7: a 16 x 16 grid in the plane z = 0.
inline std::vector<point3> grid_outline(const std::uint8_t* data, std::size_t size)
{
    std::vector<point3> vertices;
    for (std::size_t i = 0; i + 1 < size; i += 2)
        vertices.push_back(point3(static_cast<float>(data[i] % 16) - 8.0f, static_cast<float>(data[i + 1] % 16) - 8.0f, 0.0f));
    return vertices;
}

inline double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Empty when every triangle winds like the polygon, lies inside it, and together they add up to
// exactly its area (so, inside and adding up, they cannot overlap); otherwise what broke.
inline std::string broken(const std::vector<point3>& vertices, const PolygonTriangles& cut)
{
    const std::size_t n = vertices.size();
    double twice_area = 0.0;  // signed, positive counterclockwise
    for (std::size_t i = 0; i < n; ++i) {
        const point3 &a = vertices[i], &b = vertices[(i + 1) % n];
        twice_area += cross2(a.x, a.y, b.x, b.y);
    }
    const double orientation = twice_area > 0.0 ? 1.0 : -1.0;
    double covered = 0.0;
    for (const TriangleIndices& t : cut.triangles) {
        const point3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
        const double twice = cross2(b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y) * orientation;
        if (!(twice > 0.0))
            return "a triangle is wound against the polygon, or has no area";
        covered += twice;
        // The centroid, strictly inside the triangle, must be inside the polygon (even-odd rule).
        const double px = (a.x + b.x + c.x) / 3.0, py = (a.y + b.y + c.y) / 3.0;
        bool inside = false;
        for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
            const point3 &vi = vertices[i], &vj = vertices[j];
            if ((vi.y > py) != (vj.y > py) && px < (vj.x - vi.x) * (py - vi.y) / (vj.y - vi.y) + vi.x)
                inside = !inside;
        }
        if (!inside)
            return "a triangle lies outside the polygon";
    }
    if (covered != std::abs(twice_area))
        return "the triangles do not add up to the polygon's area";
    return "";
}

}  // namespace rt::polygon_contract
