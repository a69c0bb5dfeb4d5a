#include "common/scenes/nff_generators.hpp"

#include "common/mesh.hpp"
#include "common/random.hpp"
#include "common/vec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <utility>
#include <vector>

namespace rt {

namespace {

constexpr double pi = 3.14159265358979323846;

// Digits a coordinate is written with: enough that the smallest objects of the deepest scenes
// (a sphereflake's spheres at 3^-6 of the first, a pyramid's tetrahedra at 2^-8) keep their shape.
constexpr int written_digits = 7;

double radians(double degrees) { return degrees * pi / 180.0; }

// Writes NFF commands, one a line, as the SPD programs print them.
class NffWriter {
public:
    explicit NffWriter(std::ostream& out) : out_(out) { out_ << std::setprecision(written_digits); }

    void comment(const std::string& text) { out_ << "# " << text << '\n'; }

    void view(const dvec3& from, const dvec3& at, double angle, int resolution)
    {
        out_ << "v\nfrom " << xyz(from) << "\nat " << xyz(at) << "\nup 0 1 0\nangle " << angle
             << "\nhither 0.01\nresolution " << resolution << ' ' << resolution << '\n';
    }
    void background(const dvec3& rgb) { out_ << "b " << xyz(rgb) << '\n'; }
    void light(const dvec3& p) { out_ << "l " << xyz(p) << '\n'; }
    // f r g b Kd Ks Shine T ior
    void material(const dvec3& rgb, double kd, double ks, double shine)
    {
        out_ << "f " << xyz(rgb) << ' ' << kd << ' ' << ks << ' ' << shine << " 0 0\n";
    }
    void sphere(const dvec3& c, double r) { out_ << "s " << xyz(c) << ' ' << r << '\n'; }
    void cone(const dvec3& base, double base_r, const dvec3& apex, double apex_r)
    {
        out_ << "c\n" << xyz(base) << ' ' << base_r << '\n' << xyz(apex) << ' ' << apex_r << '\n';
    }
    // NFF has no cylinder of its own: a cone whose two radii are equal, as SPD writes them.
    void cylinder(const dvec3& a, const dvec3& b, double r) { cone(a, r, b, r); }
    void polygon(const std::vector<dvec3>& vertices)
    {
        out_ << "p " << vertices.size() << '\n';
        for (const dvec3& v : vertices)
            out_ << xyz(v) << '\n';
    }

    // A square floor at height y, half as wide as `half`, facing up (counterclockwise from above).
    void floor(double y, double half)
    {
        polygon({{-half, y, -half}, {-half, y, half}, {half, y, half}, {half, y, -half}});
    }

private:
    struct Xyz {
        dvec3 v;
    };
    static Xyz xyz(const dvec3& v) { return {v}; }
    friend std::ostream& operator<<(std::ostream& o, const Xyz& p)
    {
        // A tiny negative zero would print as "-0": clean, and the same on every machine.
        const auto clean = [](double x) { return x == 0.0 ? 0.0 : x; };
        return o << clean(p.v.x) << ' ' << clean(p.v.y) << ' ' << clean(p.v.z);
    }

    std::ostream& out_;
};

// Two unit vectors perpendicular to unit `w` and to each other (Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited"): no branch on which axis w is nearest.
void basis(const dvec3& w, dvec3& u, dvec3& v)
{
    const double sign = std::copysign(1.0, w.z);
    const double a = -1.0 / (sign + w.z);
    const double b = w.x * w.y * a;
    u = dvec3(1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x);
    v = dvec3(b, sign + w.y * w.y * a, -w.y);
}

// A direction `elevation` degrees above the plane perpendicular to `axis`, at `azimuth` degrees
// around it.
dvec3 around(const dvec3& axis, double azimuth, double elevation)
{
    dvec3 u, v;
    basis(axis, u, v);
    const double e = radians(elevation), a = radians(azimuth);
    return std::cos(e) * (std::cos(a) * u + std::sin(a) * v) + std::sin(e) * axis;
}

// --- Sphereflake ---

// Where a sphere's nine children sit: six around its equator (perpendicular to the direction it
// grew in), three higher up between them. Apart by at least 56 degrees seen from the parent's
// centre, while a child a third the parent's size spans 29: the children never touch.
constexpr int flake_ring_count = 6;
constexpr double flake_crown_elevation = 50.0;  // degrees above the equator
constexpr double flake_child_scale = 1.0 / 3.0;

void flake(NffWriter& w, const dvec3& center, double radius, const dvec3& axis, int depth)
{
    w.sphere(center, radius);
    if (depth == 0)
        return;
    const double child_radius = radius * flake_child_scale;
    const double reach = radius + child_radius;  // children rest on the parent's surface
    for (int k = 0; k < flake_ring_count; ++k) {
        const dvec3 d = around(axis, 360.0 / flake_ring_count * k, 0.0);
        flake(w, center + reach * d, child_radius, d, depth - 1);
    }
    for (int k = 0; k < 3; ++k) {
        const dvec3 d = around(axis, 30.0 + 120.0 * k, flake_crown_elevation);
        flake(w, center + reach * d, child_radius, d, depth - 1);
    }
}

// --- Pyramid ---

using Tetrahedron = std::array<dvec3, 4>;

void tetrahedron_faces(NffWriter& w, const Tetrahedron& t)
{
    // Each face is the three corners other than one; wound so its normal points away from that one.
    for (int skip = 0; skip < 4; ++skip) {
        std::vector<dvec3> face;
        for (int k = 0; k < 4; ++k)
            if (k != skip)
                face.push_back(t[k]);
        if (glm::dot(glm::cross(face[1] - face[0], face[2] - face[0]), t[skip] - face[0]) > 0.0)
            std::swap(face[1], face[2]);
        w.polygon(face);
    }
}

void pyramid(NffWriter& w, const Tetrahedron& t, int depth)
{
    if (depth == 0) {
        tetrahedron_faces(w, t);
        return;
    }
    // Each corner keeps a half-size copy: the corner and the midpoints of its three edges.
    for (int corner = 0; corner < 4; ++corner) {
        Tetrahedron half;
        for (int k = 0; k < 4; ++k)
            half[k] = 0.5 * (t[corner] + t[k]);
        pyramid(w, half, depth - 1);
    }
}

// --- Tree ---

constexpr int tree_branches = 3;
constexpr double tree_spread = 32.0;        // degrees between a branch and its parent
constexpr double tree_twist = 137.5;        // degrees each level turns: the golden angle, so no
                                            // two levels' branches line up
constexpr double tree_length_scale = 0.72;  // a branch against its parent
constexpr double tree_taper = 0.65;         // a branch's tip radius against its base radius

struct Leaf {
    dvec3 center;
    double radius;
};

// Writes the branch and those growing from it; keeps its leaves for later, since they take
// another material and NFF's material is whatever `f` came last.
void branch(NffWriter& w, const dvec3& base, const dvec3& direction, double length, double radius, double twist,
            int depth, std::vector<Leaf>& leaves)
{
    const dvec3 tip = base + length * direction;
    const double tip_radius = radius * tree_taper;
    w.cone(base, radius, tip, tip_radius);
    w.sphere(tip, tip_radius);  // the joint: closes the open cones that meet here
    if (depth == 0) {
        // A leaf about a third of the last branch's length, just past its tip.
        leaves.push_back({tip + 0.25 * length * direction, 0.35 * length});
        return;
    }
    for (int k = 0; k < tree_branches; ++k) {
        const dvec3 d = around(direction, twist + 360.0 / tree_branches * k, 90.0 - tree_spread);
        branch(w, tip, d, length * tree_length_scale, tip_radius, twist + tree_twist, depth - 1, leaves);
    }
}

// --- Mountain ---

// Why 0.5: each level of the midpoint displacement halves the random offsets, as the cells halve:
// a surface whose roughness looks alike at every scale (fractal dimension about 2.5; Fournier,
// Fussell and Carpenter 1982, "Computer Rendering of Stochastic Models").
constexpr double mountain_roughness = 0.5;
constexpr std::uint64_t mountain_seed = 1982;
constexpr double mountain_peak = 1.4;  // the centre's rise above the corners, before the offsets

// Heights on a (2^depth + 1)^2 grid over [-1, 1]^2 by the diamond-square midpoint displacement,
// from a seeded stream so the mountain is the same on every machine.
std::vector<double> mountain_heights(int depth)
{
    const int n = (1 << depth) + 1;
    std::vector<double> h(static_cast<size_t>(n) * n, 0.0);
    const auto at = [&](int i, int j) -> double& { return h[static_cast<size_t>(j) * n + i]; };
    Rng rng(mountain_seed, 0);
    const auto offset = [&](double amplitude) { return amplitude * (2.0 * rng.next_float() - 1.0); };
    at(n / 2, n / 2) = 0.0;
    double amplitude = 0.8;
    for (int step = n - 1; step > 1; step /= 2, amplitude *= mountain_roughness) {
        const int half = step / 2;
        // Diamond: each square's centre from its four corners.
        for (int j = half; j < n; j += step)
            for (int i = half; i < n; i += step)
                at(i, j) = 0.25 * (at(i - half, j - half) + at(i + half, j - half) + at(i - half, j + half) +
                                   at(i + half, j + half)) + offset(amplitude) + (step == n - 1 ? mountain_peak : 0.0);
        // Square: each edge's midpoint from its (three or four) neighbours.
        for (int j = 0; j < n; j += half)
            for (int i = (j / half) % 2 == 0 ? half : 0; i < n; i += step) {
                double sum = 0.0;
                int count = 0;
                for (const auto& [di, dj] : {std::pair{-half, 0}, {half, 0}, {0, -half}, {0, half}})
                    if (i + di >= 0 && i + di < n && j + dj >= 0 && j + dj < n) {
                        sum += at(i + di, j + dj);
                        ++count;
                    }
                at(i, j) = sum / count + offset(amplitude);
            }
    }
    return h;
}

// --- Sticks ---

constexpr std::uint64_t sticks_seed = 1987;
constexpr double sticks_length = 0.9;  // against a pile 2 wide: each stick spans many grid cells
constexpr double sticks_width = 0.012;

// --- Gears ---

// SPD's gears have 36 teeth, a multiple of 4: a tooth then points along each axis of the grid the
// gears stand in, so turning every other gear half a tooth puts a gap opposite each tooth of its
// neighbours, along rows and columns alike.
constexpr int gear_teeth = 36;
constexpr double gear_root_ratio = 0.88;  // the gaps' floor against the teeth's tips
constexpr double gear_tip_half = 0.12;    // half a tooth's flat tip, in tooth pitches
constexpr double gear_root_half = 0.22;   // half a gap's flat floor, in tooth pitches
// Neighbours' centres this many tip radii apart: each tip stops 0.01 short of the other's gap
// floor, and with the tips narrower than the gaps no corner comes nearer than 0.01 to a neighbour's
// outline: no two gears touch or share a surface (SPD 2.3 moved its gears apart for that reason).
constexpr double gear_spacing = 1.0 + gear_root_ratio + 0.01;
constexpr double gear_thickness = 0.3;  // against the tip radius
constexpr double gear_rise = 1.1;       // from one layer of gears to the next, against the tip radius

// A gear's outline in the plane y = centre.y, its corners by increasing angle around y: so it faces
// down (the NFF front is the side that sees it counterclockwise). Each tooth adds two corners at its
// tip, then two at the floor of the gap after it: 4 x 36 corners, concave between the teeth.
std::vector<dvec3> gear_outline(const dvec3& centre, double radius, double turn)
{
    const double pitch = 2.0 * pi / gear_teeth;
    const double root = gear_root_ratio * radius;
    const std::array<std::pair<double, double>, 4> corners = {{{-gear_tip_half, radius},
                                                               {gear_tip_half, radius},
                                                               {0.5 - gear_root_half, root},
                                                               {0.5 + gear_root_half, root}}};
    std::vector<dvec3> outline;
    for (int k = 0; k < gear_teeth; ++k)
        for (const auto& [offset, r] : corners) {
            const double a = turn + pitch * (k + offset);
            outline.push_back(centre + dvec3(r * std::cos(a), 0.0, r * std::sin(a)));
        }
    return outline;
}

// One gear lying flat, its bottom face at `base`: two faces of 144 corners and a quad for each edge
// of the outline between them, each facing out of the gear.
void gear(NffWriter& w, const dvec3& base, double radius, double turn)
{
    const dvec3 up(0.0, gear_thickness * radius, 0.0);
    const std::vector<dvec3> bottom = gear_outline(base, radius, turn);
    std::vector<dvec3> top(bottom.rbegin(), bottom.rend());  // reversed: faces up
    for (dvec3& p : top)
        p += up;
    w.polygon(top);
    w.polygon(bottom);
    for (std::size_t k = 0; k < bottom.size(); ++k) {
        const dvec3& a = bottom[k];
        const dvec3& b = bottom[(k + 1) % bottom.size()];
        w.polygon({a + up, b + up, b, a});
    }
}

// --- Rings ---

// Six pentagonal rings around one centre, each square to one of the six axes through an
// icosahedron's opposite corners: SPD's rings join the midpoints of a dodecahedron's edges, the
// same symmetry, so from any side the rings cross one another and hide what lies behind.
std::array<dvec3, 6> ring_axes()
{
    const double g = 0.5 * (1.0 + std::sqrt(5.0));  // the golden ratio: an icosahedron's corners
    const std::array<dvec3, 6> corners = {
        dvec3(0.0, 1.0, g), dvec3(0.0, 1.0, -g), dvec3(1.0, g, 0.0),
        dvec3(1.0, -g, 0.0), dvec3(g, 0.0, 1.0), dvec3(-g, 0.0, 1.0)};
    std::array<dvec3, 6> axes;
    for (std::size_t k = 0; k < axes.size(); ++k)
        axes[k] = glm::normalize(corners[k]);
    return axes;
}

// Against the distance between neighbouring objects: a ring's corners stand 0.44 from its centre
// and its tube is 0.03 thick, so an object fits in a ball of radius 0.47 and neighbours never touch.
constexpr double ring_corner = 0.44;
constexpr double ring_tube = 0.03;

// A ring: a sphere at each of its five corners, a cylinder along each edge between them.
void pentagon_ring(NffWriter& w, const dvec3& centre, const dvec3& axis, double corner, double tube)
{
    for (int k = 0; k < 5; ++k) {
        const dvec3 a = centre + corner * around(axis, 72.0 * k, 0.0);
        const dvec3 b = centre + corner * around(axis, 72.0 * (k + 1), 0.0);
        w.sphere(a, tube);
        w.cylinder(a, b, tube);
    }
}

// The objects' centres, a square pyramid `levels` high stacked like cannonballs: n x n at the
// bottom, each level above one fewer a side, resting in the hollows of the one below.
std::vector<dvec3> ring_pyramid(int levels, double spacing)
{
    std::vector<dvec3> centres;
    for (int level = 0; level < levels; ++level) {
        const int side = levels - level;
        const double y = 0.5 * spacing + level * spacing / std::sqrt(2.0);
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i)
                centres.emplace_back((i - 0.5 * (side - 1)) * spacing, y, (j - 0.5 * (side - 1)) * spacing);
    }
    return centres;
}

// --- Lattice ---

// Against the lattice's spacing: joints a fifth of it, rods 0.06, thin enough that the eye sees
// through the lattice to its far side, as in SPD's.
constexpr double lattice_joint = 0.2;
constexpr double lattice_rod = 0.06;

// The rods along one axis: from each joint to the next, starting and stopping just inside the two
// joints (where the rod's rim is still inside the ball), so no rod shows a bare end and none
// reaches the far side of a joint.
void lattice_rods(NffWriter& w, int cells, double spacing, const dvec3& origin, int axis)
{
    const double joint = lattice_joint * spacing, rod = lattice_rod * spacing;
    const double inset = 0.95 * std::sqrt(joint * joint - rod * rod);
    dvec3 along(0.0);
    along[axis] = 1.0;
    for (int i = 0; i <= cells; ++i)
        for (int j = 0; j <= cells; ++j)
            for (int k = 0; k <= cells; ++k) {
                const dvec3 index(i, j, k);
                if (index[axis] == cells)
                    continue;
                const dvec3 p = origin + spacing * index;
                w.cylinder(p + inset * along, p + (spacing - inset) * along, rod);
            }
}

// The lights and view every generated scene shares, framing an object `size` across whose base
// stands at the origin.
void stage(NffWriter& w, double size, double height)
{
    const dvec3 target(0.0, 0.5 * height, 0.0);
    w.view(target + size * dvec3(1.6, 1.0, 2.6), target, 40.0, 512);
    w.background(dvec3(0.078, 0.361, 0.753));  // the sky blue of SPD's sphereflake
    w.light(size * dvec3(-3.0, 4.0, 2.0));
    w.light(size * dvec3(3.0, 5.0, 3.0));
    w.light(size * dvec3(1.0, 3.0, -4.0));
}

}  // namespace

void write_sphereflake(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("sphereflake, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    stage(w, 2.6, 2.0);
    w.material(dvec3(0.8, 0.6, 0.4), 0.7, 0.3, 30.0);  // a brass floor that mirrors a little
    w.floor(-1.0, 8.0);
    w.material(dvec3(1.0, 0.9, 0.7), 0.5, 0.5, 100.0);
    flake(w, dvec3(0.0), 1.0, dvec3(0.0, 1.0, 0.0), depth);
}

void write_pyramid(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("tetrahedral pyramid, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    // A regular tetrahedron of edge 2 standing on the floor.
    const double edge = 2.0;
    const double height = edge * std::sqrt(2.0 / 3.0);
    const double circumradius = edge / std::sqrt(3.0);  // of the base triangle
    Tetrahedron t;
    for (int k = 0; k < 3; ++k) {
        const double a = radians(90.0 + 120.0 * k);
        t[k] = dvec3(circumradius * std::cos(a), 0.0, circumradius * std::sin(a));
    }
    t[3] = dvec3(0.0, height, 0.0);
    stage(w, 1.4, height);
    w.material(dvec3(0.6, 0.6, 0.6), 0.9, 0.1, 10.0);
    w.floor(0.0, 6.0);
    w.material(dvec3(1.0, 0.2, 0.2), 0.8, 0.2, 20.0);
    pyramid(w, t, depth);
}

void write_tree(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("tree, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    const double trunk = 1.2;
    stage(w, 3.0, 2.8);
    w.material(dvec3(0.4, 0.7, 0.3), 0.9, 0.0, 0.0);
    w.floor(0.0, 8.0);
    w.material(dvec3(0.45, 0.3, 0.15), 0.9, 0.1, 5.0);
    std::vector<Leaf> leaves;
    branch(w, dvec3(0.0), dvec3(0.0, 1.0, 0.0), trunk, 0.12, 0.0, depth, leaves);
    w.material(dvec3(0.2, 0.6, 0.15), 0.8, 0.2, 20.0);
    for (const Leaf& leaf : leaves)
        w.sphere(leaf.center, leaf.radius);
}

void write_mountain(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("fractal mountain, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    const int n = (1 << depth) + 1;
    const std::vector<double> h = mountain_heights(depth);
    const double size = 4.0;  // the terrain spans [-2, 2] in x and z
    const auto vertex = [&](int i, int j) {
        return dvec3(size * (static_cast<double>(i) / (n - 1) - 0.5), h[static_cast<size_t>(j) * n + i],
                     size * (static_cast<double>(j) / (n - 1) - 0.5));
    };
    stage(w, 1.7, 1.0);
    w.material(dvec3(0.55, 0.5, 0.42), 0.9, 0.05, 4.0);
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            // Two triangles per square, counterclockwise seen from above.
            w.polygon({vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1)});
            w.polygon({vertex(i, j), vertex(i + 1, j + 1), vertex(i + 1, j)});
        }
    // Four balls resting above the slopes, as SPD's mount has.
    w.material(dvec3(0.9, 0.3, 0.25), 0.6, 0.4, 60.0);
    const dvec3 balls[4] = {{-1.0, 1.5, 0.8}, {0.9, 1.4, 0.9}, {0.4, 1.9, -0.7}, {-0.6, 2.0, -1.0}};
    for (const dvec3& c : balls)
        w.sphere(c, 0.28);
}

void write_sticks(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("pick-up sticks, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    stage(w, 1.6, 1.0);
    w.material(dvec3(0.5, 0.5, 0.55), 0.9, 0.0, 0.0);
    w.floor(0.0, 4.0);
    // Seeded, so the pile is the same everywhere: each stick a long thin triangle from one end to
    // the other, lying at any angle within a box 2 wide and 1 high above the floor.
    Rng rng(sticks_seed, 0);
    const auto u = [&] { return static_cast<double>(rng.next_float()); };
    const dvec3 colours[3] = {{0.85, 0.2, 0.15}, {0.95, 0.75, 0.2}, {0.2, 0.45, 0.85}};
    const int count = 250 << depth;
    for (int c = 0; c < 3; ++c) {
        w.material(colours[c], 0.8, 0.2, 20.0);
        for (int k = c; k < count; k += 3) {
            // One draw a statement: the order in which a call's arguments are computed is the
            // compiler's (GCC takes the last first, clang the first), and the scene must not depend
            // on what compiled it. These are GCC's order, which drew the kit's figures.
            const double z = 2.0 * u() - 1.0;
            const double y = 0.05 + 0.95 * u();
            const double x = 2.0 * u() - 1.0;
            const double tilt = 60.0 * (2.0 * u() - 1.0);
            const double turn = 360.0 * u();
            const dvec3 centre(x, y, z);
            const dvec3 along = around(dvec3(0.0, 1.0, 0.0), turn, tilt);
            dvec3 side, unused;
            basis(along, side, unused);
            const dvec3 a = centre - 0.5 * sticks_length * along, b = centre + 0.5 * sticks_length * along;
            w.polygon({a, b, b + sticks_width * side});
        }
    }
}

void write_stadium(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("teapot in a stadium, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    // The view: close to the small dense mesh, the stadium's stands behind it.
    w.view(dvec3(0.0, 2.3, 4.6), dvec3(0.0, 1.0, 0.0), 50.0, 512);
    w.background(dvec3(0.078, 0.361, 0.753));
    w.light(dvec3(12.0, 30.0, 20.0));
    w.light(dvec3(-25.0, 18.0, 10.0));
    // The stadium: a field 130 across, and stands rising from radius 40 to 60, 64 segments round
    // and 6 tiers up: big triangles, few of them.
    w.material(dvec3(0.3, 0.55, 0.25), 0.9, 0.0, 0.0);
    w.floor(0.0, 65.0);
    w.material(dvec3(0.6, 0.6, 0.65), 0.9, 0.05, 5.0);
    constexpr int segments = 64, tiers = 6;
    const auto stand = [&](int s, int t) {
        const double a = 2.0 * pi * s / segments, radius = 40.0 + 20.0 * t / tiers;
        return dvec3(radius * std::cos(a), 15.0 * t / tiers, radius * std::sin(a));
    };
    for (int s = 0; s < segments; ++s)
        for (int t = 0; t < tiers; ++t) {
            // Facing the field (inward and up): counterclockwise seen from the centre.
            w.polygon({stand(s, t), stand(s + 1, t + 1), stand(s + 1, t)});
            w.polygon({stand(s, t), stand(s, t + 1), stand(s + 1, t + 1)});
        }
    // The "teapot": a small dense mesh at the field's centre, 20 x 4^depth triangles.
    w.material(dvec3(0.9, 0.85, 0.8), 0.7, 0.3, 50.0);
    const IndexedMesh pot = icosphere(point3(0.0f, 1.0f, 0.0f), 1.0f, depth);
    for (int f = 0; f < static_cast<int>(pot.faces.size()); ++f) {
        const std::array<point3, 3> c = pot.corners(f);
        w.polygon({dvec3(c[0]), dvec3(c[1]), dvec3(c[2])});
    }
}

void write_gears(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("gears, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    // (depth + 1)^3 gears, as SPD's size factor depth + 1 has: layers of (depth + 1)^2 meshing
    // gears, one above another, the whole 2 wide whatever the depth.
    const int n = depth + 1;
    const double width = 2.0;
    const double radius = width / ((n - 1) * gear_spacing + 2.0);
    const double lift = 0.5 * radius;  // the lowest layer's gap to the floor
    stage(w, 1.5, lift + ((n - 1) * gear_rise + gear_thickness) * radius);
    w.material(dvec3(0.9, 0.85, 0.75), 0.7, 0.3, 30.0);  // a floor that mirrors a little, as SPD's
    w.floor(0.0, 5.0);
    const dvec3 colours[5] = {{0.85, 0.55, 0.2}, {0.7, 0.7, 0.75}, {0.8, 0.3, 0.2}, {0.3, 0.5, 0.8}, {0.85, 0.75, 0.3}};
    for (int layer = 0; layer < n; ++layer)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                // Neighbours differ in colour (i + 2j + 3 layer changes by 1, 2 or 3 mod 5), and
                // every other gear turns half a tooth so that the teeth of neighbours interleave.
                w.material(colours[(i + 2 * j + 3 * layer) % 5], 0.7, 0.3, 40.0);
                const dvec3 base(-0.5 * width + radius + i * gear_spacing * radius,
                                 lift + layer * gear_rise * radius,
                                 -0.5 * width + radius + j * gear_spacing * radius);
                gear(w, base, radius, (i + j + layer) % 2 == 0 ? 0.0 : pi / gear_teeth);
            }
}

void write_rings(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("rings, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    // A pyramid depth + 1 levels high, as SPD's size factor depth + 1 has, its base 2 wide whatever
    // the depth.
    const int levels = depth + 1;
    const double spacing = 2.0 / levels;
    const std::vector<dvec3> centres = ring_pyramid(levels, spacing);
    stage(w, 1.4, centres.back().y + 0.5 * spacing);
    w.material(dvec3(0.9, 0.9, 0.9), 0.9, 0.1, 10.0);
    w.floor(0.0, 5.0);
    // Each of the six rings of every object takes the same colour (SPD's six colours too), so one
    // material line serves a sixth of the scene.
    const dvec3 colours[6] = {{0.9, 0.2, 0.15}, {0.2, 0.75, 0.25}, {0.2, 0.35, 0.9},
                              {0.2, 0.8, 0.8},  {0.85, 0.25, 0.8}, {0.95, 0.85, 0.2}};
    const std::array<dvec3, 6> axes = ring_axes();
    for (std::size_t r = 0; r < axes.size(); ++r) {
        w.material(colours[r], 0.5, 0.5, 40.0);
        for (const dvec3& c : centres)
            pentagon_ring(w, c, axes[r], ring_corner * spacing, ring_tube * spacing);
    }
}

void write_lattice(std::ostream& out, int depth)
{
    NffWriter w(out);
    w.comment("lattice, depth " + std::to_string(depth) + ", by nff_generate (the kit's own)");
    // depth cells a side, as SPD's size factor depth has: a cube 2 wide whatever the depth (one
    // joint alone at depth 0).
    const int cells = depth;
    const double spacing = 2.0 / std::max(cells, 1);
    const double lift = 0.3;  // the lowest joints' height above the floor
    const dvec3 origin(-1.0, lift, -1.0);
    stage(w, 2.0, lift + 2.0);
    w.material(dvec3(0.6, 0.6, 0.6), 0.9, 0.0, 0.0);
    w.floor(0.0, 6.0);
    // Shiny joints, matte rods coloured by their axis, as SPD's lattice has them.
    w.material(dvec3(0.9, 0.9, 0.9), 0.5, 0.5, 40.0);
    for (int i = 0; i <= cells; ++i)
        for (int j = 0; j <= cells; ++j)
            for (int k = 0; k <= cells; ++k)
                w.sphere(origin + spacing * dvec3(i, j, k), lattice_joint * spacing);
    const dvec3 colours[3] = {{0.85, 0.15, 0.1}, {0.15, 0.75, 0.2}, {0.15, 0.3, 0.85}};
    for (int axis = 0; axis < 3; ++axis) {
        w.material(colours[axis], 0.9, 0.0, 0.0);
        lattice_rods(w, cells, spacing, origin, axis);
    }
}

const std::vector<NffGenerator>& nff_generators()
{
    // Depth limits: 597871 spheres, 262144 triangles, 88573 cones, 524288 triangles; gears 572000
    // triangles in 1000 gears, rings 165750 spheres and as many cylinders, lattice 132651 spheres and
    // 390150 cylinders; each file tens of megabytes (gears 27, rings 19, lattice 25).
    static const std::vector<NffGenerator> generators = {
        {"sphereflake", "a sphere with nine smaller spheres on it, recursively (SPD's balls)", 3, 6, write_sphereflake},
        {"pyramid", "a tetrahedron of four half-size tetrahedra, recursively (SPD's tetra)", 4, 8, write_pyramid},
        {"tree", "a trunk branching into three, recursively: cones, joints and leaves", 5, 10, write_tree},
        {"mountain", "a fractal terrain of 2 x 4^depth triangles with four balls (SPD's mount)", 6, 9, write_mountain},
        {"sticks", "250 x 2^depth long thin triangles in a pile, each across many grid cells", 4, 12, write_sticks},
        {"stadium", "a small dense mesh (20 x 4^depth triangles) in a huge sparse stadium: the teapot in a stadium", 5, 8, write_stadium},
        {"gears", "(depth+1)^3 meshing gears, faces of 144 corners, concave (SPD's gears)", 3, 9, write_gears},
        {"rings", "a pyramid of balls of six pentagonal rings: spheres and cylinders (SPD's rings)", 6, 24, write_rings},
        {"lattice", "a cube of depth^3 cells: joints (spheres) and rods (cylinders) (SPD's lattice)", 12, 50, write_lattice},
    };
    return generators;
}

}  // namespace rt
