/// @file AdapterBenchmark.cc
/// Cost of the mesh-kernel adapters: time and peak memory of one extraction through the
/// traits (input view -> copy into the built-in kernel -> extraction -> output written
/// through the output traits) against the built-in kernel alone.
///
///   adapter_benchmark CASE PATH
///
/// CASE: cube40 (generateCube(80, 40): 3.07M tets, 64,000 hexes) or cylinder6
/// (generateCylinder(6, 64, 64, 1, 1): 36 tets, 1,572,864 hexes); cube20 (generateCube(40,
/// 20): 384,000 tets, 8,000 hexes) and cylinder6m (generateCylinder(6, 32, 32, 1, 1):
/// 196,608 hexes) are moderate, cube8/cylinder6s small versions. PATH: builtin,
/// builtin-provenance (the same with ExtractionOptions::provenance), arrays
/// (TetArraysView -> HexArrays), lcc (CGAL Linear_cell_complex both ways through the view
/// LccTetMesh and LccHexOutput), lcc-native (the one-call overload extractHexMesh(tetLcc,
/// hexLcc): read straight into the built-in kernel, copy freed before the writing) or, when
/// built with OpenVolumeMesh, ovm (tetrahedral kernel with the halfface map -> hexahedral
/// kernel, through OvmTetMesh and OvmHexOutput) and ovm-native (the one-call overload
/// extractHexMesh(tetMesh, halffaceProperty, hexMesh), timed stage by stage through the
/// same detail functions it calls) and ovm-native-split (the same, with cpu_write_s
/// HexEx's own writing and OpenVolumeMesh's rebuild of its bottom-up incidences
/// (OvmHexOutput::restoreIncidences()) timed apart as cpu_incidences_s: the two parts of
/// ovm-native's cpu_write_s; cpu_inc_vertex_s, cpu_inc_edge_s, cpu_inc_face_s: its vertex
/// lists, edge lists, and face incidences with OpenVolumeMesh's ordering of the halffaces
/// around every edge); ovm-native-vf is ovm-native into a hex mesh whose edge
/// incidences the user turned off (vertex and face incidences only). The other ways that
/// OpenVolumeMesh's public API leaves for writing into a hex mesh with all its incidences on
/// (issue 34; read and extraction as ovm-native): ovm-native-fe turns the face incidences on
/// before the edge incidences (cpu_inc_face_s: the face incidences alone, cpu_inc_edge_s: the
/// edge lists with the ordering of the halffaces around every edge); ovm-write-inc writes
/// with the incidences on from the start (OvmHexOutput's lookup tables, the mesh's
/// reserve_*() calls, OpenVolumeMesh updating its incidences cell by cell); ovm-write-ovm adds
/// every hex through OpenVolumeMesh's own add_cell(vertices) with its topology check, the
/// incidences on from the start (OvmHexOutput's topologyCheck). Run one measurement per process:
/// the peak resident set size (VmHWM) then belongs to it. Prints one line of
/// `key=value` pairs; building the input in the user's structure is not timed (input_mb:
/// the resident memory once it is built, the generated built-in mesh freed except for builtin). view_s:
/// the adapter's scan of the input; copy_s: toParametrizedTetMesh() including the
/// adjacency (for builtin: TetMesh::build_adjacency() alone); extract_s: the extraction;
/// write_s: fromHexMesh() into the output structure; total_s: all of them. cpu_copy_s,
/// cpu_extract_s, cpu_write_s: the same stages in CPU seconds of the process (all threads),
/// which a loaded machine distorts less than the wall times.

#include "../TestSupport/LccTetFixtures.hh"
#include "BenchClock.hh"

#include <HexEx/Adapters/CgalLinearCellComplex.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexExTraits.hh>

#ifdef HEXEX_BENCH_OVM
#include "../TestSupport/OvmTetFixtures.hh"

#include <HexEx/Adapters/OpenVolumeMesh.hh>
#include <OpenVolumeMesh/Mesh/HexahedralMesh.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralMesh.hh>
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <malloc.h>
#include <string>
#include <time.h>
#include <utility>

using HexExBench::cpuSeconds;

namespace {

/// Peak resident set size of this process in MB (VmHWM), or -1.
double peakMb() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return -1;
}

/// Resident set size of this process in MB (VmRSS) after returning freed heap memory to
/// the system, or -1.
double rssMb() {
    malloc_trim(0);
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return -1;
}

/// With the environment variable HEXEX_BENCH_MARKS set, prints `mark NAME T` to stderr, T
/// the CLOCK_MONOTONIC seconds of the steady clock: the stage boundaries for
/// `perf record -k CLOCK_MONOTONIC` and `perf report --time T0,T1` (a profile of one stage).
void mark(const char* name) {
    static const bool on = std::getenv("HEXEX_BENCH_MARKS") != nullptr;
    if (on)
        std::fprintf(stderr, "mark %s %.6f\n", name,
                     std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count());
}

/// Seconds since @p t0.
double since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}


using HexExTestSupport::HexLcc;
using HexExTestSupport::TetLcc;

#ifdef HEXEX_BENCH_OVM
using OvmTets = OpenVolumeMesh::GeometricTetrahedralMeshV3d;
using OvmHexes = OpenVolumeMesh::GeometricHexahedralMeshV3d;
#endif

/// Times of one extraction through the mesh-kernel traits (see the file comment).
struct Timings {
    double view = 0;     ///< constructing the input view (the adapter's scan)
    double copy = 0;     ///< toParametrizedTetMesh(), adjacency included
    double extract = 0;  ///< extractHexMesh() on the built-in kernel
    double write = 0;    ///< fromHexMesh() into the output structure
    double total = 0;    ///< all of them
    double cpu_copy = 0, cpu_extract = 0, cpu_write = 0;  ///< CPU seconds of copy, extract, write
    double cpu_incidences = 0;  ///< CPU seconds of OpenVolumeMesh's incidence rebuild (ovm-native-split)
    double cpu_inc_vertex = 0, cpu_inc_edge = 0, cpu_inc_face = 0;  ///< its parts (see ovm-native-split)
};

/// Runs view -> copy -> extraction -> write-back: @p makeView returns the input view,
/// @p out receives the hex mesh through the output traits.
template <class MakeView, class Output>
Timings timeThroughTraits(MakeView makeView, Output& out) {
    Timings r;
    const auto t0 = std::chrono::steady_clock::now();
    const auto in = makeView();
    r.view = since(t0);
    const auto t1 = std::chrono::steady_clock::now();
    const double c1 = cpuSeconds();
    HexEx::ParametrizedTetMesh copyPm = HexEx::toParametrizedTetMesh(in);
    r.copy = since(t1);
    const double c2 = cpuSeconds();
    r.cpu_copy = c2 - c1;
    const auto t2 = std::chrono::steady_clock::now();
    HexEx::HexMesh hm;
    HexEx::extractHexMesh(copyPm, hm);
    r.extract = since(t2);
    const double c3 = cpuSeconds();
    r.cpu_extract = c3 - c2;
    const auto t3 = std::chrono::steady_clock::now();
    HexEx::fromHexMesh(hm, out);
    r.write = since(t3);
    r.cpu_write = cpuSeconds() - c3;
    r.total = since(t0);
    return r;
}

/// The stages of a one-call overload: @p read copies the user's mesh into the built-in
/// kernel (adjacency included), the extraction runs taking the copy's parameters over as its
/// working copy (the builtin path's extraction copies them), the copy is freed, and the
/// result is written by @p write (called with the HexMesh, which it may free, and the
/// timings, whose cpu_incidences it may set).
template <class Read, class Write>
Timings timeOneCall(Read read, Write write) {
    Timings r;
    mark("read");
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpuSeconds();
    HexEx::HexMesh hm;
    double c3 = 0;
    {
        HexEx::ParametrizedTetMesh copyPm = read();
        r.copy = since(t0);
        mark("extract");
        const double c2 = cpuSeconds();
        r.cpu_copy = c2 - c0;
        const auto t2 = std::chrono::steady_clock::now();
        HexEx::extractHexMesh(std::move(copyPm), hm);  // parameters taken over, as in the overloads
        r.extract = since(t2);
        c3 = cpuSeconds();
        r.cpu_extract = c3 - c2;
    }
    mark("write");
    const auto t3 = std::chrono::steady_clock::now();
    write(hm, r);
    r.write = since(t3);
    mark("end");
    r.cpu_write = cpuSeconds() - c3 - r.cpu_incidences;
    r.total = since(t0);
    return r;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: adapter_benchmark cube40|cylinder6|cube20|cylinder6m|cube8|cylinder6s "
                     "builtin|builtin-provenance|arrays|lcc|lcc-native"
#ifdef HEXEX_BENCH_OVM
                     "|ovm|ovm-native|ovm-native-split|ovm-native-vf|ovm-native-fe|ovm-write-inc|ovm-write-ovm"
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
    else if (c == "cube20") pm = HexEx::generateCube(40, 20);
    else if (c == "cylinder6m") pm = HexEx::generateCylinder(6, 32, 32, 1, 1);
    else {
        std::cerr << "unknown case " << c << "\n";
        return 2;
    }
    Timings r;
    std::size_t hexes = 0;
    double inputMb = -1;  // resident memory once the input is built (the user's structure)
    if (path == "builtin" || path == "builtin-provenance") {
        inputMb = rssMb();
        // copy_s: the adjacency, which the traits path builds inside its copy.
        mark("read");
        auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpuSeconds();
        pm.mesh.build_adjacency();
        r.copy = since(t0);
        const double c1 = cpuSeconds();
        r.cpu_copy = c1 - c0;
        HexEx::HexMesh hm;
        HexEx::HexProvenance prov;
        HexEx::ExtractionOptions opt;
        if (path == "builtin-provenance") opt.provenance = &prov;
        mark("extract");
        auto t1 = std::chrono::steady_clock::now();
        HexEx::extractHexMesh(pm, hm, opt);
        r.extract = since(t1);
        mark("end");
        r.cpu_extract = cpuSeconds() - c1;
        r.total = since(t0);
        hexes = hm.hexes.size();
    } else if (path == "arrays") {
        std::vector<HexEx::Vec3d> positions(pm.mesh.n_vertices());
        for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = pm.mesh.position(HexEx::VertexHandle(int(v)));
        std::vector<std::array<int, 4>> tets(pm.mesh.n_cells());
        for (std::size_t t = 0; t < tets.size(); ++t)
            for (int i = 0; i < 4; ++i) tets[t][std::size_t(i)] = pm.mesh.cell_vertex(HexEx::CellHandle(int(t)), i).idx();
        std::vector<std::array<HexEx::Vec3d, 4>> params = pm.params;
        pm = HexEx::ParametrizedTetMesh();
        inputMb = rssMb();
        HexEx::HexArrays out;
        r = timeThroughTraits([&] { return HexEx::TetArraysView{&positions, &tets, &params}; }, out);
        hexes = out.hexes.size();
    } else if (path == "lcc") {
        TetLcc lcc;
        HexExTestSupport::buildTetLcc(pm, lcc);
        pm = HexEx::ParametrizedTetMesh();
        inputMb = rssMb();
        HexLcc outLcc;
        HexEx::LccHexOutput<HexLcc> out(outLcc);
        r = timeThroughTraits([&] { return HexEx::LccTetMesh(lcc); }, out);
        hexes = out.cellDarts().size();
    } else if (path == "lcc-native") {
        TetLcc lcc;
        HexExTestSupport::buildTetLcc(pm, lcc);
        pm = HexEx::ParametrizedTetMesh();
        inputMb = rssMb();
        HexLcc outLcc;
        r = timeOneCall([&] { return HexEx::detail::lccToParametrizedTetMesh(lcc, HexEx::LccDartInfoParameter{}, 0); },
                        [&](HexEx::HexMesh& hm, Timings&) {
                            HexEx::LccHexOutput<HexLcc> out(outLcc);
                            HexEx::fromHexMesh(hm, out);
                        });
        hexes = outLcc.one_dart_per_cell<3>().size();
#ifdef HEXEX_BENCH_OVM
    } else if (path == "ovm") {
        OvmTets tm;
        HexExTestSupport::buildOvmTets(pm, tm);
        pm = HexEx::ParametrizedTetMesh();
        inputMb = rssMb();
        OvmHexes hexMesh;
        HexEx::OvmHexOutput<OvmHexes> out(hexMesh);
        r = timeThroughTraits([&] { return HexEx::OvmTetMesh(tm); }, out);
        hexes = out.cells().size();
    } else if (path == "ovm-native" || path == "ovm-native-split" || path == "ovm-native-vf" || path == "ovm-native-fe" ||
               path == "ovm-write-inc" || path == "ovm-write-ovm") {
        OvmTets tm;
        HexExTestSupport::buildOvmTets(pm, tm);
        pm = HexEx::ParametrizedTetMesh();
        inputMb = rssMb();
        const auto prop = *tm.get_halfface_property<OpenVolumeMesh::Geometry::Vec3d>(HexEx::kOvmParametrization);
        OvmHexes hexMesh;
        if (path == "ovm-native-vf") hexMesh.enable_edge_bottom_up_incidences(false);  // the user needs no edge incidences
        const bool split = path == "ovm-native-split", faceFirst = path == "ovm-native-fe";
        r = timeOneCall(
            [&] {
                // The accessor of the halfface overload (the property's values by pointer, prefetched).
                return HexEx::detail::ovmToParametrizedTetMesh(
                    tm, HexEx::detail::OvmHalffaceParams<OpenVolumeMesh::Geometry::Vec3d>{prop.data_vector().data()}, 0);
            },
            [&](HexEx::HexMesh& hm, Timings& t) {  // the writing of the one-call overload (extractOvm())
                if (path == "ovm-write-inc") {  // incidences on while writing: no OvmHexOutput::reserve()
                    HexEx::OvmHexOutput<OvmHexes> out(hexMesh);
                    out.clear();
                    hexMesh.reserve_vertices(hm.vertices.size());
                    hexMesh.reserve_edges(hm.vertices.size() + 2 * hm.hexes.size());
                    hexMesh.reserve_faces(3 * hm.hexes.size() + hm.hexes.size() / 2);
                    hexMesh.reserve_cells(hm.hexes.size());
                    for (const HexEx::Vec3d& p : hm.vertices) out.addVertex(p);
                    for (const auto& h : hm.hexes) {
                        std::array<std::size_t, 8> hv;
                        for (std::size_t i = 0; i < 8; ++i) hv[i] = static_cast<std::size_t>(h[i]);
                        out.addHex(hv);
                    }
                    return;
                }
                if (path == "ovm-write-ovm") {  // OpenVolumeMesh's own add_cell(vertices), checked
                    HexEx::OvmHexOutput<OvmHexes> out(hexMesh, /*topologyCheck=*/true);
                    HexEx::fromHexMesh(hm, out);
                    return;
                }
                HexEx::OvmHexOutput<OvmHexes> out(hexMesh);
                out.deferIncidences();
                HexEx::fromHexMesh(hm, out);
                hm = HexEx::HexMesh();
                const double c0 = cpuSeconds();
                if (faceFirst) {  // face incidences first: the ordering is done with the edge lists
                    hexMesh.enable_vertex_bottom_up_incidences(true);
                    const double c1 = cpuSeconds();
                    hexMesh.enable_face_bottom_up_incidences(true);
                    const double c2 = cpuSeconds();
                    hexMesh.enable_edge_bottom_up_incidences(true);
                    const double c3 = cpuSeconds();
                    t.cpu_inc_vertex = c1 - c0;
                    t.cpu_inc_face = c2 - c1;
                    t.cpu_inc_edge = c3 - c2;
                }
                if (split) {
                    // restoreIncidences()'s order, kind by kind: the vertex lists, the edge
                    // lists (face incidences still off: no ordering), then the face
                    // incidences, with which OpenVolumeMesh orders the halffaces around
                    // every edge.
                    hexMesh.enable_vertex_bottom_up_incidences(true);
                    const double c1 = cpuSeconds();
                    hexMesh.enable_edge_bottom_up_incidences(true);
                    const double c2 = cpuSeconds();
                    hexMesh.enable_face_bottom_up_incidences(true);
                    const double c3 = cpuSeconds();
                    t.cpu_inc_vertex = c1 - c0;
                    t.cpu_inc_edge = c2 - c1;
                    t.cpu_inc_face = c3 - c2;
                }
                out.restoreIncidences();  // with split: nothing left to do
                if (split || faceFirst) t.cpu_incidences = cpuSeconds() - c0;
            });
        hexes = hexMesh.n_cells();
#endif
    } else {
        std::cerr << "unknown path " << path << "\n";
        return 2;
    }
    std::printf("case=%s path=%s hexes=%zu view_s=%.3f copy_s=%.3f extract_s=%.3f write_s=%.3f total_s=%.3f peak_mb=%.0f "
                "input_mb=%.0f cpu_copy_s=%.3f cpu_extract_s=%.3f cpu_write_s=%.3f cpu_incidences_s=%.3f cpu_inc_vertex_s=%.3f "
                "cpu_inc_edge_s=%.3f cpu_inc_face_s=%.3f\n",
                c.c_str(), path.c_str(), hexes, r.view, r.copy, r.extract, r.write, r.total, peakMb(), inputMb, r.cpu_copy,
                r.cpu_extract, r.cpu_write, r.cpu_incidences, r.cpu_inc_vertex, r.cpu_inc_edge, r.cpu_inc_face);
    return 0;
}
