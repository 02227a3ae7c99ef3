/// @file traits.cc
/// Extracting a hex mesh straight from an application's own volume-mesh kernel: the
/// program defines a small OpenVolumeMesh-like kernel (typed handles, a cell property
/// holding the four corner parameters), writes HexEx's input and output traits for it
/// (about 50 lines) and calls the templated HexEx::extractHexMesh(). It then does the same
/// with plain arrays. Input: the unit cube as six tets, parameters 2 * position, so the
/// expected result is a 2x2x2 grid: 8 hexes, 27 vertices. Exits non-zero on any mismatch.

#include <HexEx/HexExTraits.hh>

#include <array>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

// ---------------------------------------------------------------------------------------
// The application's kernel (stands in for OpenVolumeMesh, CGAL, an in-house mesh, ...).
// ---------------------------------------------------------------------------------------
namespace app {

struct Point { double x, y, z; };
struct VertexHandle { int idx; };
struct CellHandle { int idx; };

/// Tet mesh; the integer-grid map is a cell property: parameter of each corner.
class TetMesh {
public:
    VertexHandle add_vertex(const Point& p) { points_.push_back(p); return {int(points_.size()) - 1}; }
    CellHandle add_cell(const std::array<VertexHandle, 4>& c) {
        cells_.push_back(c);
        params_.push_back({});
        return {int(cells_.size()) - 1};
    }
    int n_vertices() const { return int(points_.size()); }
    int n_cells() const { return int(cells_.size()); }
    const Point& vertex(VertexHandle v) const { return points_[v.idx]; }
    const std::array<VertexHandle, 4>& cell(CellHandle c) const { return cells_[c.idx]; }
    std::array<Point, 4>& param(CellHandle c) { return params_[c.idx]; }  // the "cell property"
    const std::array<Point, 4>& param(CellHandle c) const { return params_[c.idx]; }

private:
    std::vector<Point> points_;
    std::vector<std::array<VertexHandle, 4>> cells_;
    std::vector<std::array<Point, 4>> params_;
};

/// Hex mesh with its own handles.
struct HexMesh {
    std::vector<Point> points;
    std::vector<std::array<VertexHandle, 8>> hexes;
    std::vector<std::vector<std::vector<VertexHandle>>> polyhedra;
};

} // namespace app

// ---------------------------------------------------------------------------------------
// The traits: everything HexEx needs to read app::TetMesh and write app::HexMesh.
// ---------------------------------------------------------------------------------------
namespace HexEx {

template <>
struct TetMeshTraits<app::TetMesh> {
    static std::size_t n_vertices(const app::TetMesh& m) { return std::size_t(m.n_vertices()); }
    static Vec3d position(const app::TetMesh& m, std::size_t v) {
        const app::Point& p = m.vertex({int(v)});
        return Vec3d(p.x, p.y, p.z);
    }
    static std::size_t n_tets(const app::TetMesh& m) { return std::size_t(m.n_cells()); }
    static std::array<std::size_t, 4> tet_vertices(const app::TetMesh& m, std::size_t t) {
        const auto& c = m.cell({int(t)});
        return {std::size_t(c[0].idx), std::size_t(c[1].idx), std::size_t(c[2].idx), std::size_t(c[3].idx)};
    }
    static Vec3d corner_param(const app::TetMesh& m, std::size_t t, int corner) {
        const app::Point& u = m.param({int(t)})[std::size_t(corner)];
        return Vec3d(u.x, u.y, u.z);
    }
};

template <>
struct HexMeshOutputTraits<app::HexMesh> {
    static void clear(app::HexMesh& m) { m = app::HexMesh(); }
    static std::size_t add_vertex(app::HexMesh& m, const Vec3d& p) {
        m.points.push_back({p[0], p[1], p[2]});
        return m.points.size() - 1;
    }
    static void add_hex(app::HexMesh& m, const std::array<std::size_t, 8>& v) {
        std::array<app::VertexHandle, 8> h;
        for (std::size_t i = 0; i < 8; ++i) h[i] = {int(v[i])};
        m.hexes.push_back(h);
    }
    static void add_polyhedron(app::HexMesh& m, const std::vector<std::vector<std::size_t>>& faces) {
        std::vector<std::vector<app::VertexHandle>> cell;
        for (const auto& f : faces) {
            cell.emplace_back();
            for (std::size_t v : f) cell.back().push_back({int(v)});
        }
        m.polyhedra.push_back(cell);
    }
};

} // namespace HexEx

namespace {

/// Unit cube, vertex i at (i&1, (i>>1)&1, (i>>2)&1), six positive tets around the
/// diagonal 0-7, each corner with parameter 2 * position.
app::TetMesh makeCube() {
    app::TetMesh m;
    for (int i = 0; i < 8; ++i) m.add_vertex({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    const int tets[6][4] = {{0, 1, 3, 7}, {0, 5, 1, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 6, 4, 7}};
    for (const auto& t : tets) {
        const app::CellHandle c = m.add_cell({app::VertexHandle{t[0]}, app::VertexHandle{t[1]},
                                              app::VertexHandle{t[2]}, app::VertexHandle{t[3]}});
        for (int i = 0; i < 4; ++i) {
            const app::Point& p = m.vertex({t[i]});
            m.param(c)[std::size_t(i)] = {2 * p.x, 2 * p.y, 2 * p.z};
        }
    }
    return m;
}

bool check(const char* what, bool ok) {
    std::cout << (ok ? "  ok      " : "  FAILED  ") << what << "\n";
    return ok;
}

} // namespace

int main() {
    bool ok = true;
    try {
        // 1. The application's own kernel in, the application's own hex mesh out.
        const app::TetMesh tets = makeCube();
        app::HexMesh hexes;
        const HexEx::ExtractionReport r = HexEx::extractHexMesh(tets, hexes);
        std::cout << "user kernel: " << hexes.hexes.size() << " hexes, " << hexes.points.size() << " vertices, "
                  << hexes.polyhedra.size() << " other cells\n";
        ok &= check("8 hexes", hexes.hexes.size() == 8 && r.output.hexes == 8);
        ok &= check("27 vertices", hexes.points.size() == 27 && r.output.vertices == 27);
        ok &= check("no other cells", hexes.polyhedra.empty());
        ok &= check("valid all-hex mesh", r.valid_all_hex);
        bool inRange = true;
        for (const auto& h : hexes.hexes)
            for (const auto& v : h) inRange = inRange && v.idx >= 0 && v.idx < int(hexes.points.size());
        ok &= check("hex vertex handles valid", inRange);

        // 2. Plain arrays in and out (HexEx::TetArraysView / HexEx::HexArrays).
        std::vector<HexEx::Vec3d> positions;
        std::vector<std::array<int, 4>> cells;
        std::vector<std::array<HexEx::Vec3d, 4>> params;
        for (int v = 0; v < tets.n_vertices(); ++v) {
            const app::Point& p = tets.vertex({v});
            positions.emplace_back(p.x, p.y, p.z);
        }
        for (int c = 0; c < tets.n_cells(); ++c) {
            const auto& cv = tets.cell({c});
            cells.push_back({cv[0].idx, cv[1].idx, cv[2].idx, cv[3].idx});
            std::array<HexEx::Vec3d, 4> u;
            for (std::size_t i = 0; i < 4; ++i) u[i] = 2.0 * positions[std::size_t(cv[i].idx)];
            params.push_back(u);
        }
        HexEx::HexArrays arrays;
        const HexEx::ExtractionReport ra = HexEx::extractHexMesh(HexEx::TetArraysView{&positions, &cells, &params}, arrays);
        std::cout << "plain arrays: " << arrays.hexes.size() << " hexes, " << arrays.positions.size() << " vertices\n";
        ok &= check("arrays: 8 hexes, 27 vertices, valid",
                    arrays.hexes.size() == 8 && arrays.positions.size() == 27 && ra.valid_all_hex);

        // 3. Bad input is reported, not crashed on.
        cells[3][1] = 99;
        try {
            HexEx::extractHexMesh(HexEx::TetArraysView{&positions, &cells, &params}, arrays);
            ok &= check("out-of-range index rejected", false);
        } catch (const HexEx::InputError& e) {
            std::cout << "expected error: " << e.what() << "\n";
            ok &= check("out-of-range index rejected", std::string(e.what()).find("tet 3") != std::string::npos);
        }
    } catch (const std::exception& e) {
        std::cout << "unexpected error: " << e.what() << "\n";
        ok = false;
    }
    std::cout << (ok ? "OK" : "FAILED") << "\n";
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
