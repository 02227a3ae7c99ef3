/// @file COptimize.cc
/// The C API of the mesh optimiser: hexex_optimize() and hexex_result_optimize()
/// (HexEx::optimizeHexMesh()).

#include "CResult.hh"

#include <HexEx/IO/OptimizeReportJson.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

namespace HexExC {

namespace {

/// The defaults of hexex_optimize_options (those of HexEx::OptimizeOptions).
hexex_optimize_options defaultOptimizeOptions() {
    const HexEx::OptimizeOptions d;
    hexex_optimize_options o;
    std::memset(static_cast<void*>(&o), 0, sizeof o);
    o.size = sizeof o;
    o.threads = d.threads;
    o.fixed_boundary = d.boundary == HexEx::BoundaryMode::Fixed ? 1 : 0;
    o.target = d.target;
    o.feature_angle_deg = d.feature_angle_deg;
    o.max_global_blocks = d.max_global_blocks;
    o.max_local_passes = d.max_local_passes;
    o.pillow = d.pillow ? 1 : 0;
    return o;
}

/// Checks the ranges of @p o and converts it to the C++ options; fills @p surface from the
/// optional surface arrays (the same rules as the untangling options).
HexEx::OptimizeOptions optimizeOptions(const hexex_optimize_options& o, HexEx::TriangleSurface& surface,
                                       bool& has_surface) {
    requireAtLeast("optimize", "threads", o.threads, 0);
    requireAtLeast("optimize", "max_global_blocks", o.max_global_blocks, 0);
    requireAtLeast("optimize", "max_local_passes", o.max_local_passes, 0);
    if (!(o.target > -1 && o.target <= 1))
        throw ArgumentError("optimize options: target must be in (-1, 1], got " + HexEx::jsonNumber(o.target));
    requireFeatureAngle("optimize", o.feature_angle_deg);
    // The surface arrays are read by the untangling options' converter (one place for them).
    hexex_untangle_options u = defaultUntangleOptions();
    u.surface_points = o.surface_points;
    u.n_surface_points = o.n_surface_points;
    u.surface_triangles = o.surface_triangles;
    u.n_surface_triangles = o.n_surface_triangles;
    untangleOptions(u, surface, has_surface);

    HexEx::OptimizeOptions r;
    r.boundary = o.fixed_boundary ? HexEx::BoundaryMode::Fixed : HexEx::BoundaryMode::Surface;
    r.threads = o.threads;
    r.target = o.target;
    r.feature_angle_deg = o.feature_angle_deg;
    r.max_global_blocks = o.max_global_blocks;
    r.max_local_passes = o.max_local_passes;
    r.pillow = o.pillow != 0;
    return r;
}

/// Sets the HEXEX_VALUE_OPTIMIZE_* values of @p q on @p r.
void setOptimizeValues(hexex_result* r, const HexEx::OptimizeReport& q) {
    r->values[HEXEX_VALUE_OPTIMIZE_SUCCESS] = q.success ? 1 : 0;
    r->values[HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_BEFORE] = q.min_scaled_jacobian_before;
    r->values[HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_AFTER] = q.min_scaled_jacobian_after;
    r->values[HEXEX_VALUE_OPTIMIZE_MEAN_SCALED_JACOBIAN_BEFORE] = q.mean_scaled_jacobian_before;
    r->values[HEXEX_VALUE_OPTIMIZE_MEAN_SCALED_JACOBIAN_AFTER] = q.mean_scaled_jacobian_after;
    r->values[HEXEX_VALUE_OPTIMIZE_REACHED_TARGET] = q.reached_target ? 1 : 0;
    r->values[HEXEX_VALUE_OPTIMIZE_INVALID_AFTER] = static_cast<double>(q.invalid_after);
    r->values[HEXEX_VALUE_OPTIMIZE_MAX_SURFACE_DISTANCE] = q.max_surface_distance;
    r->values[HEXEX_VALUE_OPTIMIZE_SECONDS] = q.seconds;
    r->values[HEXEX_VALUE_OPTIMIZE_PILLOWED_HEXES] = static_cast<double>(q.pillowed_hexes);
    r->values[HEXEX_VALUE_OPTIMIZE_TRIMMED_HEXES] = static_cast<double>(q.trimmed_hexes);
}

/// Optimises a copy of @p mesh with the C options @p options (NULL: defaults) into
/// @p optimized, so that the caller's mesh is unchanged if anything throws.
HexEx::OptimizeReport optimizeCopy(const HexEx::HexMesh& mesh, const hexex_optimize_options* options,
                                   HexEx::HexMesh& optimized) {
    const hexex_optimize_options o = readOptions(options, defaultOptimizeOptions());
    HexEx::TriangleSurface surface;
    bool has_surface = false;
    const HexEx::OptimizeOptions opt = optimizeOptions(o, surface, has_surface);
    optimized = mesh;
    return HexEx::optimizeHexMesh(optimized, opt, has_surface ? &surface : nullptr);
}

/// Throws HexEx::InputError naming the first hex with a vertex index outside [0, n_points).
void requireIndicesInRange(const HexEx::HexMesh& mesh) {
    const long nv = static_cast<long>(mesh.vertices.size());
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        for (const int v : mesh.hexes[h])
            if (v < 0 || v >= nv)
                throw HexEx::InputError("hex " + std::to_string(h) + ": vertex index " + std::to_string(v) +
                                        " out of range (the mesh has " + std::to_string(nv) + " vertices)");
}

} // namespace

} // namespace HexExC

extern "C" {

void hexex_optimize_options_init(hexex_optimize_options* options) {
    if (options) *options = HexExC::defaultOptimizeOptions();
}

hexex_status hexex_optimize(double* points, int64_t n_points, const int32_t* hexes, int64_t n_hexes,
                            const hexex_optimize_options* options, hexex_result** result) {
    const hexex_status s = HexExC::newResult(result);
    if (s != HEXEX_OK) return s;
    hexex_result* r = *result;
    return HexExC::guarded(r, [&] {
        if (options && options->size >= offsetof(hexex_optimize_options, pillow) + sizeof options->pillow && options->pillow)
            throw HexExC::ArgumentError("optimize options: pillow adds hexes and vertices, which the caller's arrays "
                                        "cannot hold; use hexex_result_optimize() on a result");
        HexExC::requireArray(points, n_points, "points");
        HexExC::requireArray(hexes, n_hexes, "hexes");
        HexEx::HexMesh hm;
        hm.vertices.resize(static_cast<std::size_t>(n_points));
        if (n_points > 0) std::copy(points, points + 3 * n_points, hm.vertices.data()->data());
        hm.hexes.resize(static_cast<std::size_t>(n_hexes));
        if (n_hexes > 0) std::copy(hexes, hexes + 8 * n_hexes, hm.hexes.data()->data());
        HexExC::requireIndicesInRange(hm);
        HexEx::HexMesh optimized;
        const HexEx::OptimizeReport q = HexExC::optimizeCopy(hm, options, optimized);
        r->json = HexEx::optimizeReportToJson(q) + "\n";
        HexExC::setOptimizeValues(r, q);
        HexExC::setQualityValues(r, HexEx::computeQuality(optimized));
        r->values[HEXEX_VALUE_VERTICES] = static_cast<double>(n_points);
        r->values[HEXEX_VALUE_HEXES] = static_cast<double>(n_hexes);
        if (n_points > 0)
            std::copy(optimized.vertices.data()->data(), optimized.vertices.data()->data() + 3 * n_points, points);
        r->optimize = q;
    });
}

hexex_status hexex_result_optimize(hexex_result* result, const hexex_optimize_options* options) {
    if (!result) return HEXEX_ERROR_INVALID_ARGUMENT;
    if (result->status != HEXEX_OK)
        return HexExC::fail(result, HEXEX_ERROR_INVALID_ARGUMENT, "optimize: the result holds an error, not a mesh");
    return HexExC::guarded(result, [&] {
        HexEx::HexMesh optimized;
        const HexEx::OptimizeReport q = HexExC::optimizeCopy(result->mesh, options, optimized);
        if (optimized.vertices.size() == result->mesh.vertices.size() && optimized.hexes == result->mesh.hexes) {
            // Same sizes: copying keeps the pointers the caller already has valid.
            std::copy(optimized.vertices.begin(), optimized.vertices.end(), result->mesh.vertices.begin());
        } else {  // pillowed: new arrays, and the counts of the new mesh
            result->mesh = std::move(optimized);
            const HexEx::HexMeshCheckResult c = HexEx::checkHexMesh(result->mesh);
            result->values[HEXEX_VALUE_VERTICES] = static_cast<double>(c.vertices);
            result->values[HEXEX_VALUE_HEXES] = static_cast<double>(c.hexes);
            result->values[HEXEX_VALUE_QUADS] = static_cast<double>(c.quads);
            result->values[HEXEX_VALUE_BOUNDARY_QUADS] = static_cast<double>(c.boundary_quads);
        }
        result->optimize = q;
        HexExC::setOptimizeValues(result, q);
        const HexEx::QualityStats quality = HexEx::computeQuality(result->mesh);
        HexExC::setQualityValues(result, quality);
        if (result->extraction) {
            result->extras.quality = quality;
            if (result->untangle) result->extras.untangle = &*result->untangle;
            result->extras.optimize = &*result->optimize;
            result->json = HexEx::reportToJson(*result->extraction, result->extras);
        } else {
            result->json = HexEx::optimizeReportToJson(q) + "\n";
        }
    });
}

} // extern "C"
