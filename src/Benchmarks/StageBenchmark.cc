/// @file StageBenchmark.cc
/// Times every stage of extractHexMesh() on one `.hexex` file: wall time and CPU time of the
/// process (all threads) per stage. On a machine shared with other jobs the CPU time is the
/// steadier figure (wall time grows with the load, CPU time much less); compare two builds
/// alternately.
///
/// Usage: stage_benchmark FILE.hexex [threads] [repetitions]   (defaults: 2 threads, 3 runs)
/// Prints, per stage, the smallest wall and the smallest CPU time over the repetitions
/// (each minimum over all runs separately), and the same for the whole extraction.

#include "BenchClock.hh"

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

using HexExBench::cpuSeconds;
using HexExBench::wallSeconds;
using Lap = HexExBench::BestTime;

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
                    laps[phase].offerLap(w - w0, c - c0);
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
            laps["total"].offer(wStart, cStart);
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
