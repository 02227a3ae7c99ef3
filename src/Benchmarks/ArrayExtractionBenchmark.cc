/// @file ArrayExtractionBenchmark.cc
/// The C++ side of the Python binding benchmark (python/benchmarks/bench_extract.py): times
/// the extraction of a tet mesh with its map held in plain arrays, i.e. exactly what
/// `hexex.extract(points, tets, params)` does below the binding.
///
/// Usage:
/// ```
/// array_extraction_benchmark POINTS.f64 TETS.i32 PARAMS.f64 [--threads N] [--repeat K]
/// ```
/// The three files hold raw little-endian arrays as numpy's `tofile()` writes them:
/// float64 (n,3) points, int32 (m,4) tets and float64 (m,4,3) corner parameters. Reading
/// them is not timed. Each repeat times the conversion into the library's tet mesh
/// (toParametrizedTetMesh() of a TetArraysView, which builds the adjacency), the
/// manifoldness check that the readers and the binding run, and extractHexMesh(); one line
/// per repeat: `seconds=S convert=C manifold=M extract=E hexes=H vertices=V` (S = C + M + E +
/// freeing the converted mesh).

#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/ArrayMeshTraits.hh>
#include <HexEx/Mesh/MeshTraits.hh>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// The bytes of file @p path; throws std::runtime_error if it cannot be read.
std::vector<char> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open");
    return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// Reinterprets the raw bytes of @p path as elements of T (a trivially copyable array
/// type); throws if the size is not a multiple of sizeof(T).
template <class T>
std::vector<T> readArray(const std::string& path) {
    const std::vector<char> bytes = readBytes(path);
    if (bytes.size() % sizeof(T) != 0) throw std::runtime_error(path + ": size is not a multiple of the row size");
    std::vector<T> out(bytes.size() / sizeof(T));
    if (!out.empty()) std::memcpy(static_cast<void*>(out.data()), bytes.data(), bytes.size());
    return out;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: array_extraction_benchmark POINTS.f64 TETS.i32 PARAMS.f64 [--threads N] [--repeat K]\n");
        return 2;
    }
    int threads = 0, repeat = 5;
    for (int i = 4; i + 1 < argc; i += 2) {
        const std::string opt = argv[i];
        if (opt == "--threads") threads = std::atoi(argv[i + 1]);
        else if (opt == "--repeat") repeat = std::atoi(argv[i + 1]);
        else {
            std::fprintf(stderr, "unknown option %s\n", opt.c_str());
            return 2;
        }
    }
    try {
        const std::vector<HexEx::Vec3d> points = readArray<HexEx::Vec3d>(argv[1]);
        const std::vector<std::array<int, 4>> tets = readArray<std::array<int, 4>>(argv[2]);
        const std::vector<std::array<HexEx::Vec3d, 4>> params = readArray<std::array<HexEx::Vec3d, 4>>(argv[3]);
        const HexEx::TetArraysView view{&points, &tets, &params};
        for (int r = 0; r < repeat; ++r) {
            using Clock = std::chrono::steady_clock;
            auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
            double convert = 0, manifold = 0, extract = 0;
            HexEx::HexMesh hm;
            const auto t0 = Clock::now();
            {
                // As extractHexMesh() of a TetArraysView does: the converted mesh is a
                // temporary, and freeing it is part of the time.
                const HexEx::ParametrizedTetMesh pm = HexEx::toParametrizedTetMesh(view);
                convert = since(t0);
                const auto t1 = Clock::now();
                if (!pm.mesh.check_manifold().empty()) throw std::runtime_error("input is not a manifold");
                manifold = since(t1);
                const auto t2 = Clock::now();
                HexEx::ExtractionOptions opt;
                opt.threads = threads;
                HexEx::extractHexMesh(pm, hm, opt);
                extract = since(t2);
            }
            std::printf("seconds=%.6f convert=%.6f manifold=%.6f extract=%.6f hexes=%zu vertices=%zu\n", since(t0),
                        convert, manifold, extract, hm.hexes.size(), hm.vertices.size());
            std::fflush(stdout);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "array_extraction_benchmark: %s\n", e.what());
        return 2;
    }
    return 0;
}
