/// @file WriterBenchmark.cc
/// Times the hex mesh writers (and the OpenVolumeMesh face numbering they need) on one mesh.
///
/// Usage: writer_benchmark MESH [threads] [repetitions] [formats] [DIR]   (defaults: 2 threads,
/// 3 runs, all formats; formats is a comma-separated list of faces,vtu,vtk,ovm,ovmb,mesh or "all";
/// tfaces, tovm, tovmb: the same with a face-neighbour table, HexFaceNeighbours.hh, built before
/// each run by checkAssembledHexes() as the extraction builds it, not timed; not in "all").
/// Without DIR every format is written to an std::ostringstream (the time includes growing it);
/// with DIR to the file DIR/writer_benchmark.EXT by writeHexMesh(), as `hexex` writes its output
/// (the time includes the kernel's copy into the page cache, not the disk).
/// MESH is any hex mesh file readHexMesh() reads (e.g. the `.vtu` written by `hexex extract`).
/// Every format is written to memory; prints the best wall time of each, the CPU time of
/// that run (all threads; steadier than wall time on a shared machine) and the output size.

#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/OvmModel.hh>
#include <HexEx/Postprocessing/AssembledMeshCheck.hh>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// CPU time of the process (all threads) in seconds.
double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

/// Best wall time of @p reps runs of @p f, and the CPU time of that run in @p cpu; @p before
/// (if set) runs untimed before each run.
double best(int reps, const std::function<void()>& f, double& cpu, const std::function<void()>& before = {}) {
    double t = 1e300;
    for (int r = 0; r < reps; ++r) {
        if (before) before();
        const auto start = std::chrono::steady_clock::now();
        const double c0 = cpuSeconds();
        f();
        const double w = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (w < t) t = w, cpu = cpuSeconds() - c0;
    }
    return t;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s MESH [threads] [repetitions] [formats] [DIR]\n", argv[0]);
        return 2;
    }
    const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
    const int reps = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
    const std::string only = argc > 4 && std::string(argv[4]) != "all" ? "," + std::string(argv[4]) + "," : "";
    const std::string dir = argc > 5 ? argv[5] : "";
    const auto wanted = [&](const char* name) { return only.empty() || only.find("," + std::string(name) + ",") != std::string::npos; };
    try {
        const HexEx::HexMesh mesh = HexEx::readHexMesh(argv[1]);
        std::printf("%s: %zu vertices, %zu hexes, %zu polyhedra; %d threads, best of %d\n", argv[1],
                    mesh.vertices.size(), mesh.hexes.size(), mesh.polyhedra.size(), threads, reps);
        std::size_t faces = 0;
        double cpu = 0;
        if (wanted("faces")) {
            const double tf = best(reps, [&] { faces = HexEx::ovmFlatFromHexMesh(mesh, threads).faces.size(); }, cpu);
            std::printf("%-6s %8.3f s wall %8.3f s cpu  (%zu faces)\n", "faces", tf, cpu, faces);
        }
        // The table variants: only when named.
        HexEx::HexFaceNeighbours table;
        const auto buildTable = [&] { HexEx::checkAssembledHexes(mesh, threads, nullptr, 0, &table); };
        const auto named = [&](const char* name) { return !only.empty() && wanted(name); };
        if (named("tfaces")) {
            const double tf = best(reps, [&] { faces = HexEx::ovmFlatFromHexMesh(mesh, threads, &table).faces.size(); }, cpu, buildTable);
            std::printf("%-6s %8.3f s wall %8.3f s cpu  (%zu faces)\n", "tfaces", tf, cpu, faces);
        }
        for (const auto& [name, format] : {std::pair<const char*, HexEx::HexMeshFormat>{"tovm", HexEx::HexMeshFormat::Ovm},
                                           std::pair<const char*, HexEx::HexMeshFormat>{"tovmb", HexEx::HexMeshFormat::Ovmb}}) {
            if (!named(name)) continue;
            std::size_t bytes = 0;
            const double t = best(reps, [&, format = format] {
                std::ostringstream out;
                HexEx::writeHexMeshStream(out, mesh, format, HexEx::VtuEncoding::Binary, threads, &table);
                bytes = static_cast<std::size_t>(out.tellp());
            }, cpu, buildTable);
            std::printf("%-6s %8.3f s wall %8.3f s cpu  %zu bytes\n", name, t, cpu, bytes);
        }
        const std::pair<const char*, HexEx::HexMeshFormat> formats[] = {
            {"vtu", HexEx::HexMeshFormat::Vtu}, {"vtk", HexEx::HexMeshFormat::Vtk},
            {"ovm", HexEx::HexMeshFormat::Ovm}, {"ovmb", HexEx::HexMeshFormat::Ovmb},
            {"mesh", HexEx::HexMeshFormat::Medit}};
        for (const auto& [name, format] : formats) {
            if (!wanted(name)) continue;
            std::size_t bytes = 0;
            const std::string path = dir + "/writer_benchmark." + name;
            const double t = best(reps, [&] {
                if (!dir.empty()) {
                    HexEx::writeHexMesh(path, mesh, HexEx::VtuEncoding::Binary, threads);
                    std::ifstream in(path, std::ios::binary | std::ios::ate);
                    bytes = static_cast<std::size_t>(in.tellg());
                    return;
                }
                std::ostringstream out;
                HexEx::writeHexMeshStream(out, mesh, format, HexEx::VtuEncoding::Binary, threads);
                bytes = static_cast<std::size_t>(out.tellp());
            }, cpu);
            if (!dir.empty()) std::remove(path.c_str());
            std::printf("%-6s %8.3f s wall %8.3f s cpu  %zu bytes\n", name, t, cpu, bytes);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "writer_benchmark: %s\n", e.what());
        return 2;
    }
    return 0;
}
