/// @file AdjacencyBenchmark.cc
/// Times TetMesh::build_adjacency() on a generated cube of about one million tets.
///
/// Usage: adjacency_benchmark [n] [repetitions]   (defaults: n = 55, i.e. 998,250 tets; 3 runs)
/// Prints the mesh size and the best and median wall-clock time of the runs.

#include <HexEx/Generators/Generators.hh>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 55;
    const int reps = argc > 2 ? std::atoi(argv[2]) : 3;
    if (n < 1 || reps < 1) {
        std::fprintf(stderr, "usage: %s [n >= 1] [repetitions >= 1]\n", argv[0]);
        return 2;
    }
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    HexEx::ParametrizedTetMesh pm = HexEx::generateCube(n, n);
    const double genSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    std::printf("cube n=%d: %zu vertices, %zu tets (generated in %.3f s)\n", n, pm.mesh.n_vertices(),
                pm.mesh.n_cells(), genSeconds);

    std::vector<double> times;
    for (int r = 0; r < reps; ++r) {
        HexEx::TetMesh mesh = pm.mesh;  // fresh copy: no state carried over between runs
        const auto start = Clock::now();
        mesh.build_adjacency();
        times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
        std::printf("run %d: build_adjacency %.3f s (%zu faces, %zu edges, %zu boundary faces)\n", r + 1, times.back(),
                    mesh.n_faces(), mesh.n_edges(), mesh.n_boundary_faces());
    }
    std::sort(times.begin(), times.end());
    std::printf("build_adjacency: best %.3f s, median %.3f s over %d runs (%.0f ns per tet)\n", times.front(),
                times[times.size() / 2], reps, 1e9 * times.front() / static_cast<double>(pm.mesh.n_cells()));
    return 0;
}
