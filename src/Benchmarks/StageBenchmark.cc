/// @file StageBenchmark.cc
/// Times every stage of extractHexMesh() on one `.hexex` file: wall time and CPU time of the
/// process (all threads) per stage. On a machine shared with other jobs the CPU time is the
/// steadier figure (wall time grows with the load, CPU time much less); compare two builds
/// alternately.
///
/// Usage: stage_benchmark FILE.hexex [threads] [repetitions]   (defaults: 2 threads, 3 runs)
/// Prints, per stage, the smallest wall and the smallest CPU time over the repetitions
/// (each minimum over all runs separately), and the same for the whole extraction.

#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <map>
#include <string>
#include <vector>

namespace {

/// CPU time of the process (all threads) in seconds.
double cpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Wall-clock seconds since an arbitrary start.
double wallSeconds() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

/// Wall and CPU seconds of one stage.
struct Lap {
    double wall = 1e300;  ///< smallest wall time
    double cpu = 1e300;   ///< smallest CPU time
};

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: stage_benchmark FILE.hexex [threads] [repetitions]\n");
        return 2;
    }
    const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
    const int reps = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
    try {
        const HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(argv[1]);
        std::vector<std::string> order;  // stages in the order they ran
        std::map<std::string, Lap> laps;
        for (int r = 0; r < reps; ++r) {
            std::string phase;
            double w0 = wallSeconds(), c0 = cpuSeconds();
            const double wStart = w0, cStart = c0;
            auto close = [&](const std::string& next) {
                const double w = wallSeconds(), c = cpuSeconds();
                if (!phase.empty()) {
                    if (!laps.count(phase)) order.push_back(phase);
                    Lap& l = laps[phase];
                    l.wall = std::min(l.wall, w - w0);
                    l.cpu = std::min(l.cpu, c - c0);
                }
                phase = next;
                w0 = w;
                c0 = c;
            };
            HexEx::ExtractionOptions opt;
            opt.threads = threads;
            opt.progress = [&](const std::string& p, double) {
                if (p != phase) close(p);
            };
            HexEx::HexMesh out;
            HexEx::extractHexMesh(pm, out, opt);
            close("");
            if (!laps.count("total")) order.push_back("total");
            Lap& t = laps["total"];
            t.wall = std::min(t.wall, wallSeconds() - wStart);
            t.cpu = std::min(t.cpu, cpuSeconds() - cStart);
        }
        std::printf("%-12s %9s %9s   (best of %d, %d threads, %s)\n", "stage", "wall_s", "cpu_s", reps, threads, argv[1]);
        for (const std::string& s : order)
            if (s != "done") std::printf("%-12s %9.3f %9.3f\n", s.c_str(), laps[s].wall, laps[s].cpu);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stage_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
