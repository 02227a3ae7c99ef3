/// @file CExtract.cc
/// hexex_extract() and hexex_extract64(): the one-call extraction on flat arrays, read
/// through TetMeshTraits of a non-owning view of the caller's arrays.

#include "CResult.hh"

#include <HexEx/HexEx.hh>
#include <HexEx/HexExTraits.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>

#include <chrono>
#include <cstring>
#include <utility>

namespace HexExC {

/// Non-owning view of the caller's arrays (3 doubles per point, 4 indices and 12 parameters per tet).
template <class Index>
struct CTetArrays {
    const double* points = nullptr;  ///< n_vertices x 3
    std::size_t n_vertices = 0;      ///< number of vertices
    const Index* tets = nullptr;     ///< n_tets x 4
    std::size_t n_tets = 0;          ///< number of tets
    const double* params = nullptr;  ///< n_tets x 4 x 3
};

} // namespace HexExC

/// TetMeshTraits of the C arrays; toParametrizedTetMesh() validates the indices (a negative
/// index wraps around to a huge one and is reported with its negative value).
template <class Index>
struct HexEx::TetMeshTraits<HexExC::CTetArrays<Index>> {
    /// Alias of the view type.
    using View = HexExC::CTetArrays<Index>;
    /// Number of vertices.
    static std::size_t n_vertices(const View& m) { return m.n_vertices; }
    /// Position of vertex @p v.
    static Vec3d position(const View& m, std::size_t v) {
        const double* p = m.points + 3 * v;
        return Vec3d(p[0], p[1], p[2]);
    }
    /// Number of tets.
    static std::size_t n_tets(const View& m) { return m.n_tets; }
    /// Corners of tet @p t.
    static std::array<std::size_t, 4> tet_vertices(const View& m, std::size_t t) {
        const Index* c = m.tets + 4 * t;
        return {static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1]), static_cast<std::size_t>(c[2]),
                static_cast<std::size_t>(c[3])};
    }
    /// Parameter of corner @p corner of tet @p t.
    static Vec3d corner_param(const View& m, std::size_t t, int corner) {
        const double* p = m.params + 12 * t + 3 * static_cast<std::size_t>(corner);
        return Vec3d(p[0], p[1], p[2]);
    }
};

namespace HexExC {

namespace {

/// The defaults of hexex_extraction_options (those of HexEx::ExtractionOptions).
hexex_extraction_options defaultExtractionOptions() {
    const HexEx::ExtractionOptions d;
    hexex_extraction_options o;
    std::memset(static_cast<void*>(&o), 0, sizeof o);
    o.size = sizeof o;
    o.threads = d.threads;
    o.epsilon = d.epsilon;
    o.merge = d.merge ? 1 : 0;
    o.implicit_cells = d.implicit_cells ? 1 : 0;
    o.cheap_folds = d.cheap_folds ? 1 : 0;
    o.annihilation_retries = d.annihilation_retries ? 1 : 0;
    o.max_hexes = d.max_hexes;
    o.max_memory = d.max_memory;
    o.given_rotations = nullptr;
    return o;
}

/// The extraction behind both entry points.
template <class Index>
void extract(hexex_result* r, const double* points, std::int64_t n_points, const Index* tets, std::int64_t n_tets,
             const double* params, const hexex_extraction_options* options) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    requireArray(points, n_points, "points");
    requireArray(tets, n_tets, "tets");
    requireArray(params, n_tets, "params");
    const hexex_extraction_options o = readOptions(options, defaultExtractionOptions());
    if (o.threads < 0)
        throw ArgumentError("options: threads must be >= 0 (0 = all hardware threads), got " + std::to_string(o.threads));
    if (!(o.epsilon >= 0 && o.epsilon < 0.5))
        throw ArgumentError("options: epsilon must be in [0, 0.5), got " + HexEx::jsonNumber(o.epsilon));
    if (!(o.max_hexes > 0)) throw ArgumentError("options: max_hexes must be > 0, got " + HexEx::jsonNumber(o.max_hexes));
    HexEx::ExtractionOptions opt;
    opt.threads = o.threads;
    opt.epsilon = o.epsilon;
    opt.merge = o.merge != 0;
    opt.implicit_cells = o.implicit_cells != 0;
    opt.cheap_folds = o.cheap_folds != 0;
    opt.annihilation_retries = o.annihilation_retries != 0;
    opt.max_hexes = o.max_hexes;
    opt.max_memory = o.max_memory;
    std::vector<int> given;
    if (o.given_rotations) {
        given.assign(o.given_rotations, o.given_rotations + 4 * n_tets);
        opt.given_rotations = &given;
    }

    HexEx::ExtractionReport rep;
    HexEx::HexMesh hm;
    {
        const CTetArrays<Index> view{points, static_cast<std::size_t>(n_points), tets, static_cast<std::size_t>(n_tets),
                                     params};
        HexEx::ParametrizedTetMesh pm = HexEx::toParametrizedTetMesh(view);
        const std::string problem = pm.mesh.check_manifold();
        if (!problem.empty()) throw HexEx::InputError(problem);
        r->extras.read_s = std::chrono::duration<double>(Clock::now() - t0).count();
        rep = HexEx::extractHexMesh(std::move(pm), hm, opt);  // takes the parameters over, no copy
    }
    r->extras.quality = HexEx::computeQuality(hm);
    r->extras.total_s = std::chrono::duration<double>(Clock::now() - t0).count();
    r->json = HexEx::reportToJson(rep, r->extras);
    r->mesh = std::move(hm);
    flattenPolyhedra(r);

    auto set = [r](hexex_value k, double v) { r->values[k] = v; };
    set(HEXEX_VALUE_VALID_ALL_HEX, rep.valid_all_hex ? 1 : 0);
    set(HEXEX_VALUE_VERTICES, static_cast<double>(rep.output.vertices));
    set(HEXEX_VALUE_HEXES, static_cast<double>(rep.output.hexes));
    set(HEXEX_VALUE_NON_HEX_CELLS, static_cast<double>(rep.output.non_hex_cells));
    set(HEXEX_VALUE_QUADS, static_cast<double>(rep.output.quads));
    set(HEXEX_VALUE_BOUNDARY_QUADS, static_cast<double>(rep.output.boundary_quads));
    setQualityValues(r, r->extras.quality);
    set(HEXEX_VALUE_INPUT_VERTICES, static_cast<double>(rep.input.vertices));
    set(HEXEX_VALUE_INPUT_TETS, static_cast<double>(rep.input.tets));
    set(HEXEX_VALUE_FLIPPED_TETS, static_cast<double>(rep.input.flipped_tets));
    set(HEXEX_VALUE_DEGENERATE_TETS, static_cast<double>(rep.input.degenerate_tets));
    set(HEXEX_VALUE_SINGULAR_EDGES, static_cast<double>(rep.input.singular_edges));
    set(HEXEX_VALUE_SINGULAR_VERTICES, static_cast<double>(rep.input.singular_vertices));
    set(HEXEX_VALUE_PARAMETRIC_VOLUME, rep.input.parametric_volume);
    set(HEXEX_VALUE_EXTRACTED_DARTS, static_cast<double>(rep.darts.extracted));
    set(HEXEX_VALUE_ANTI_DARTS, static_cast<double>(rep.darts.anti));
    set(HEXEX_VALUE_UNCONNECTED_DARTS, static_cast<double>(rep.output.unconnected_darts));
    set(HEXEX_VALUE_THREADS, rep.threads);
    set(HEXEX_VALUE_SECONDS, r->extras.total_s);
    r->extraction = std::move(rep);
}

/// Allocates the result and runs extract() under guarded().
template <class Index>
hexex_status extractEntry(const double* points, std::int64_t n_points, const Index* tets, std::int64_t n_tets,
                          const double* params, const hexex_extraction_options* options, hexex_result** result) {
    const hexex_status s = newResult(result);
    if (s != HEXEX_OK) return s;
    return guarded(*result, [&] { extract(*result, points, n_points, tets, n_tets, params, options); });
}

} // namespace

} // namespace HexExC

extern "C" {

void hexex_extraction_options_init(hexex_extraction_options* options) {
    if (options) *options = HexExC::defaultExtractionOptions();
}

hexex_status hexex_extract(const double* points, int64_t n_points, const int32_t* tets, int64_t n_tets,
                           const double* params, const hexex_extraction_options* options, hexex_result** result) {
    return HexExC::extractEntry(points, n_points, tets, n_tets, params, options, result);
}

hexex_status hexex_extract64(const double* points, int64_t n_points, const int64_t* tets, int64_t n_tets,
                             const double* params, const hexex_extraction_options* options, hexex_result** result) {
    return HexExC::extractEntry(points, n_points, tets, n_tets, params, options, result);
}

} // extern "C"
