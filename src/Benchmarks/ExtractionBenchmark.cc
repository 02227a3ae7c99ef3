/// @file ExtractionBenchmark.cc
/// Times the whole extraction pipeline (extractHexMesh()) on the inputs of the published
/// performance table, per stage, with the peak memory of every measurement.
///
/// Usage:
/// ```
/// extraction_benchmark [--case NAME]... [--threads 1,2] [--json OUT.json]
///                      [--data-dir DIR] [--quick] [--timeout SECONDS] [--max-memory SIZE] [--arcs] [--list]
/// ```
/// Cases (default: all): cube20, cube30, cube40, cylinder6, s1x2, perturbed, sphere_1e5,
/// sphere_1e6 (one corrupted number: repaired), needle_1e4, needle_1e5 (the interior vertex
/// moved in all its tets: a genuine fold), read_cube20, write_cylinder6 (the cylinder6 extraction, then writeHexMesh()
/// to .vtu in each encoding).
/// `--quick` runs small versions of every case as a smoke test.
///
/// Every measurement (one case at one thread count) runs in a child process made with
/// fork(), so that its peak resident set size (VmHWM of /proc/self/status) is its own: the
/// parent stays small and builds no mesh, and the kernel starts a forked child's high-water
/// mark at the child's current RSS. The child builds the input (not timed), builds the
/// adjacency (timed, "adjacency"), runs extractHexMesh() (timed, "total", with the report's
/// per-stage timings) and sends one line of `key=value` fields back through a pipe.
/// A crash, an out-of-memory kill or a `--timeout` is reported as that row's status; the
/// other rows still run. A refusal by the memory budget (HexEx::ResourceError) is the
/// status "refused", with the time and peak memory until the refusal.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Core/Error.hh>
#include <HexEx/Core/Memory.hh>
#include <HexEx/Core/Parallel.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/HexMeshWriters.hh>

#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#ifndef HEXEX_SOURCE_DIR
#define HEXEX_SOURCE_DIR "."
#endif

namespace {

using Clock = std::chrono::steady_clock;

/// Seconds since @p t0.
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Reads a `kB` field (e.g. "VmHWM") of /proc/self/status; returns -1 if unavailable.
long procStatusKb(const char* field) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::size_t len = std::strlen(field);
    while (std::getline(in, line)) {
        if (line.compare(0, len, field) == 0 && line.size() > len && line[len] == ':')
            return std::strtol(line.c_str() + len + 1, nullptr, 10);
    }
    return -1;
}

/// Best effort: resets the peak RSS of this process to its current RSS (Linux >= 4.0).
void resetPeakRss() {
    std::ofstream out("/proc/self/clear_refs");
    if (out) out << "5";
}

/// Command-line options.
struct Options {
    std::vector<std::string> cases;  ///< cases to run, in order
    std::vector<int> threads{1, 2};  ///< thread counts to run each case with
    std::string json;                ///< JSON output path, empty for none
    std::string data_dir = std::string(HEXEX_SOURCE_DIR) + "/../shared/data";  ///< real inputs
    bool quick = false;              ///< small inputs only
    double timeout_s = 0;            ///< per-measurement time limit, 0 for none
    bool arcs = false;               ///< also compute edge arcs and face patches (ExtractionOptions::arcs)
    std::uint64_t max_memory = 0;    ///< ExtractionOptions::max_memory (0: the library's default)
};

/// The published numbers a case is compared with (NaN / empty where the table has none).
struct Reference {
    long tets = 0, hexes = 0;  ///< input and output size in the published table
    double hexex_s = NAN;      ///< reference HexEx, seconds
    double hexhex_1t_s = NAN;  ///< HexHex with 1 thread, seconds
    double hexhex_2t_s = NAN;  ///< HexHex with 2 threads, seconds
    std::string memory;        ///< peak memory as published
    std::string note;          ///< anything else
};

/// A benchmark case: how to build its input for the full and the quick run.
struct CaseDef {
    std::string name;         ///< name on the command line and in the output
    std::string description;  ///< full-size input
    std::string quick;        ///< quick-mode input
    bool is_read = false;     ///< times readHexExFile() instead of the extraction
    Reference ref;            ///< published numbers (full size only)
};

/// All cases, in default order.
const std::vector<CaseDef>& caseDefs() {
    static const std::vector<CaseDef> defs = {
        {"cube20", "generateCube(40, 20)", "generateCube(10, 5)", false,
         {384000, 8000, 23.6, 3.16, 1.90, "", ""}},
        {"cube30", "generateCube(60, 30)", "generateCube(12, 6)", false,
         {1296000, 27000, 83.0, NAN, NAN, "1.9 GB (reference)", ""}},
        {"cube40", "generateCube(80, 40)", "generateCube(16, 8)", false,
         {3072000, 64000, NAN, 37.0, 22.7, "5.2 GB (HexHex)", ""}},
        {"cylinder6", "generateCylinder(6, 64, 64, 1, 1)", "generateCylinder(6, 8, 8, 1, 1)", false,
         {36, 1572864, NAN, 5.85, 5.25, "1.0-2.0 GB (HexHex)", ""}},
        {"s1x2", "S1_polycube_scale2.hexex.xz", "S1_polycube_scale1.hexex.xz", false,
         {113683, 84347, 47.6, NAN, NAN, "", "HexHex refuses the input"}},
        {"perturbed", "generateCube(24, 12) + perturbParameters(a=1, seed=1)",
         "generateCube(8, 4) + perturbParameters(a=1, seed=1)", false, {}},
        {"sphere_1e5", "sphere.hexex, tet 10 corner 2 v = 1e5 (one bad parameter)",
         "sphere.hexex, tet 10 corner 2 v = 1e3", false, {}},
        {"sphere_1e6", "sphere.hexex, tet 10 corner 2 v = 1e6 (one bad parameter)",
         "sphere.hexex, tet 10 corner 2 v = 1e4", false, {}},
        {"needle_1e4", "sphere.hexex, vertex 40 v += 1e4 in all its tets (a genuine fold)",
         "sphere.hexex, vertex 40 v += 1e2 in all its tets", false, {}},
        {"needle_1e5", "sphere.hexex, vertex 40 v += 1e5 in all its tets (a genuine fold)",
         "sphere.hexex, vertex 40 v += 1e3 in all its tets", false, {}},
        {"read_cube20", "readHexExFile of generateCube(40, 20)", "readHexExFile of generateCube(10, 5)", true,
         {384000, 0, 10.0, 5.0, NAN, "", "31 MB .hexex; HexHex time is its reader"}},
        {"write_cylinder6", "writeHexMesh(.vtu) of the cylinder6 output", "writeHexMesh(.vtu) of generateCylinder(6, 8, 8, 1, 1)",
         false, {}},
    };
    return defs;
}

const CaseDef* findCase(const std::string& name) {
    for (const auto& d : caseDefs())
        if (d.name == name) return &d;
    return nullptr;
}

/// One measurement, as sent from the child to the parent and printed.
struct Result {
    std::string name;          ///< case name
    int threads = 0;           ///< requested thread count (0 = all)
    std::string status = "ok"; ///< "ok", "skipped", "refused", "error", "crashed", "timeout"
    std::string message;       ///< reason for a status other than ok
    std::string input;         ///< what the input was
    std::map<std::string, double> num;  ///< numeric fields (see kNumericFields)
};

/// Numeric fields in output order.
const char* const kNumericFields[] = {
    "threads_used", "tets", "input_vertices", "expected_hexes", "hexes", "vertices", "non_hex_cells",
    "flipped_tets", "degenerate_tets", "valid_all_hex", "file_mb",
    "adjacency_s", "preprocess_s", "vertices_s", "darts_s", "connect_s", "postprocess_s", "assemble_s",
    "total_s", "read_s", "input_rss_mb", "peak_rss_mb", "tets_per_s", "hexes_per_s",
    "write_binary_s", "write_compressed_s", "write_ascii_s", "binary_mb", "compressed_mb", "ascii_mb",
    "cpu_s", "arcs_s", "arc_edges", "failed_arcs", "failed_patches",
};

/// Replaces tabs and line breaks so that @p s fits in one field of a result line.
std::string oneLine(std::string s) {
    for (char& c : s)
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    return s;
}

/// Serializes @p r as one tab-separated line of key=value fields.
std::string encode(const Result& r) {
    std::ostringstream os;
    os.precision(17);
    os << "status=" << oneLine(r.status) << "\tmessage=" << oneLine(r.message) << "\tinput=" << oneLine(r.input);
    for (const auto& kv : r.num) os << '\t' << kv.first << '=' << kv.second;
    os << '\n';
    return os.str();
}

/// Parses a line written by encode() into @p r (name and threads are kept).
void decode(const std::string& line, Result& r) {
    std::istringstream is(line);
    std::string field;
    while (std::getline(is, field, '\t')) {
        const auto eq = field.find('=');
        if (eq == std::string::npos) continue;
        const std::string key = field.substr(0, eq), value = field.substr(eq + 1);
        if (key == "status") r.status = value;
        else if (key == "message") r.message = value;
        else if (key == "input") r.input = value;
        else r.num[key] = std::strtod(value.c_str(), nullptr);
    }
}

/// Decompresses @p path with `xz -dc` into memory.
std::string readXz(const std::string& path) {
    const std::string cmd = "xz -dc '" + path + "'";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run: " + cmd);
    std::string data;
    char buf[1 << 16];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) data.append(buf, n);
    const int rc = pclose(pipe);
    if (rc != 0) throw std::runtime_error(cmd + " failed (status " + std::to_string(rc) + ")");
    return data;
}

bool fileExists(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
}

/// Path of the real input file of @p def (empty if the case is generated).
std::string dataFile(const CaseDef& def, const Options& opt) {
    if (def.name.rfind("sphere_", 0) == 0 || def.name.rfind("needle_", 0) == 0) return opt.data_dir + "/sphere.hexex";
    if (def.name != "s1x2") return {};
    return opt.data_dir + "/" + (opt.quick ? def.quick : def.description);
}

/// Cube sizes (n, s) of a cube-based case.
std::pair<int, int> cubeSize(const std::string& name, bool quick) {
    if (name == "cube20" || name == "read_cube20") return quick ? std::make_pair(10, 5) : std::make_pair(40, 20);
    if (name == "cube30") return quick ? std::make_pair(12, 6) : std::make_pair(60, 30);
    if (name == "cube40") return quick ? std::make_pair(16, 8) : std::make_pair(80, 40);
    if (name == "perturbed") return quick ? std::make_pair(8, 4) : std::make_pair(24, 12);
    throw std::logic_error("not a cube case: " + name);
}

/// Builds the input of an extraction case (without timing); sets expected_hexes when known.
HexEx::ParametrizedTetMesh buildInput(const CaseDef& def, const Options& opt, Result& r) {
    r.input = opt.quick ? def.quick : def.description;
    if (def.name == "cylinder6" || def.name == "write_cylinder6") {
        const int R = opt.quick ? 8 : 64;
        r.num["expected_hexes"] = 6.0 * R * R * R;
        return HexEx::generateCylinder(6, R, R, 1, 1);
    }
    if (def.name.rfind("sphere_", 0) == 0) {
        // One corrupted number: a needle tet; the majority vote of the sanitization repairs
        // it (see Documentation/performance.md, "One bad parameter").
        HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(dataFile(def, opt));
        pm.params[10][2][1] = def.name == "sphere_1e5" ? (opt.quick ? 1e3 : 1e5) : (opt.quick ? 1e4 : 1e6);
        r.num["expected_hexes"] = 216;
        return pm;
    }
    if (def.name.rfind("needle_", 0) == 0) {
        // The interior vertex moved consistently in all its tets: a fold that cancels
        // (216 hexes) but whose darts cost time and memory in proportion to its volume.
        HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(dataFile(def, opt));
        const double shift = def.name == "needle_1e4" ? (opt.quick ? 1e2 : 1e4) : (opt.quick ? 1e3 : 1e5);
        for (std::size_t c = 0; c < pm.params.size(); ++c)
            for (int k = 0; k < 4; ++k)
                if (pm.mesh.cell_vertex(HexEx::CellHandle(static_cast<int>(c)), k).idx() == 40) pm.params[c][k][1] += shift;
        r.num["expected_hexes"] = 216;
        return pm;
    }
    if (def.name == "s1x2") {
        const std::string path = dataFile(def, opt);
        r.input = path;
        r.num["expected_hexes"] = opt.quick ? 10288 : 84347;  // parametric volume (data/README.md)
        return HexEx::readHexExBuffer(readXz(path), path);
    }
    const auto [n, s] = cubeSize(def.name, opt.quick);
    r.num["expected_hexes"] = static_cast<double>(s) * s * s;
    HexEx::ParametrizedTetMesh pm = HexEx::generateCube(n, s);
    if (def.name == "perturbed") HexEx::perturbParameters(pm, 1.0, 1);
    return pm;
}

/// A copy of the vertices and cells of @p m without adjacency.
HexEx::TetMesh bareCopy(const HexEx::TetMesh& m) {
    HexEx::TetMesh copy;
    copy.reserve(m.n_vertices(), m.n_cells());
    for (std::size_t v = 0; v < m.n_vertices(); ++v)
        copy.add_vertex(m.position(HexEx::VertexHandle(static_cast<int>(v))));
    for (std::size_t c = 0; c < m.n_cells(); ++c) copy.add_cell(m.cell_vertices(HexEx::CellHandle(static_cast<int>(c))));
    return copy;
}

/// Runs one extraction measurement in the current (child) process.
void measureExtraction(const CaseDef& def, const Options& opt, int threads, Result& r) {
    HexEx::ParametrizedTetMesh pm = buildInput(def, opt, r);
    // Time the adjacency on a mesh that has none (readers and perturbParameters build it).
    if (pm.mesh.has_adjacency()) pm.mesh = bareCopy(pm.mesh);
    auto t0 = Clock::now();
    pm.mesh.build_adjacency();
    r.num["adjacency_s"] = secondsSince(t0);
    r.num["input_rss_mb"] = procStatusKb("VmRSS") / 1024.0;

    HexEx::HexMesh out;
    HexEx::HexArcs arcs;
    HexEx::ExtractionOptions eo;
    eo.threads = threads;
    if (opt.arcs) eo.arcs = &arcs;
    eo.max_memory = opt.max_memory;
    t0 = Clock::now();
    const std::clock_t c0 = std::clock();
    HexEx::ExtractionReport rep;
    try {
        rep = HexEx::extractHexMesh(pm, out, eo);
    } catch (const HexEx::ResourceError& e) {
        r.num["total_s"] = secondsSince(t0);
        r.num["peak_rss_mb"] = procStatusKb("VmHWM") / 1024.0;
        r.status = "refused";
        r.message = e.what();
        return;
    }
    const double total = secondsSince(t0);
    // Processor time of all threads (steadier than wall time on a shared machine).
    r.num["cpu_s"] = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    r.num["peak_rss_mb"] = procStatusKb("VmHWM") / 1024.0;

    r.num["threads_used"] = rep.threads;
    r.num["tets"] = static_cast<double>(pm.mesh.n_cells());
    r.num["input_vertices"] = static_cast<double>(pm.mesh.n_vertices());
    r.num["hexes"] = static_cast<double>(out.hexes.size());
    r.num["vertices"] = static_cast<double>(out.vertices.size());
    r.num["non_hex_cells"] = static_cast<double>(out.polyhedra.size());
    r.num["flipped_tets"] = static_cast<double>(rep.input.flipped_tets);
    r.num["degenerate_tets"] = static_cast<double>(rep.input.degenerate_tets);
    r.num["valid_all_hex"] = rep.valid_all_hex ? 1 : 0;
    r.num["preprocess_s"] = rep.timings_s.preprocess;
    r.num["vertices_s"] = rep.timings_s.vertices;
    r.num["darts_s"] = rep.timings_s.darts;
    r.num["connect_s"] = rep.timings_s.connect;
    r.num["postprocess_s"] = rep.timings_s.postprocess;
    r.num["assemble_s"] = rep.timings_s.assemble;
    if (opt.arcs) {
        r.num["arcs_s"] = rep.timings_s.arcs;
        r.num["arc_edges"] = static_cast<double>(rep.arcs.edges);
        r.num["failed_arcs"] = static_cast<double>(rep.arcs.failed_edges);
        r.num["failed_patches"] = static_cast<double>(rep.arcs.failed_faces);
    }
    r.num["total_s"] = total;
    r.num["tets_per_s"] = total > 0 ? static_cast<double>(pm.mesh.n_cells()) / total : 0;
    r.num["hexes_per_s"] = total > 0 ? static_cast<double>(out.hexes.size()) / total : 0;
    if (def.name != "write_cylinder6") return;
    // Writing the output: each .vtu encoding into a temporary file (time includes the disk write).
    const char* tmpDir = std::getenv("TMPDIR");
    const std::string path = std::string(tmpDir && *tmpDir ? tmpDir : "/tmp") + "/hexex_bench_write_" +
                             std::to_string(static_cast<long>(getpid())) + ".vtu";
    for (const char* enc : {"binary", "compressed", "ascii"}) {
        const auto w0 = Clock::now();
        HexEx::writeHexMesh(path, out, HexEx::vtuEncodingFromName(enc));
        r.num[std::string("write_") + enc + "_s"] = secondsSince(w0);
        struct stat st;
        if (::stat(path.c_str(), &st) == 0) r.num[std::string(enc) + "_mb"] = static_cast<double>(st.st_size) / 1e6;
    }
    std::remove(path.c_str());
}

/// Runs the read measurement of @p path (written beforehand) in the current (child) process.
void measureRead(const CaseDef& def, const Options& opt, const std::string& path, Result& r) {
    r.input = opt.quick ? def.quick : def.description;
    struct stat st;
    if (::stat(path.c_str(), &st) == 0) r.num["file_mb"] = static_cast<double>(st.st_size) / 1e6;
    const auto t0 = Clock::now();
    const HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(path);
    const double total = secondsSince(t0);
    r.num["peak_rss_mb"] = procStatusKb("VmHWM") / 1024.0;
    // Large files are parsed and their adjacency built on all hardware threads.
    r.num["threads_used"] = HexEx::resolveThreadCount(0);
    r.num["tets"] = static_cast<double>(pm.mesh.n_cells());
    r.num["input_vertices"] = static_cast<double>(pm.mesh.n_vertices());
    r.num["read_s"] = total;
    r.num["total_s"] = total;
    r.num["tets_per_s"] = total > 0 ? static_cast<double>(pm.mesh.n_cells()) / total : 0;
}

/// Runs @p work in a forked child; collects its result line. The result's name and
/// threads are set by the caller; status reflects crashes and timeouts.
void runInChild(const std::function<void(Result&)>& work, double timeout_s, Result& r) {
    int fds[2];
    if (pipe(fds) != 0) {
        r.status = "error";
        r.message = std::string("pipe: ") + std::strerror(errno);
        return;
    }
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) {
        r.status = "error";
        r.message = std::string("fork: ") + std::strerror(errno);
        close(fds[0]);
        close(fds[1]);
        return;
    }
    if (pid == 0) {  // child
        close(fds[0]);
        resetPeakRss();
        Result cr = r;
        try {
            work(cr);
        } catch (const std::exception& e) {
            cr.status = "error";
            cr.message = e.what();
        }
        const std::string line = encode(cr);
        std::size_t off = 0;
        while (off < line.size()) {
            const ssize_t w = write(fds[1], line.data() + off, line.size() - off);
            if (w <= 0) break;
            off += static_cast<std::size_t>(w);
        }
        close(fds[1]);
        std::fflush(stdout);
        _exit(0);
    }
    close(fds[1]);
    std::string data;
    bool timedOut = false;
    const auto start = Clock::now();
    char buf[4096];
    for (;;) {
        int waitMs = -1;
        if (timeout_s > 0) {
            const double left = timeout_s - secondsSince(start);
            if (left <= 0) {
                timedOut = true;
                kill(pid, SIGKILL);
                break;
            }
            waitMs = static_cast<int>(std::ceil(left * 1000));
        }
        pollfd pfd{fds[0], POLLIN, 0};
        const int pr = poll(&pfd, 1, waitMs);
        if (pr < 0 && errno == EINTR) continue;
        if (pr == 0) continue;  // deadline check at the top of the loop
        const ssize_t n = read(fds[0], buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        data.append(buf, static_cast<std::size_t>(n));
    }
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut) {
        r.status = "timeout";
        char buf[64];
        std::snprintf(buf, sizeof buf, "killed after %g s (--timeout)", timeout_s);
        r.message = buf;
    } else if (!data.empty()) {
        decode(data, r);
    } else if (WIFSIGNALED(status)) {
        r.status = "crashed";
        r.message = std::string("child killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
                    strsignal(WTERMSIG(status)) + (WTERMSIG(status) == SIGKILL ? "; out of memory?" : "") + ")";
    } else {
        r.status = "crashed";
        r.message = "child exited with status " + std::to_string(WEXITSTATUS(status)) + " without a result";
    }
}

/// Runs every requested case at every thread count.
std::vector<Result> runAll(const Options& opt) {
    std::vector<Result> results;
    for (const std::string& name : opt.cases) {
        const CaseDef& def = *findCase(name);
        if (def.is_read) {
            Result r;
            r.name = name;
            r.threads = 1;
            const char* tmpDir = std::getenv("TMPDIR");
            std::string tmpl = std::string(tmpDir && *tmpDir ? tmpDir : "/tmp") + "/hexex_bench_XXXXXX.hexex";
            const int fd = mkstemps(tmpl.data(), 6);
            if (fd < 0) {
                r.status = "error";
                r.message = std::string("mkstemp: ") + std::strerror(errno);
                results.push_back(r);
                continue;
            }
            close(fd);
            const std::string path = tmpl;
            std::fprintf(stderr, "[%s] writing %s ...\n", name.c_str(), path.c_str());
            Result w = r;
            runInChild(
                [&](Result& cr) {
                    const auto [n, s] = cubeSize(name, opt.quick);
                    HexEx::writeHexExFile(path, HexEx::generateCube(n, s));
                    cr.status = "ok";
                },
                0, w);
            if (w.status != "ok") {
                r.status = w.status;
                r.message = "writing the input failed: " + w.message;
            } else {
                std::fprintf(stderr, "[%s] reading ...\n", name.c_str());
                runInChild([&](Result& cr) { measureRead(def, opt, path, cr); }, opt.timeout_s, r);
            }
            std::remove(path.c_str());
            results.push_back(r);
            continue;
        }
        const std::string file = dataFile(def, opt);
        for (int t : opt.threads) {
            Result r;
            r.name = name;
            r.threads = t;
            if (!file.empty() && !fileExists(file)) {
                r.status = "skipped";
                r.message = "input file not found: " + file;
                r.input = file;
                std::fprintf(stderr, "[%s] skipped: %s\n", name.c_str(), r.message.c_str());
                results.push_back(r);
                break;  // same reason for every thread count
            }
            std::fprintf(stderr, "[%s] threads=%d ...\n", name.c_str(), t);
            runInChild([&](Result& cr) { measureExtraction(def, opt, t, cr); }, opt.timeout_s, r);
            if (r.status != "ok") std::fprintf(stderr, "[%s] %s: %s\n", name.c_str(), r.status.c_str(), r.message.c_str());
            results.push_back(r);
        }
    }
    return results;
}

/// Formats a number of seconds (or "-" if absent).
std::string fmtNum(const Result& r, const char* key, const char* fmt) {
    const auto it = r.num.find(key);
    if (it == r.num.end()) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, it->second);
    return buf;
}

/// Formats a count with thousands separators.
std::string fmtCount(double v) {
    std::string digits = std::to_string(static_cast<long long>(std::llround(v)));
    std::string out;
    const bool neg = !digits.empty() && digits[0] == '-';
    if (neg) digits.erase(0, 1);
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return neg ? "-" + out : out;
}

std::string fmtCountField(const Result& r, const char* key) {
    const auto it = r.num.find(key);
    return it == r.num.end() ? "-" : fmtCount(it->second);
}

std::string fmtRate(const Result& r, const char* key) {
    const auto it = r.num.find(key);
    if (it == r.num.end() || it->second <= 0) return "-";
    char buf[32];
    if (it->second >= 1e6) std::snprintf(buf, sizeof buf, "%.2fM", it->second / 1e6);
    else if (it->second >= 1e3) std::snprintf(buf, sizeof buf, "%.1fk", it->second / 1e3);
    else std::snprintf(buf, sizeof buf, "%.0f", it->second);
    return buf;
}

std::string fmtOptSeconds(double v) {
    if (std::isnan(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

/// Prints the results table and the reference table.
void printTables(const Options& opt, const std::vector<Result>& results) {
    std::printf("\nHexEx %s extraction benchmark%s, %u hardware threads\n", HexEx::version(),
                opt.quick ? " (--quick: small inputs, not comparable with the reference)" : "",
                std::thread::hardware_concurrency());
    std::printf("%-11s %3s %10s %9s %9s %9s %5s %7s %7s %7s %7s %7s %7s %7s %8s %8s %8s %8s\n", "case", "thr",
                "tets", "exp.hex", "hexes", "vertices", "valid", "adj", "pre", "verts", "darts", "connect", "post",
                "asm", "total_s", "peakMB", "tets/s", "hexes/s");
    for (const Result& r : results) {
        if (r.status == "refused") {
            std::printf("%-11s %3d  refused after %s s, peak %s MB: %s\n", r.name.c_str(), r.threads,
                        fmtNum(r, "total_s", "%.3f").c_str(), fmtNum(r, "peak_rss_mb", "%.0f").c_str(), r.message.c_str());
            continue;
        }
        if (r.status != "ok") {
            std::printf("%-11s %3d  %s: %s\n", r.name.c_str(), r.threads, r.status.c_str(), r.message.c_str());
            continue;
        }
        const auto valid = r.num.find("valid_all_hex");
        std::printf("%-11s %3s %10s %9s %9s %9s %5s %7s %7s %7s %7s %7s %7s %7s %8s %8s %8s %8s\n", r.name.c_str(),
                    fmtNum(r, "threads_used", "%.0f").c_str(), fmtCountField(r, "tets").c_str(),
                    fmtCountField(r, "expected_hexes").c_str(), fmtCountField(r, "hexes").c_str(),
                    fmtCountField(r, "vertices").c_str(),
                    valid == r.num.end() ? "-" : (valid->second != 0 ? "yes" : "NO"),
                    fmtNum(r, "adjacency_s", "%.3f").c_str(), fmtNum(r, "preprocess_s", "%.3f").c_str(),
                    fmtNum(r, "vertices_s", "%.3f").c_str(), fmtNum(r, "darts_s", "%.3f").c_str(),
                    fmtNum(r, "connect_s", "%.3f").c_str(), fmtNum(r, "postprocess_s", "%.3f").c_str(),
                    fmtNum(r, "assemble_s", "%.3f").c_str(), fmtNum(r, "total_s", "%.3f").c_str(),
                    fmtNum(r, "peak_rss_mb", "%.0f").c_str(), fmtRate(r, "tets_per_s").c_str(),
                    fmtRate(r, "hexes_per_s").c_str());
        if (r.name == "write_cylinder6")
            std::printf("%-11s     (.vtu write: binary %s s / %s MB, compressed %s s / %s MB, ascii %s s / %s MB)\n", "",
                        fmtNum(r, "write_binary_s", "%.3f").c_str(), fmtNum(r, "binary_mb", "%.0f").c_str(),
                        fmtNum(r, "write_compressed_s", "%.3f").c_str(), fmtNum(r, "compressed_mb", "%.0f").c_str(),
                        fmtNum(r, "write_ascii_s", "%.3f").c_str(), fmtNum(r, "ascii_mb", "%.0f").c_str());
        if (r.name == "read_cube20")
            std::printf("%-11s     (readHexExFile of a %s MB file, adjacency included; total = read time)\n", "",
                        fmtNum(r, "file_mb", "%.1f").c_str());
    }
    std::printf("\nPublished reference (full-size inputs):\n");
    std::printf("%-11s %10s %10s %10s %12s %12s  %-22s %s\n", "case", "tets", "hexes", "HexEx_s", "HexHex_1t_s",
                "HexHex_2t_s", "memory", "note");
    for (const std::string& name : opt.cases) {
        const Reference& ref = findCase(name)->ref;
        if (ref.tets == 0) continue;
        std::printf("%-11s %10s %10s %10s %12s %12s  %-22s %s\n", name.c_str(), fmtCount(static_cast<double>(ref.tets)).c_str(),
                    ref.hexes ? fmtCount(static_cast<double>(ref.hexes)).c_str() : "-", fmtOptSeconds(ref.hexex_s).c_str(),
                    fmtOptSeconds(ref.hexhex_1t_s).c_str(), fmtOptSeconds(ref.hexhex_2t_s).c_str(),
                    ref.memory.empty() ? "-" : ref.memory.c_str(), ref.note.c_str());
    }
}

/// Escapes @p s as a JSON string literal.
std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        case '\r': out += "\\r"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

/// A double as a JSON number (null if not finite).
std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

/// Writes all results and the reference numbers as JSON to @p path.
bool writeJson(const Options& opt, const std::vector<Result>& results, const std::string& path) {
    std::ofstream out(path);
    if (!out) return false;
    out << "{\n  \"program\": \"extraction_benchmark\",\n  \"version\": " << jsonString(HexEx::version())
        << ",\n  \"quick\": " << (opt.quick ? "true" : "false")
        << ",\n  \"hardware_threads\": " << std::thread::hardware_concurrency() << ",\n  \"results\": [";
    for (std::size_t i = 0; i < results.size(); ++i) {
        const Result& r = results[i];
        out << (i ? "," : "") << "\n    {\"case\": " << jsonString(r.name) << ", \"threads\": " << r.threads
            << ", \"status\": " << jsonString(r.status) << ", \"message\": " << jsonString(r.message)
            << ", \"input\": " << jsonString(r.input);
        for (const char* key : kNumericFields) {
            const auto it = r.num.find(key);
            if (it == r.num.end()) continue;
            if (std::strcmp(key, "valid_all_hex") == 0) out << ", \"valid_all_hex\": " << (it->second != 0 ? "true" : "false");
            else out << ", " << jsonString(key) << ": " << jsonNumber(it->second);
        }
        out << "}";
    }
    out << "\n  ],\n  \"reference\": [";
    bool first = true;
    for (const CaseDef& def : caseDefs()) {
        const Reference& ref = def.ref;
        if (ref.tets == 0) continue;
        out << (first ? "" : ",") << "\n    {\"case\": " << jsonString(def.name) << ", \"tets\": " << ref.tets
            << ", \"hexes\": " << ref.hexes << ", \"hexex_s\": " << jsonNumber(ref.hexex_s)
            << ", \"hexhex_1t_s\": " << jsonNumber(ref.hexhex_1t_s) << ", \"hexhex_2t_s\": " << jsonNumber(ref.hexhex_2t_s)
            << ", \"memory\": " << jsonString(ref.memory) << ", \"note\": " << jsonString(ref.note) << "}";
        first = false;
    }
    out << "\n  ]\n}\n";
    return static_cast<bool>(out);
}

const char* const kUsage =
    "usage: extraction_benchmark [--case NAME]... [--threads 1,2] [--json OUT.json]\n"
    "                            [--data-dir DIR] [--quick] [--timeout SECONDS] [--max-memory SIZE] [--arcs] [--list]\n"
    "  --case NAME      run only this case (repeatable; default: all, see --list)\n"
    "  --threads LIST   comma-separated thread counts, 0 = all hardware threads (default 1,2)\n"
    "  --json FILE      also write the results and the reference numbers as JSON\n"
    "  --data-dir DIR   directory of the real inputs (default <repo>/../shared/data)\n"
    "  --quick          small inputs: a smoke test that runs in seconds\n"
    "  --timeout S      kill a measurement after S seconds (default: no limit)\n"
    "  --arcs           also compute the edge arcs and face patches (ExtractionOptions::arcs)\n"
    "  --max-memory SZ  memory budget of every extraction, e.g. 2G (default: the library's,\n"
    "                   half of the available memory); a refusal is the status 'refused'\n"
    "  --list           list the cases and exit\n";

/// Parses "1,2,4" into thread counts; throws std::invalid_argument.
std::vector<int> parseThreads(const std::string& s) {
    std::vector<int> out;
    std::istringstream is(s);
    std::string item;
    while (std::getline(is, item, ',')) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || v < 0 || v > 4096) throw std::invalid_argument("bad thread count '" + item + "'");
        out.push_back(static_cast<int>(v));
    }
    if (out.empty()) throw std::invalid_argument("empty thread list");
    return out;
}

} // namespace

int main(int argc, char** argv) {
    Options opt;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
                return argv[++i];
            };
            if (a == "--case") {
                const std::string name = value();
                if (!findCase(name)) throw std::invalid_argument("unknown case '" + name + "' (see --list)");
                opt.cases.push_back(name);
            } else if (a == "--threads") {
                opt.threads = parseThreads(value());
            } else if (a == "--json") {
                opt.json = value();
            } else if (a == "--data-dir") {
                opt.data_dir = value();
            } else if (a == "--quick") {
                opt.quick = true;
            } else if (a == "--arcs") {
                opt.arcs = true;
            } else if (a == "--timeout") {
                const std::string v = value();
                char* end = nullptr;
                opt.timeout_s = std::strtod(v.c_str(), &end);
                if (v.empty() || *end != '\0' || !(opt.timeout_s > 0)) throw std::invalid_argument("bad timeout '" + v + "'");
            } else if (a == "--max-memory") {
                opt.max_memory = HexEx::parseByteSize(value());
            } else if (a == "--list") {
                for (const CaseDef& d : caseDefs())
                    std::printf("%-11s %s   (quick: %s)\n", d.name.c_str(), d.description.c_str(), d.quick.c_str());
                return 0;
            } else if (a == "-h" || a == "--help") {
                std::fputs(kUsage, stdout);
                return 0;
            } else {
                throw std::invalid_argument("unknown argument '" + a + "'");
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "extraction_benchmark: %s\n%s", e.what(), kUsage);
        return 2;
    }
    if (opt.cases.empty())
        for (const CaseDef& d : caseDefs()) opt.cases.push_back(d.name);

    const std::vector<Result> results = runAll(opt);
    printTables(opt, results);
    if (!opt.json.empty()) {
        if (!writeJson(opt, results, opt.json)) {
            std::fprintf(stderr, "extraction_benchmark: cannot write %s\n", opt.json.c_str());
            return 1;
        }
        std::printf("\nJSON written to %s\n", opt.json.c_str());
    }
    for (const Result& r : results)
        if (r.status != "ok" && r.status != "skipped" && r.status != "refused") return 1;
    return 0;
}
