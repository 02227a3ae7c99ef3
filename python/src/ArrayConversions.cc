/// @file ArrayConversions.cc
/// numpy <-> C++ conversions of the Python module.

#include "ArrayConversions.hh"

#include <HexEx/Core/Error.hh>

#include <nanobind/stl/string.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace HexExPython {

static_assert(sizeof(HexEx::Vec3d) == 3 * sizeof(double), "Vec3d must be three packed doubles");
static_assert(sizeof(std::array<int, 8>) == 8 * sizeof(std::int32_t), "hexes must be packed int32");

namespace {

/// A shape as text, e.g. "(5, 3)".
std::string shapeText(const std::vector<std::size_t>& shape) {
    std::string s = "(";
    for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + (shape.size() == 1 ? ",)" : ")");
}

/// A new C-contiguous numpy array of @p n elements of T with the given shape; @p fill
/// writes the elements through the raw pointer.
template <class T, class Fill>
nb::object newArray(std::initializer_list<std::size_t> shape, Fill&& fill) {
    std::size_t n = 1;
    for (std::size_t e : shape) n *= e;
    std::unique_ptr<T[]> data(new T[n > 0 ? n : 1]);
    fill(data.get());
    T* raw = data.get();
    nb::capsule owner(raw, [](void* p) noexcept { delete[] static_cast<T*>(p); });
    data.release();
    return nb::cast(nb::ndarray<nb::numpy, T>(raw, shape, owner));
}

} // namespace

void requireShape(const char* name, const std::vector<std::size_t>& shape, std::initializer_list<long> expected) {
    bool ok = shape.size() == expected.size();
    std::size_t i = 0;
    for (long e : expected) {
        if (ok && e >= 0 && shape[i] != static_cast<std::size_t>(e)) ok = false;
        ++i;
    }
    if (ok) return;
    std::string want = "(";
    i = 0;
    for (long e : expected) want += (i++ ? ", " : "") + (e < 0 ? std::string("n") : std::to_string(e));
    throw std::invalid_argument(std::string(name) + " must have shape " + want + "), got " + shapeText(shape));
}

TetIndices tetIndices(const nb::handle& tets) {
    TetIndices r;
    Int32Array a32;
    Int64Array a64;
    if (nb::try_cast(tets, a32, false)) {
        requireArrayShape("tets", a32, {-1, 4});
        r.i32 = a32.data();
        r.n_tets = a32.shape(0);
    } else if (nb::try_cast(tets, a64, false)) {
        requireArrayShape("tets", a64, {-1, 4});
        r.i64 = a64.data();
        r.n_tets = a64.shape(0);
    } else {
        throw std::invalid_argument("tets must be a C-contiguous int32 or int64 array of shape (m, 4)");
    }
    return r;
}

HexEx::ParametrizedTetMesh toTetMesh(const DoubleArray& points, const TetIndices& tets, const DoubleArray& params) {
    requireArrayShape("points", points, {-1, 3});
    requireArrayShape("params", params, {static_cast<long>(tets.n_tets), 4, 3});
    auto finish = [](HexEx::ParametrizedTetMesh pm) {
        const std::string problem = pm.mesh.check_manifold();
        if (!problem.empty()) throw HexEx::InputError(problem);
        return pm;
    };
    if (tets.i32) {
        const TetArraysRef<std::int32_t> ref{points.data(), points.shape(0), tets.i32, tets.n_tets, params.data()};
        return finish(HexEx::toParametrizedTetMesh(ref));
    }
    const TetArraysRef<std::int64_t> ref{points.data(), points.shape(0), tets.i64, tets.n_tets, params.data()};
    return finish(HexEx::toParametrizedTetMesh(ref));
}

nb::tuple mapToArrays(const HexEx::ParametrizedTetMesh& pm) {
    const HexEx::TetMesh& m = pm.mesh;
    const std::size_t nv = m.n_vertices(), nt = m.n_cells();
    nb::object points = newArray<double>({nv, 3}, [&](double* d) {
        for (std::size_t v = 0; v < nv; ++v) {
            const HexEx::Vec3d& p = m.position(HexEx::VertexHandle(static_cast<int>(v)));
            for (int k = 0; k < 3; ++k) d[3 * v + static_cast<std::size_t>(k)] = p[k];
        }
    });
    nb::object tets = newArray<std::int32_t>({nt, 4}, [&](std::int32_t* d) {
        for (std::size_t c = 0; c < nt; ++c)
            for (int i = 0; i < 4; ++i)
                d[4 * c + static_cast<std::size_t>(i)] = m.cell_vertex(HexEx::CellHandle(static_cast<int>(c)), i).idx();
    });
    nb::object params = newArray<double>({nt, 4, 3}, [&](double* d) {
        for (std::size_t c = 0; c < nt; ++c)
            for (std::size_t i = 0; i < 4; ++i)
                for (int k = 0; k < 3; ++k) d[12 * c + 3 * i + static_cast<std::size_t>(k)] = pm.params[c][i][k];
    });
    return nb::make_tuple(points, tets, params);
}

nb::tuple hexMeshToArrays(HexEx::HexMesh&& mesh) {
    nb::list polyhedra;
    for (const HexEx::Polyhedron& p : mesh.polyhedra) {
        nb::list faces;
        for (const auto& f : p.faces) {
            nb::list face;
            for (int v : f) face.append(v);
            faces.append(face);
        }
        polyhedra.append(faces);
    }
    auto* owned = new HexEx::HexMesh(std::move(mesh));
    owned->polyhedra.clear();
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<HexEx::HexMesh*>(p); });
    // Empty vectors may have no buffer; numpy still wants a valid pointer.
    static double noDoubles[3] = {0, 0, 0};
    static std::int32_t noInts[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    double* pts = owned->vertices.empty() ? noDoubles : owned->vertices.data()->data();
    std::int32_t* hexes = owned->hexes.empty() ? noInts : owned->hexes.data()->data();
    nb::object points = nb::cast(NumpyDoubles(pts, {owned->vertices.size(), 3}, owner));
    nb::object hexArray = nb::cast(NumpyInts(hexes, {owned->hexes.size(), 8}, owner));
    return nb::make_tuple(points, hexArray, polyhedra);
}

HexEx::HexMesh hexMeshFromArrays(const DoubleArray& points, const Int32Array& hexes, const nb::handle& polyhedra) {
    requireArrayShape("points", points, {-1, 3});
    requireArrayShape("hexes", hexes, {-1, 8});
    HexEx::HexMesh hm;
    const std::size_t nv = points.shape(0), nh = hexes.shape(0);
    hm.vertices.resize(nv);
    for (std::size_t v = 0; v < nv; ++v)
        hm.vertices[v] = HexEx::Vec3d(points.data()[3 * v], points.data()[3 * v + 1], points.data()[3 * v + 2]);
    hm.hexes.resize(nh);
    for (std::size_t h = 0; h < nh; ++h)
        for (std::size_t i = 0; i < 8; ++i) hm.hexes[h][i] = hexes.data()[8 * h + i];
    for (nb::handle cell : polyhedra) {
        HexEx::Polyhedron p;
        for (nb::handle face : cell) {
            std::vector<int> loop;
            for (nb::handle v : face) loop.push_back(nb::cast<int>(v));
            p.faces.push_back(std::move(loop));
        }
        hm.polyhedra.push_back(std::move(p));
    }
    return hm;
}

bool surfaceFromArrays(const std::optional<DoubleArray>& points, const std::optional<Int32Array>& triangles,
                       HexEx::TriangleSurface& surface) {
    if (!points.has_value() || !triangles.has_value()) return false;
    requireArrayShape("surface points", *points, {-1, 3});
    requireArrayShape("surface triangles", *triangles, {-1, 3});
    const std::size_t np = points->shape(0), nt = triangles->shape(0);
    const double* p = points->data();
    for (std::size_t i = 0; i < np; ++i) surface.points.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    const std::int32_t* t = triangles->data();
    for (std::size_t i = 0; i < nt; ++i) {
        for (int k = 0; k < 3; ++k)
            if (t[3 * i + k] < 0 || static_cast<std::size_t>(t[3 * i + k]) >= np)
                throw std::invalid_argument("surface triangle " + std::to_string(i) + " references point " +
                                            std::to_string(t[3 * i + k]) + " of " + std::to_string(np));
        surface.triangles.push_back({{t[3 * i], t[3 * i + 1], t[3 * i + 2]}});
    }
    return true;
}

} // namespace HexExPython
