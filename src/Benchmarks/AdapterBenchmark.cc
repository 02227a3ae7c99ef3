/// @file AdapterBenchmark.cc
/// Cost of the mesh-kernel adapters: time and peak memory of one extraction through the
/// traits (input view -> copy into the built-in kernel -> extraction -> output written
/// through the output traits) against the built-in kernel alone.
///
///   adapter_benchmark CASE PATH
///
/// CASE: cube40 (generateCube(80, 40): 3.07M tets, 64,000 hexes) or cylinder6
/// (generateCylinder(6, 64, 64, 1, 1): 36 tets, 1,572,864 hexes); cube8/cylinder6s are
/// small versions. PATH: builtin, arrays (TetArraysView -> HexArrays), lcc (CGAL
/// Linear_cell_complex both ways) or, when built with OpenVolumeMesh, ovm (tetrahedral
/// kernel with the halfface map -> hexahedral kernel). Run one measurement per process:
/// the peak resident set size (VmHWM) then belongs to it. Prints one line of
/// `key=value` pairs; building the input in the user's structure is not timed. view_s:
/// the adapter's scan of the input; copy_s: toParametrizedTetMesh() including the
/// adjacency (for builtin: TetMesh::build_adjacency() alone); extract_s: the extraction;
/// write_s: fromHexMesh() into the output structure; total_s: all of them.

#include <HexEx/Adapters/CgalLinearCellComplex.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexExTraits.hh>

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#ifdef HEXEX_BENCH_OVM
#include <HexEx/Adapters/OpenVolumeMesh.hh>
#include <OpenVolumeMesh/Mesh/HexahedralMesh.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralMesh.hh>
#endif

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

namespace {

/// Peak resident set size of this process in MB (VmHWM), or -1.
double peakMb() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return -1;
}

/// Seconds since @p t0.
double since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// LCC items whose darts carry the parameter of their vertex in their volume's chart.
struct ParamItems {
    template <class Refs>
    struct Dart_wrapper {
        typedef CGAL::Cell_attribute_with_point<Refs> Vertex_attribute;
        typedef std::tuple<Vertex_attribute> Attributes;
        typedef std::array<double, 3> Dart_info;
    };
};
using TetLcc = CGAL::Linear_cell_complex_for_combinatorial_map<3, 3, CGAL::Linear_cell_complex_traits<3>, ParamItems>;
using HexLcc = CGAL::Linear_cell_complex_for_combinatorial_map<3>;

/// Tets of @p pm as an LCC with shared vertex attributes and the map in the darts.
void buildLcc(const HexEx::ParametrizedTetMesh& pm, TetLcc& lcc) {
    HexEx::LccHexOutput<TetLcc> b(lcc);
    b.clear();
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) b.addVertex(pm.mesh.position(HexEx::VertexHandle(int(v))));
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(int(t)));
        const std::size_t a = cv[0].uidx(), bb = cv[1].uidx(), c = cv[2].uidx(), d = cv[3].uidx();
        const auto first = b.addVolume({{a, c, bb}, {a, bb, d}, {bb, c, d}, {c, a, d}});
        for (auto it = lcc.darts_of_cell<3>(first).begin(); it != lcc.darts_of_cell<3>(first).end(); ++it)
            for (std::size_t i = 0; i < 4; ++i) {
                const HexEx::Vec3d p = pm.mesh.position(cv[i]);
                if (lcc.point(it) == TetLcc::Point(p[0], p[1], p[2])) {
                    const HexEx::Vec3d u = pm.params[t][i];
                    lcc.info(it) = {u[0], u[1], u[2]};
                }
            }
    }
}

#ifdef HEXEX_BENCH_OVM
using OvmTets = OpenVolumeMesh::GeometricTetrahedralMeshV3d;
using OvmHexes = OpenVolumeMesh::GeometricHexahedralMeshV3d;
using OvmVec = OpenVolumeMesh::Geometry::Vec3d;

/// Tets of @p pm in OpenVolumeMesh with the halfface map (the files' convention).
void buildOvm(const HexEx::ParametrizedTetMesh& pm, OvmTets& m) {
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
        const HexEx::Vec3d p = pm.mesh.position(HexEx::VertexHandle(int(v)));
        m.add_vertex(OvmVec(p[0], p[1], p[2]));
    }
    auto prop = m.request_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    m.set_persistent(prop, true);  // outlives this handle, as after reading a file
    static const int kFaces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(int(t)));
        std::vector<OpenVolumeMesh::HalfFaceHandle> hfs;
        for (const auto& f : kFaces) {
            std::vector<OpenVolumeMesh::VertexHandle> vs = {OpenVolumeMesh::VertexHandle(cv[f[0]].idx()),
                                                            OpenVolumeMesh::VertexHandle(cv[f[1]].idx()),
                                                            OpenVolumeMesh::VertexHandle(cv[f[2]].idx())};
            OpenVolumeMesh::HalfFaceHandle hf = m.find_halfface(vs);
            if (!hf.is_valid()) hf = m.halfface_handle(m.add_face(vs), 0);
            const HexEx::Vec3d u = pm.params[t][std::size_t(f[3])];
            prop[hf] = OvmVec(u[0], u[1], u[2]);
            hfs.push_back(hf);
        }
        m.add_cell(hfs);
    }
}
#endif

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: adapter_benchmark cube40|cylinder6|cube8|cylinder6s builtin|arrays|lcc"
#ifdef HEXEX_BENCH_OVM
                     "|ovm"
#endif
                     "\n";
        return 2;
    }
    const std::string c = argv[1], path = argv[2];
    HexEx::ParametrizedTetMesh pm;
    if (c == "cube40") pm = HexEx::generateCube(80, 40);
    else if (c == "cube8") pm = HexEx::generateCube(16, 8);
    else if (c == "cylinder6") pm = HexEx::generateCylinder(6, 64, 64, 1, 1);
    else if (c == "cylinder6s") pm = HexEx::generateCylinder(6, 8, 8, 1, 1);
    else {
        std::cerr << "unknown case " << c << "\n";
        return 2;
    }
    double view = 0, copy = 0, extract = 0, write = 0, total = 0;
    std::size_t hexes = 0;
    if (path == "builtin") {
        // copy_s: the adjacency, which the traits path builds inside its copy.
        auto t0 = std::chrono::steady_clock::now();
        pm.mesh.build_adjacency();
        copy = since(t0);
        HexEx::HexMesh hm;
        auto t1 = std::chrono::steady_clock::now();
        HexEx::extractHexMesh(pm, hm);
        extract = since(t1);
        total = since(t0);
        hexes = hm.hexes.size();
    } else if (path == "arrays") {
        std::vector<HexEx::Vec3d> positions(pm.mesh.n_vertices());
        for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = pm.mesh.position(HexEx::VertexHandle(int(v)));
        std::vector<std::array<int, 4>> tets(pm.mesh.n_cells());
        for (std::size_t t = 0; t < tets.size(); ++t)
            for (int i = 0; i < 4; ++i) tets[t][std::size_t(i)] = pm.mesh.cell_vertex(HexEx::CellHandle(int(t)), i).idx();
        std::vector<std::array<HexEx::Vec3d, 4>> params = pm.params;
        pm = HexEx::ParametrizedTetMesh();
        const HexEx::TetArraysView in{&positions, &tets, &params};
        HexEx::HexArrays out;
        auto t0 = std::chrono::steady_clock::now();
        HexEx::ParametrizedTetMesh copyPm = HexEx::toParametrizedTetMesh(in);
        copy = since(t0);
        auto t1 = std::chrono::steady_clock::now();
        HexEx::HexMesh hm;
        HexEx::extractHexMesh(copyPm, hm);
        extract = since(t1);
        auto t2 = std::chrono::steady_clock::now();
        HexEx::fromHexMesh(hm, out);
        write = since(t2);
        total = since(t0);
        hexes = out.hexes.size();
    } else if (path == "lcc") {
        TetLcc lcc;
        buildLcc(pm, lcc);
        pm = HexEx::ParametrizedTetMesh();
        HexLcc outLcc;
        HexEx::LccHexOutput<HexLcc> out(outLcc);
        auto t0 = std::chrono::steady_clock::now();
        const HexEx::LccTetMesh in(lcc);
        view = since(t0);
        auto t1 = std::chrono::steady_clock::now();
        HexEx::ParametrizedTetMesh copyPm = HexEx::toParametrizedTetMesh(in);
        copy = since(t1);
        auto t2 = std::chrono::steady_clock::now();
        HexEx::HexMesh hm;
        HexEx::extractHexMesh(copyPm, hm);
        extract = since(t2);
        auto t3 = std::chrono::steady_clock::now();
        HexEx::fromHexMesh(hm, out);
        write = since(t3);
        total = since(t0);
        hexes = out.cellDarts().size();
#ifdef HEXEX_BENCH_OVM
    } else if (path == "ovm") {
        OvmTets tm;
        buildOvm(pm, tm);
        pm = HexEx::ParametrizedTetMesh();
        OvmHexes hexMesh;
        HexEx::OvmHexOutput<OvmHexes> out(hexMesh);
        auto t0 = std::chrono::steady_clock::now();
        const HexEx::OvmTetMesh in(tm);
        view = since(t0);
        auto t1 = std::chrono::steady_clock::now();
        HexEx::ParametrizedTetMesh copyPm = HexEx::toParametrizedTetMesh(in);
        copy = since(t1);
        auto t2 = std::chrono::steady_clock::now();
        HexEx::HexMesh hm;
        HexEx::extractHexMesh(copyPm, hm);
        extract = since(t2);
        auto t3 = std::chrono::steady_clock::now();
        HexEx::fromHexMesh(hm, out);
        write = since(t3);
        total = since(t0);
        hexes = out.cells().size();
#endif
    } else {
        std::cerr << "unknown path " << path << "\n";
        return 2;
    }
    std::printf("case=%s path=%s hexes=%zu view_s=%.3f copy_s=%.3f extract_s=%.3f write_s=%.3f total_s=%.3f peak_mb=%.0f\n",
                c.c_str(), path.c_str(), hexes, view, copy, extract, write, total, peakMb());
    return 0;
}
