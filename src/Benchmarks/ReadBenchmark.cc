/// @file ReadBenchmark.cc
/// Times the two steps before the extraction proper on one `.hexex` file: reading it
/// (parsing, orientation checks, adjacency, manifold check: readHexExBuffer() on the mapped
/// file) and the preprocess stage (parameter checks, transitions, sanitization,
/// singularities, per-tet data). Wall time and CPU time of the process (all threads); on a
/// machine shared with other jobs the CPU time is the steadier figure.
///
/// Usage: read_benchmark FILE.hexex [threads] [repetitions]   (defaults: 2 threads, 3 runs)
/// Prints the smallest wall and the smallest CPU time of each step over the repetitions,
/// and the mesh's counts (a check that two builds read the same mesh).

#include "BenchClock.hh"

#include <HexEx/IO/FileBytes.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/Pipeline/PreprocessStage.hh>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>

using HexExBench::BestTime;
using HexExBench::cpuSeconds;
using HexExBench::wallSeconds;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: read_benchmark FILE.hexex [threads] [repetitions]\n");
        return 2;
    }
    const int threads = argc > 2 ? std::max(1, std::atoi(argv[2])) : 2;
    const int reps = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
    try {
        BestTime read, pre;
        std::size_t nv = 0, nc = 0, ne = 0, nf = 0, nb = 0;
        long singular = 0;
        for (int r = 0; r < reps; ++r) {
            double w0 = wallSeconds(), c0 = cpuSeconds();
            const HexEx::detail::FileBytes bytes(argv[1]);
            HexEx::ParametrizedTetMesh pm = HexEx::readHexExBuffer(bytes.view(), argv[1], nullptr, threads);
            read.offer(w0, c0);
            w0 = wallSeconds();
            c0 = cpuSeconds();
            HexEx::PreprocessInput in;
            in.input = &pm;
            in.threads = threads;
            in.owned_params = &pm.params;  // as hexex extract does
            const HexEx::PreprocessOutput out = HexEx::preprocess(in);
            pre.offer(w0, c0);
            nv = pm.mesh.n_vertices();
            nc = pm.mesh.n_cells();
            ne = pm.mesh.n_edges();
            nf = pm.mesh.n_faces();
            nb = pm.mesh.n_boundary_faces();
            singular = out.stats.singular_edges;
        }
        std::printf("%-12s %9s %9s   (best of %d, %d threads, %s)\n", "step", "wall_s", "cpu_s", reps, threads, argv[1]);
        std::printf("%-12s %9.3f %9.3f\n", "read", read.wall, read.cpu);
        std::printf("%-12s %9.3f %9.3f\n", "preprocess", pre.wall, pre.cpu);
        std::printf("%-12s %9.3f %9.3f\n", "total", read.wall + pre.wall, read.cpu + pre.cpu);
        std::printf("mesh: %zu vertices, %zu tets, %zu edges, %zu faces, %zu boundary faces, %ld singular edges\n", nv, nc,
                    ne, nf, nb, singular);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "read_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
