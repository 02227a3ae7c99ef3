/// @file QuadBenchmark.cc
/// Times the 2D pipeline (extractQuadMesh()) on generated maps of about one million
/// triangles, per stage, at the given thread counts (median of the runs).
///
/// Usage: `quad_benchmark [--threads 1,2] [--runs 3] [--quick]`
/// Cases: disk5 (a flat disk around a valence-5 cone, 998,560 triangles, 499,280 quads,
/// exact map) and disk5-perturbed (the same map perturbed with a = 0.3, many flipped
/// triangles). `--quick` uses about 10,000 triangles (a smoke test).

#include <HexEx/Quad/QuadExtraction.hh>
#include <HexEx/Quad/QuadGenerators.hh>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::vector<int> threads = {1, 2};
    int runs = 3;
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
            threads.clear();
            std::stringstream ss(argv[++i]);
            std::string t;
            while (std::getline(ss, t, ',')) threads.push_back(std::stoi(t));
        } else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) {
            runs = std::max(1, std::stoi(argv[++i]));
        } else if (!std::strcmp(argv[i], "--quick")) {
            quick = true;
        } else {
            std::fprintf(stderr, "usage: quad_benchmark [--threads 1,2] [--runs 3] [--quick]\n");
            return 2;
        }
    }
    const int n = quick ? 32 : 316;  // 5 wedges * n^2 boxes * 2 triangles
    struct Case {
        std::string name;
        HexEx::ParametrizedTriMesh mesh;
    };
    std::vector<Case> cases;
    cases.push_back({"disk5", HexEx::generateConeDisk(5, n, n)});
    cases.push_back({"disk5-perturbed", cases[0].mesh});
    HexEx::perturbTriParameters(cases[1].mesh, 0.3, 1);
    std::printf("%-16s %8s %7s %10s %9s %6s %8s %8s %8s %8s %8s %8s\n", "case", "tris", "threads", "quads", "flipped", "valid",
                "total_s", "prep_s", "darts_s", "conn_s", "post_s", "asm_s");
    for (const Case& c : cases)
        for (int t : threads) {
            std::vector<double> totals;
            HexEx::QuadExtractionReport rep;
            for (int r = 0; r < runs; ++r) {
                HexEx::QuadMesh qm;
                HexEx::QuadExtractionOptions opt;
                opt.threads = t;
                const auto t0 = std::chrono::steady_clock::now();
                rep = HexEx::extractQuadMesh(c.mesh, qm, opt);
                totals.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            }
            std::sort(totals.begin(), totals.end());
            const auto& ts = rep.timings_s;
            std::printf("%-16s %8ld %7d %10ld %9ld %6s %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f\n", c.name.c_str(),
                        rep.input.triangles, t, rep.output.quads, rep.input.flipped_triangles,
                        rep.valid_all_quad ? "yes" : "NO", totals[totals.size() / 2], ts.preprocess, ts.darts, ts.connect,
                        ts.postprocess, ts.assemble);
        }
    return 0;
}
