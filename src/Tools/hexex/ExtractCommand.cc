/// @file ExtractCommand.cc
/// `hexex extract IN -o OUT [options]`: extract the hex mesh of a .hexex, .ovm or .ovmb tet
/// mesh with its integer-grid map, write it (.vtu, .vtk, .ovm, .ovmb, .mesh) and optionally a JSON report,
/// the singular edges, the tet mesh in parameter space and the boundary surface.

#include "ArgParser.hh"
#include "Commands.hh"
#include "OptimizeOutput.hh"
#include "UntangleOutput.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Core/Memory.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/ArcWriters.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/TetMeshInput.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/ReportJson.hh>
#include <HexEx/Mesh/BoundarySurface.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Mesh/HexProvenance.hh>
#include <HexEx/Predicates/ExactPredicates.hh>
#include <HexEx/Preprocessing/SingularityGraph.hh>
#include <HexEx/Preprocessing/Transitions.hh>
#include <HexEx/Untangling/TriangleSurface.hh>
#include <HexEx/Untangling/HexOptimizer.hh>
#include <HexEx/Untangling/Untangler.hh>
#include <HexEx/Untangling/UntangleWithRepair.hh>

#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <utility>
#include <sstream>
#include <stdexcept>
#include <string>

namespace HexExTool {

namespace {

const char* kExtractUsage =
    "usage: hexex extract IN.hexex|IN.ovm|IN.ovmb -o OUT [options]\n"
    "  -o, --output OUT        hex mesh to write; format by extension: .vtu .vtk .ovm .ovmb .mesh\n"
    "  --encoding E            .vtu data: binary (default), compressed (zlib) or ascii\n"
    "  --report R.json         write the extraction report as JSON ('-' for stdout)\n"
    "  --threads N             worker threads (0 = all hardware threads, default); output is identical\n"
    "  --epsilon E             snap parameters this close to an integer (default 1e-6)\n"
    "  --no-merge              keep regular/anti dart pairs (skip annihilation and vertex merging)\n"
    "  --full-annihilation     extract and annihilate the darts of fold points that cancel out\n"
    "                          instead of skipping them (slower; may pick other fold copies)\n"
    "  --no-annihilation-retries  keep the first annihilation order even where it leaves broken\n"
    "                          hex cells (by default other orders are tried there)\n"
    "  --max-memory SIZE       memory budget, e.g. 2G, 500M (default: half of the available memory);\n"
    "                          maps that would need more are refused at once with the likely cause\n"
    "  --singularities S.vtk   write the singular edges of the input as legacy VTK lines\n"
    "  --param-mesh P.vtk      write the tet mesh in parameter space (4 points per tet, each in\n"
    "                          its own chart) as legacy VTK with cell data 'flipped', 'degenerate'\n"
    "  --surface B.obj|.off|.ply|.stl  write the boundary surface of the hex mesh (OpenMesh IO)\n"
    "  --edge-arcs A.vtu       write the exact image of every hex edge in the input as VTK polylines\n"
    "                          (cell data edge_id, vertex0, vertex1)\n"
    "  --face-patches P.vtu    write the exact image of every hex face as VTK triangles (cell data face_id)\n"
    "  --provenance P.csv      write per hex its source tet and integer grid cell (CSV: hex,tet,i,j,k;\n"
    "                          the cell is [i,i+1]x[j,j+1]x[k,k+1] in the tet's chart); not with\n"
    "                          --pillow, and --untangle then keeps the hexes as extracted (--no-pillow)\n"
    "  --untangle              move vertices so that no hex is inverted (folded maps), boundary\n"
    "                          vertices on the input's boundary surface; prints a report\n"
    "  --optimize              then raise the worst scaled Jacobian (implies --untangle; boundary\n"
    "                          vertices on the input's boundary surface, its feature curves and\n"
    "                          corners kept, every hex certified valid); prints a report\n"
    "  --target SJ             with --optimize: stop once the worst scaled Jacobian reaches SJ (default 0.9)\n"
    "  --pillow                before optimising, insert a layer of hexes along the boundary (one per\n"
    "                          boundary quad; patches with flat corners along feature curves get a strip\n"
    "                          of quads instead; implies --optimize; needs an all-hex result).\n"
    "                          Without it, --untangle takes this path only if untangling alone\n"
    "                          leaves hexes certified invalid (the report says so)\n"
    "  --no-pillow             never insert the layer: --untangle keeps the hexes as extracted,\n"
    "                          even if some stay invalid\n"
    "  -q, --quiet             print nothing but errors\n"
    "IN is read as OpenVolumeMesh if it ends in .ovm or .ovmb, as .hexex otherwise;\n"
    "it may be '-' for standard input (.hexex).\n"
    "exit status: 0 all-hex mesh written, 3 written but not all-hex (or --untangle left inverted hexes),\n"
    "2 bad input or usage\n";

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Phase/percentage display on standard error: one line updated in place on a terminal,
/// one line per update otherwise. The percentage is overall progress: each stage of the
/// pipeline (kPhases) counts equally, and the extractor's fraction moves within its stage.
class ProgressDisplay {
public:
    ProgressDisplay(bool enabled, bool tty) : enabled_(enabled), tty_(tty) {}
    ~ProgressDisplay() { finish(); }
    void update(const std::string& phase, double fraction) {
        if (!enabled_ || phase == "done") return;
        static const char* kPhases[] = {"preprocess", "darts", "connect", "postprocess", "vertices", "assemble", "write"};
        constexpr int n = static_cast<int>(sizeof kPhases / sizeof kPhases[0]);
        int k = 0;
        while (k < n && phase != kPhases[k]) ++k;
        if (k == n) k = last_index_;  // unknown phase name: keep the overall position
        const double f = std::isfinite(fraction) ? std::min(1.0, std::max(0.0, fraction)) : 0.0;
        const int pct = static_cast<int>(std::lround(100.0 * (k + f) / n));
        if (phase == last_phase_ && pct == last_pct_) return;
        last_phase_ = phase;
        last_pct_ = pct;
        last_index_ = k;
        std::ostringstream s;
        s << "hexex extract: [" << std::setw(3) << pct << "%] " << phase;
        if (tty_) {
            std::cerr << "\r" << std::left << std::setw(40) << s.str() << std::right << std::flush;
            open_line_ = true;
        } else {
            std::cerr << s.str() << "\n";
        }
    }
    void finish() {
        if (open_line_) std::cerr << "\n" << std::flush;
        open_line_ = false;
    }

private:
    bool enabled_, tty_;
    bool open_line_ = false;
    std::string last_phase_;
    int last_pct_ = -1;
    int last_index_ = 0;
};

/// The tet mesh in parameter space as legacy VTK: every tet gets its own four points (the
/// corner parameters in its chart), with cell data flipped/degenerate (exact orientation)
/// and the input vertex index as point data.
void writeParamMeshVtk(const std::string& path, const HexEx::ParametrizedTetMesh& pm) {
    std::ofstream out(path);
    if (!out) throw HexEx::InputError(path + ": cannot open for writing");
    const std::size_t n = pm.params.size();
    out << std::setprecision(17);
    out << "# vtk DataFile Version 3.0\nhexex parameter-space tet mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << 4 * n << " double\n";
    for (const auto& t : pm.params)
        for (const auto& p : t) out << p[0] << " " << p[1] << " " << p[2] << "\n";
    out << "CELLS " << n << " " << 5 * n << "\n";
    for (std::size_t c = 0; c < n; ++c)
        out << "4 " << 4 * c << " " << 4 * c + 1 << " " << 4 * c + 2 << " " << 4 * c + 3 << "\n";
    out << "CELL_TYPES " << n << "\n";
    for (std::size_t c = 0; c < n; ++c) out << "10\n";
    out << "CELL_DATA " << n << "\nSCALARS flipped int 1\nLOOKUP_TABLE default\n";
    std::vector<int> sign(n);
    for (std::size_t c = 0; c < n; ++c) {
        const auto& p = pm.params[c];
        sign[c] = HexEx::orient3d(p[0], p[1], p[2], p[3]);
        out << (sign[c] < 0 ? 1 : 0) << "\n";
    }
    out << "SCALARS degenerate int 1\nLOOKUP_TABLE default\n";
    for (std::size_t c = 0; c < n; ++c) out << (sign[c] == 0 ? 1 : 0) << "\n";
    out << "POINT_DATA " << 4 * n << "\nSCALARS vertex_id int 1\nLOOKUP_TABLE default\n";
    for (std::size_t c = 0; c < n; ++c)
        for (int i = 0; i < 4; ++i) out << pm.mesh.cell_vertex(HexEx::CellHandle(static_cast<int>(c)), i).idx() << "\n";
    out.flush();
    if (!out) throw HexEx::InputError(path + ": write failed");
}

/// Per hex its source tet and integer grid cell (HexProvenance) as CSV lines
/// `hex,tet,i,j,k` after a header line; throws InputError if the file cannot be written.
void writeProvenanceCsv(const std::string& path, const HexEx::HexProvenance& prov) {
    std::ofstream out(path);
    if (!out) throw HexEx::InputError(path + ": cannot open for writing");
    out << "hex,tet,i,j,k\n";
    for (std::size_t h = 0; h < prov.hex_source_tet.size(); ++h) {
        const std::array<int, 3>& c = prov.hex_grid_cell[h];
        out << h << ',' << prov.hex_source_tet[h] << ',' << c[0] << ',' << c[1] << ',' << c[2] << '\n';
    }
    out.flush();
    if (!out) throw HexEx::InputError(path + ": write failed");
}

/// Singular edges of the input (transitions inferred from the parameters), in 3D.
void writeSingularities(const std::string& path, const HexEx::ParametrizedTetMesh& pm, long* n_edges) {
    const HexEx::SingularityGraph g = HexEx::singularityGraph(pm);
    HexEx::writeSingularEdgesVtk(path, g.points, g.segments, g.valences);
    *n_edges = static_cast<long>(g.segments.size());
}

/// Drops what no writer can store (polyhedron faces with fewer than three vertices, cells
/// with a vertex index out of range) and returns how many faces and cells were dropped.
/// The extractor should never produce such cells; this keeps the tool writing its best mesh
/// if it does.
std::pair<long, long> dropUnwritableCells(HexEx::HexMesh& hm) {
    const long nv = static_cast<long>(hm.vertices.size());
    auto bad = [&](int v) { return v < 0 || v >= nv; };
    long faces = 0, cells = 0;
    std::vector<std::array<int, 8>> hexes;
    for (const auto& h : hm.hexes) {
        bool ok = true;
        for (const int v : h) ok = ok && !bad(v);
        if (ok) hexes.push_back(h);
        else ++cells;
    }
    hm.hexes.swap(hexes);
    std::vector<HexEx::Polyhedron> polys;
    for (auto& p : hm.polyhedra) {
        HexEx::Polyhedron q;
        for (auto& f : p.faces) {
            bool ok = f.size() >= 3;
            for (const int v : f) ok = ok && !bad(v);
            if (ok) q.faces.push_back(std::move(f));
            else ++faces;
        }
        if (q.faces.empty()) ++cells;
        else polys.push_back(std::move(q));
    }
    hm.polyhedra.swap(polys);
    return {faces, cells};
}

} // namespace

int runExtract(const Args& args) {
    const auto t_start = std::chrono::steady_clock::now();
    const std::vector<OptionSpec> spec = {
        {"--output", true, "-o"},   {"--report", true, ""},        {"--threads", true, ""},
        {"--epsilon", true, ""},    {"--no-merge", false, ""},     {"--quiet", false, "-q"},
        {"--singularities", true, ""}, {"--param-mesh", true, ""}, {"--surface", true, ""},
        {"--encoding", true, ""},         {"--max-memory", true, ""},      {"--full-annihilation", false, ""},
        {"--no-annihilation-retries", false, ""},
        {"--edge-arcs", true, ""},        {"--face-patches", true, ""},    {"--untangle", false, ""},
        {"--optimize", false, ""},        {"--target", true, ""},           {"--pillow", false, ""},
        {"--no-pillow", false, ""},       {"--provenance", true, ""},
    };
    std::string input, output, report_path, sing_path, param_path, surface_path, arcs_path, patches_path, provenance_path;
    HexEx::HexArcs arcs;
    HexEx::HexProvenance provenance;
    HexEx::ExtractionOptions opt;
    HexEx::VtuEncoding encoding = HexEx::VtuEncoding::Binary;
    bool quiet = false, untangle = false, optimize = false, pillow_fallback = true;
    HexEx::OptimizeOptions optimize_opt;
    try {
        const ParsedArgs pa = parseArgs(args, spec);
        if (pa.has("--help")) {
            std::cout << kExtractUsage;
            return 0;
        }
        if (pa.positional.empty()) throw UsageError("no input file given");
        if (pa.positional.size() > 1) throw UsageError("more than one input file given ('" + pa.positional[1] + "')");
        input = pa.positional[0];
        if (!pa.has("--output")) throw UsageError("no output file given (-o OUT.vtu|.vtk|.ovm|.ovmb|.mesh)");
        try {
            encoding = HexEx::vtuEncodingFromName(pa.get("--encoding", "binary"));
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--encoding: ") + e.what());
        }
        output = pa.get("--output");
        report_path = pa.get("--report");
        sing_path = pa.get("--singularities");
        param_path = pa.get("--param-mesh");
        arcs_path = pa.get("--edge-arcs");
        patches_path = pa.get("--face-patches");
        for (const std::string* p : {&arcs_path, &patches_path})
            if (!p->empty() && (p->size() < 4 || p->compare(p->size() - 4, 4, ".vtu") != 0))
                throw UsageError((p == &arcs_path ? "--edge-arcs" : "--face-patches") + std::string(": '") + *p +
                                 "' must end in .vtu");
        if (!arcs_path.empty() || !patches_path.empty()) opt.arcs = &arcs;
        opt.threads = static_cast<int>(pa.getInt("--threads", 0, 0, 4096));
        opt.epsilon = pa.getDouble("--epsilon", opt.epsilon, 0, 0.49);
        opt.merge = !pa.has("--no-merge");
        opt.cheap_folds = !pa.has("--full-annihilation");
        opt.annihilation_retries = !pa.has("--no-annihilation-retries");
        if (pa.has("--max-memory")) {
            try {
                opt.max_memory = HexEx::parseByteSize(pa.get("--max-memory"));
            } catch (const HexEx::InputError& e) {
                throw UsageError(std::string("--max-memory: ") + e.what());
            }
        }
        quiet = pa.has("--quiet");
        optimize = pa.has("--optimize") || pa.has("--pillow");
        optimize_opt.pillow = pa.has("--pillow");
        untangle = pa.has("--untangle") || optimize;
        if (pa.has("--pillow") && pa.has("--no-pillow")) throw UsageError("--pillow and --no-pillow exclude each other");
        pillow_fallback = !pa.has("--no-pillow");
        provenance_path = pa.get("--provenance");
        if (pa.has("--provenance")) {
            // The layer adds hexes of no source tet (and may remove some): the indices would not match.
            if (pa.has("--pillow"))
                throw UsageError("--provenance and --pillow exclude each other (the layer's hexes have no source tet)");
            pillow_fallback = false;
            opt.provenance = &provenance;
        }
        optimize_opt.target = pa.getDouble("--target", optimize_opt.target, -1, 1);
        surface_path = pa.get("--surface");
        if (pa.has("--surface") && !HexEx::isSurfaceMeshPath(surface_path))
            throw UsageError("--surface: unknown surface format '" + surface_path + "' (expected .obj, .off, .ply or .stl)");
        try {
            HexEx::hexMeshFormatFromPath(output);
        } catch (const HexEx::InputError& e) {
            throw UsageError(e.what());
        }
    } catch (const UsageError& e) {
        std::cerr << "hexex extract: " << e.what() << "\n" << kExtractUsage;
        return 2;
    }

    // Read.
    HexEx::ReadReport rr;
    HexEx::ParametrizedTetMesh pm;
    HexEx::ReportExtras extras;
    auto t0 = std::chrono::steady_clock::now();
    try {
        pm = HexEx::readParametrizedTetMesh(input, &rr);
    } catch (const HexEx::InputError& e) {
        std::cerr << "hexex extract: error: " << e.what() << "\n";
        return 2;
    }
    extras.read_s = secondsSince(t0);
    for (const auto& w : rr.warnings) {
        if (!quiet) std::cerr << "hexex extract: warning: " << w << "\n";
        extras.warnings.push_back(w);
    }

    // Optional inputs views.
    try {
        if (!param_path.empty()) writeParamMeshVtk(param_path, pm);
        if (!sing_path.empty()) {
            long n = 0;
            writeSingularities(sing_path, pm, &n);
            if (!quiet) std::cerr << "hexex extract: wrote " << n << " singular edges to " << sing_path << "\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "hexex extract: error: " << e.what() << "\n";
        return 2;
    }

    // Extract.
    ProgressDisplay progress(!quiet && pm.mesh.n_cells() > 100000, stderrIsTerminal());
    opt.progress = [&](const std::string& phase, double f) { progress.update(phase, f); };
    HexEx::HexMesh hm;
    HexEx::ExtractionReport rep;
    // The .ovm/.ovmb writers number the faces from the assembly's face neighbours (the same
    // bytes; the writer checks that the table is the one of the mesh it writes).
    const HexEx::HexMeshFormat outFormat = HexEx::hexMeshFormatFromPath(output);
    const bool ovmOut = outFormat == HexEx::HexMeshFormat::Ovm || outFormat == HexEx::HexMeshFormat::Ovmb;
    HexEx::HexFaceNeighbours neighbours;
    try {
        // The parameters are not needed afterwards (the untangler uses the tet mesh's boundary
        // only): the pipeline takes them over instead of copying them (96 bytes per tet).
        rep = HexEx::extractHexMesh(std::move(pm), hm, opt, ovmOut && !untangle ? &neighbours : nullptr);
    } catch (const HexEx::InputError& e) {
        progress.finish();
        std::cerr << "hexex extract: error: " << (input == "-" ? std::string("<stdin>") : input) << ": " << e.what()
                  << "\n";
        return 2;
    }
    const auto dropped = dropUnwritableCells(hm);
    if (dropped.first > 0 || dropped.second > 0) {
        rep.valid_all_hex = false;
        rep.warnings.push_back("dropped " + std::to_string(dropped.first) + " polyhedron faces with fewer than 3 "
                               "vertices and " + std::to_string(dropped.second) + " cells that could not be written");
    }
    extras.quality = HexEx::computeQuality(hm, opt.threads);
    HexEx::RepairReport repair;
    const HexEx::UntangleReport& untangle_rep = repair.untangle;
    const HexEx::OptimizeReport& optimize_rep = repair.optimize;
    if (untangle) {
        const HexEx::TriangleSurface input_boundary = HexEx::tetMeshBoundary(pm.mesh);
        HexEx::RepairOptions ro;
        ro.untangle.threads = opt.threads;
        ro.optimize = optimize_opt;
        ro.optimize.threads = opt.threads;
        ro.optimize_quality = optimize;
        ro.pillow = optimize_opt.pillow ? HexEx::PillowPolicy::Always
                                        : (pillow_fallback ? HexEx::PillowPolicy::IfNeeded : HexEx::PillowPolicy::Never);
        try {
            repair = HexEx::untangleWithRepair(hm, ro, &input_boundary);
        } catch (const std::invalid_argument& e) {
            progress.finish();
            std::cerr << "hexex extract: error: " << (optimize_opt.pillow ? "--pillow: " : "") << e.what() << "\n";
            return 2;
        }
        extras.untangle = &untangle_rep;
        if (!repair.note.empty()) {
            if (!quiet) std::cerr << "hexex extract: " << repair.note << "\n";
            extras.warnings.push_back(repair.note);
        }
        optimize = repair.optimized;
        if (optimize) extras.optimize = &optimize_rep;
        if (optimize && optimize_rep.pillowed_hexes > 0) {  // the written mesh has the layer
            rep.output.hexes = static_cast<long>(hm.hexes.size());
            rep.output.vertices = static_cast<long>(hm.vertices.size());
        }
        extras.quality = HexEx::computeQuality(hm, opt.threads);
    }

    // Write.
    progress.update("write", 0);
    t0 = std::chrono::steady_clock::now();
    // Runs one writer; its warnings go to stderr and the report. False on failure.
    auto write = [&](auto&& writer) {
        try {
            for (const auto& w : writer()) {
                if (!quiet) std::cerr << "hexex extract: warning: " << w << "\n";
                extras.warnings.push_back(w);
            }
            return true;
        } catch (const std::exception& e) {
            progress.finish();
            std::cerr << "hexex extract: error: " << e.what() << "\n";
            return false;
        }
    };
    if (!write([&] { return HexEx::writeHexMesh(output, hm, encoding, opt.threads, &neighbours); })) return 2;
    if (!surface_path.empty()) {
        if (!write([&] { return HexEx::writeBoundarySurface(surface_path, hm); })) return 2;
        if (!quiet) std::cerr << "hexex extract: wrote the boundary surface to " << surface_path << "\n";
    }
    if (!arcs_path.empty()) {
        if (!write([&] { HexEx::writeEdgeArcsVtu(arcs_path, arcs); return std::vector<std::string>{}; })) return 2;
        if (!quiet) std::cerr << "hexex extract: wrote " << rep.arcs.edges - rep.arcs.failed_edges << " edge arcs to " << arcs_path << "\n";
    }
    if (!provenance_path.empty()) {
        if (dropped.second > 0) {  // the hexes after a dropped one moved: indices would not match
            std::cerr << "hexex extract: error: " << provenance_path << ": not written (cells were dropped)\n";
            return 2;
        }
        if (!write([&] { writeProvenanceCsv(provenance_path, provenance); return std::vector<std::string>{}; })) return 2;
        if (!quiet) std::cerr << "hexex extract: wrote the provenance of " << provenance.hex_source_tet.size() << " hexes to " << provenance_path << "\n";
    }
    if (!patches_path.empty()) {
        if (!write([&] { HexEx::writeFacePatchesVtu(patches_path, arcs); return std::vector<std::string>{}; })) return 2;
        if (!quiet) std::cerr << "hexex extract: wrote " << rep.arcs.faces - rep.arcs.failed_faces << " face patches to " << patches_path << "\n";
    }
    extras.write_s = secondsSince(t0);
    progress.update("write", 1);
    progress.finish();
    extras.total_s = secondsSince(t_start);

    if (!report_path.empty()) {
        const std::string json = HexEx::reportToJson(rep, extras);
        if (report_path == "-") {
            std::cout << json << std::flush;
        } else {
            std::ofstream rf(report_path);
            rf << json;
            rf.flush();
            if (!rf) {
                std::cerr << "hexex extract: error: " << report_path << ": cannot write the report\n";
                return 2;
            }
        }
    }

    if (!quiet) {
        for (const auto& w : rep.warnings) std::cerr << "hexex extract: warning: " << w << "\n";
        std::ostream& os = report_path == "-" ? std::cerr : std::cout;
        os << "wrote " << output << ": " << rep.output.hexes << " hexes, " << rep.output.vertices << " vertices, "
           << (rep.valid_all_hex ? "valid all-hex" : "NOT all-hex") << "\n";
        if (untangle) printUntangleReport(os, untangle_rep);
        if (optimize) printOptimizeReport(os, optimize_rep);
    }
    // The optimiser (with --pillow: the layer, then the untangler on it) may end certified
    // valid where the first untangling did not.
    const bool left_invalid = untangle && !untangle_rep.success &&
                              !(optimize && optimize_rep.success && optimize_rep.invalid_after == 0);
    if (left_invalid) {
        std::cerr << "hexex extract: " << untangle_rep.message << "\n";
        // Hexes with several faces on the boundary can be beyond any placement with the
        // boundary on its surface (algorithm.md, boundary pillowing); a layer changes that.
        if (!optimize_opt.pillow && !repair.optimized)
            std::cerr << "hexex extract: hint: a hex with two or more faces on the boundary may have no valid "
                         "placement with the boundary kept on its surface; --pillow first inserts a layer of "
                         "hexes along the boundary (more hexes) and then untangles and optimises\n";
    }
    if (rep.valid_all_hex) return left_invalid ? 3 : 0;

    // Written, but not all-hex: say why.
    std::cerr << "hexex extract: the output is not a valid all-hex mesh:\n";
    if (rep.output.non_hex_cells > 0)
        std::cerr << "  " << rep.output.non_hex_cells << " non-hex cells (written as polyhedra)\n";
    if (rep.output.unconnected_darts > 0)
        std::cerr << "  " << rep.output.unconnected_darts << " unconnected darts (missing alpha_0..alpha_2 links)\n";
    if (rep.darts.remaining_anti > 0)
        std::cerr << "  " << rep.darts.remaining_anti << " anti darts remain after annihilation"
                  << (opt.merge ? "" : " (--no-merge)") << "\n";
    if (!rep.validation.valid()) std::cerr << "  validation: " << rep.validation.summary() << "\n";
    if (rep.output.hexes == 0 && rep.output.non_hex_cells == 0) std::cerr << "  no cells were extracted\n";
    return 3;
}

} // namespace HexExTool
