/// @file QuadBenchmark.cc
/// Times the 2D pipeline (extractQuadMesh()) on generated maps of about one million
/// triangles, per stage, at the given thread counts: median wall-clock and CPU time
/// (std::clock(), all threads) of the runs, median CPU time of the calling thread alone
/// (`main_cpu`: it runs every serial part and one chunk of every parallel one, so with 2
/// threads it bounds the wall time from below even on a loaded machine), the stage times
/// of the median run.
///
/// Usage: `quad_benchmark [--threads 1,2] [--runs 3] [--quick] [--n N] [--min-per-thread K] [--io] [--cases LIST]`
/// Cases (`--cases`, comma-separated; default disk5,disk5-perturbed): disk5 (a flat disk
/// around a valence-5 cone, 998,560 triangles, 499,280 quads, exact map), disk5-perturbed
/// (the same map perturbed with a = 0.3 as `hexex perturb -a 0.3 --seed 1`, 29 flipped
/// triangles), torus (generateTorus(700, 700, 707, 707), 999,698 triangles, 490,000 quads)
/// and square (generateSquare(707, 707), 999,698 triangles, 499,849 quads): the four maps of
/// issue 27. `--quick` uses about 10,000 triangles (a smoke test), `--n N` 10 N^2 triangles
/// (torus and square: 2 M^2 with M = round(sqrt(5) N));
/// `--min-per-thread K` sets QuadExtractionOptions::min_triangles_per_thread. `--io` times, instead
/// of the extraction, the OBJ text of each case: writing it to /dev/null (writeTriObjFile(),
/// i.e. formatting) and parsing it from memory (parseTriObj()): median wall time, MB/s of
/// OBJ text, median CPU time (all threads).

#include <HexEx/Quad/QuadExtraction.hh>
#include <HexEx/Quad/TextMeshWriters.hh>
#include <HexEx/Quad/QuadGenerators.hh>
#include <HexEx/Quad/TriObjReader.hh>

#include <algorithm>
#include <cmath>
#include <time.h>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {
/// CPU seconds of the calling thread.
double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
} // namespace

int main(int argc, char** argv) {
    std::vector<int> threads = {1, 2};
    int runs = 3;
    bool quick = false, io = false;
    int size = 316;
    long minPerThread = HexEx::QuadExtractionOptions().min_triangles_per_thread;
    std::vector<std::string> names = {"disk5", "disk5-perturbed"};
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
        } else if (!std::strcmp(argv[i], "--n") && i + 1 < argc) {
            size = std::max(1, std::stoi(argv[++i]));
        } else if (!std::strcmp(argv[i], "--min-per-thread") && i + 1 < argc) {
            minPerThread = std::stol(argv[++i]);
        } else if (!std::strcmp(argv[i], "--io")) {
            io = true;
        } else if (!std::strcmp(argv[i], "--cases") && i + 1 < argc) {
            names.clear();
            std::stringstream ss(argv[++i]);
            std::string t;
            while (std::getline(ss, t, ',')) names.push_back(t);
        } else {
            std::fprintf(stderr, "usage: quad_benchmark [--threads 1,2] [--runs 3] [--quick] [--n N] [--min-per-thread K] [--io] "
                                 "[--cases disk5,disk5-perturbed,torus,square]\n");
            return 2;
        }
    }
    const int n = quick ? 32 : size;  // 5 wedges * n^2 boxes * 2 triangles
    struct Case {
        std::string name;
        HexEx::ParametrizedTriMesh mesh;
    };
    std::vector<Case> cases;
    const int m = static_cast<int>(std::lround(std::sqrt(5.0) * n));  // torus and square: 2 m^2 triangles
    for (const std::string& name : names) {
        if (name == "disk5") {
            cases.push_back({name, HexEx::generateConeDisk(5, n, n)});
        } else if (name == "disk5-perturbed") {
            cases.push_back({name, HexEx::generateConeDisk(5, n, n)});
            HexEx::perturbTriParameters(cases.back().mesh, 0.3, 1);
        } else if (name == "torus") {
            const int l = std::max(1, m * 700 / 707);
            cases.push_back({name, HexEx::generateTorus(l, l, std::max(3, m), std::max(3, m))});
        } else if (name == "square") {
            cases.push_back({name, HexEx::generateSquare(m, m)});
        } else {
            std::fprintf(stderr, "quad_benchmark: unknown case '%s' (disk5, disk5-perturbed, torus, square)\n", name.c_str());
            return 2;
        }
    }
    if (io) {
        std::printf("%-16s %8s %7s %7s %9s %11s %10s %9s %10s %10s\n", "case", "tris", "threads", "MB", "format_s",
                    "format_MB/s", "format_cpu", "parse_s", "parse_MB/s", "parse_cpu");
        for (const Case& c : cases)
            for (int t : threads) {
                std::vector<double> fs, ps, fc, pc;
                std::size_t bytes = 0;
                const std::string text = HexEx::formatTriObj(c.mesh, t);
                bytes = text.size();
                for (int r = 0; r < runs; ++r) {
                    auto t0 = std::chrono::steady_clock::now();
                    std::clock_t c0 = std::clock();
                    HexEx::writeTriObjFile("/dev/null", c.mesh, t);
                    fc.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
                    fs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                    t0 = std::chrono::steady_clock::now();
                    c0 = std::clock();
                    const HexEx::ParametrizedTriMesh back = HexEx::parseTriObj(text, c.name, t);
                    pc.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
                    ps.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                    if (back.triangles.size() != c.mesh.triangles.size()) return 1;
                }
                for (auto* v : {&fs, &ps, &fc, &pc}) std::sort(v->begin(), v->end());
                const std::size_t mid = fs.size() / 2;
                const double mb = static_cast<double>(bytes) / 1e6, f = fs[mid], p = ps[mid];
                std::printf("%-16s %8zu %7d %7.1f %9.3f %11.0f %10.3f %9.3f %10.0f %10.3f\n", c.name.c_str(),
                            c.mesh.triangles.size(), t, mb, f, mb / f, fc[mid], p, mb / p, pc[mid]);
            }
        return 0;
    }
    std::printf("%-16s %8s %7s %10s %9s %6s %8s %8s %8s %8s %8s %8s %8s %8s %8s\n", "case", "tris", "threads", "quads",
                "flipped", "valid", "total_s", "min_s", "cpu_s", "main_cpu", "prep_s", "darts_s", "conn_s", "post_s", "asm_s");
    for (const Case& c : cases)
        for (int t : threads) {
            struct Run {
                double wall, cpu, mainCpu;
                HexEx::QuadExtractionReport rep;
            };
            std::vector<Run> rs;
            for (int r = 0; r < runs; ++r) {
                HexEx::QuadMesh qm;
                HexEx::QuadExtractionOptions opt;
                opt.threads = t;
                opt.min_triangles_per_thread = minPerThread;
                const auto t0 = std::chrono::steady_clock::now();
                const std::clock_t c0 = std::clock();
                const double m0 = threadCpuSeconds();
                HexEx::QuadExtractionReport rep = HexEx::extractQuadMesh(c.mesh, qm, opt);
                const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
                const double mainCpu = threadCpuSeconds() - m0;
                rs.push_back({std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), cpu, mainCpu, rep});
            }
            std::vector<double> cpus, mains;
            for (const Run& r : rs) cpus.push_back(r.cpu);
            for (const Run& r : rs) mains.push_back(r.mainCpu);
            std::sort(cpus.begin(), cpus.end());
            std::sort(mains.begin(), mains.end());
            std::sort(rs.begin(), rs.end(), [](const Run& a, const Run& b) { return a.wall < b.wall; });
            const Run& med = rs[rs.size() / 2];
            const auto& rep = med.rep;
            const auto& ts = rep.timings_s;
            std::printf("%-16s %8ld %7d %10ld %9ld %6s %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f\n", c.name.c_str(),
                        rep.input.triangles, t, rep.output.quads, rep.input.flipped_triangles,
                        rep.valid_all_quad ? "yes" : "NO", med.wall, rs.front().wall, cpus[cpus.size() / 2], mains[mains.size() / 2], ts.preprocess,
                        ts.darts, ts.connect, ts.postprocess, ts.assemble);
        }
    return 0;
}
