/// @file CHexMesh.cc
/// The C API on hex meshes: hexex_validate() (HexEx::checkHexMesh()), hexex_untangle() and
/// hexex_result_untangle() (HexEx::untangleHexMesh()).

#include "CResult.hh"

#include <HexEx/Mesh/HexMeshCheck.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>

#include <algorithm>
#include <sstream>

namespace HexExC {

namespace {

/// A HexMesh copied from the caller's arrays (indices are not checked here).
HexEx::HexMesh hexMeshFromArrays(const double* points, std::int64_t n_points, const std::int32_t* hexes,
                                 std::int64_t n_hexes) {
    requireArray(points, n_points, "points");
    requireArray(hexes, n_hexes, "hexes");
    HexEx::HexMesh hm;
    hm.vertices.resize(static_cast<std::size_t>(n_points));
    if (n_points > 0) std::copy(points, points + 3 * n_points, hm.vertices.data()->data());
    hm.hexes.resize(static_cast<std::size_t>(n_hexes));
    if (n_hexes > 0) std::copy(hexes, hexes + 8 * n_hexes, hm.hexes.data()->data());
    return hm;
}

/// The check as JSON, with the keys of `hexex validate --json`.
std::string checkToJson(const HexEx::HexMeshCheckResult& c) {
    std::ostringstream s;
    s << "{\n"
      << "  \"cells\": " << c.cells << ",\n"
      << "  \"hexes\": " << c.hexes << ",\n"
      << "  \"non_hex_cells\": " << c.non_hex_cells << ",\n"
      << "  \"vertices\": " << c.vertices << ",\n"
      << "  \"edges\": " << c.edges << ",\n"
      << "  \"faces\": " << c.faces << ",\n"
      << "  \"quads\": " << c.quads << ",\n"
      << "  \"boundary_quads\": " << c.boundary_quads << ",\n"
      << "  \"boundary_faces\": " << c.boundary_faces << ",\n"
      << "  \"quads_shared_by_more_than_two\": " << c.quads_shared_by_more_than_two << ",\n"
      << "  \"nonmanifold_boundary_edges\": " << c.nonmanifold_boundary_edges << ",\n"
      << "  \"nonmanifold_boundary_vertices\": " << c.nonmanifold_boundary_vertices << ",\n"
      << "  \"invalid_cells\": " << c.invalid_cells << ",\n"
      << "  \"euler_characteristic\": " << c.euler_characteristic << ",\n"
      << "  \"min_scaled_jacobian\": " << HexEx::jsonNumber(c.quality.min_scaled_jacobian) << ",\n"
      << "  \"mean_scaled_jacobian\": " << HexEx::jsonNumber(c.quality.mean_scaled_jacobian) << ",\n"
      << "  \"inverted_hexes\": " << c.quality.inverted_hexes << ",\n"
      << "  \"valid_all_hex\": " << (c.valid_all_hex ? "true" : "false") << "\n"
      << "}\n";
    return s.str();
}

/// The untangling report as JSON, with the field names of HexEx::UntangleReport.
std::string untangleToJson(const HexEx::UntangleReport& u) {
    std::ostringstream s;
    s << "{\n"
      << "  \"hexes\": " << u.hexes << ",\n"
      << "  \"inverted_before\": " << u.inverted_before << ",\n"
      << "  \"inverted_after\": " << u.inverted_after << ",\n"
      << "  \"min_scaled_jacobian_before\": " << HexEx::jsonNumber(u.min_scaled_jacobian_before) << ",\n"
      << "  \"mean_scaled_jacobian_before\": " << HexEx::jsonNumber(u.mean_scaled_jacobian_before) << ",\n"
      << "  \"min_scaled_jacobian_after\": " << HexEx::jsonNumber(u.min_scaled_jacobian_after) << ",\n"
      << "  \"mean_scaled_jacobian_after\": " << HexEx::jsonNumber(u.mean_scaled_jacobian_after) << ",\n"
      << "  \"free_vertices\": " << u.free_vertices << ",\n"
      << "  \"moved_vertices\": " << u.moved_vertices << ",\n"
      << "  \"max_displacement\": " << HexEx::jsonNumber(u.max_displacement) << ",\n"
      << "  \"mean_displacement\": " << HexEx::jsonNumber(u.mean_displacement) << ",\n"
      << "  \"released_feature_vertices\": " << u.released_feature_vertices << ",\n"
      << "  \"attempts\": " << u.attempts << ",\n"
      << "  \"rings\": " << u.rings << ",\n"
      << "  \"outer_iterations\": " << u.outer_iterations << ",\n"
      << "  \"lbfgs_iterations\": " << u.lbfgs_iterations << ",\n"
      << "  \"quality_iterations\": " << u.quality_iterations << ",\n"
      << "  \"seconds\": " << HexEx::jsonNumber(u.seconds) << ",\n"
      << "  \"success\": " << (u.success ? "true" : "false") << ",\n"
      << "  \"budget_exhausted\": " << (u.budget_exhausted ? "true" : "false") << ",\n"
      << "  \"message\": " << HexEx::jsonQuote(u.message) << "\n"
      << "}\n";
    return s.str();
}

/// Untangles a copy of @p mesh with the C options @p options (NULL: defaults); the caller
/// copies the positions back, so @p mesh is unchanged if anything throws.
HexEx::UntangleReport untangleCopy(const HexEx::HexMesh& mesh, const hexex_untangle_options* options,
                                   HexEx::HexMesh& untangled) {
    const hexex_untangle_options o = readOptions(options, defaultUntangleOptions());
    HexEx::TriangleSurface surface;
    bool has_surface = false;
    const HexEx::UntangleOptions opt = untangleOptions(o, surface, has_surface);
    untangled = mesh;
    return HexEx::untangleHexMesh(untangled, opt, has_surface ? &surface : nullptr);
}

} // namespace

} // namespace HexExC

extern "C" {

void hexex_untangle_options_init(hexex_untangle_options* options) {
    if (options) *options = HexExC::defaultUntangleOptions();
}

hexex_status hexex_validate(const double* points, int64_t n_points, const int32_t* hexes, int64_t n_hexes,
                            hexex_result** result) {
    const hexex_status s = HexExC::newResult(result);
    if (s != HEXEX_OK) return s;
    hexex_result* r = *result;
    return HexExC::guarded(r, [&] {
        const HexEx::HexMesh hm = HexExC::hexMeshFromArrays(points, n_points, hexes, n_hexes);
        const HexEx::HexMeshCheckResult c = HexEx::checkHexMesh(hm);
        r->json = HexExC::checkToJson(c);
        auto set = [r](hexex_value k, double v) { r->values[k] = v; };
        set(HEXEX_VALUE_VALID_ALL_HEX, c.valid_all_hex ? 1 : 0);
        set(HEXEX_VALUE_VERTICES, static_cast<double>(c.vertices));
        set(HEXEX_VALUE_HEXES, static_cast<double>(c.hexes));
        set(HEXEX_VALUE_NON_HEX_CELLS, static_cast<double>(c.non_hex_cells));
        set(HEXEX_VALUE_QUADS, static_cast<double>(c.quads));
        set(HEXEX_VALUE_BOUNDARY_QUADS, static_cast<double>(c.boundary_quads));
        HexExC::setQualityValues(r, c.quality);
        set(HEXEX_VALUE_CELLS, static_cast<double>(c.cells));
        set(HEXEX_VALUE_EDGES, static_cast<double>(c.edges));
        set(HEXEX_VALUE_FACES, static_cast<double>(c.faces));
        set(HEXEX_VALUE_BOUNDARY_FACES, static_cast<double>(c.boundary_faces));
        set(HEXEX_VALUE_FACES_SHARED_BY_MORE_THAN_TWO, static_cast<double>(c.quads_shared_by_more_than_two));
        set(HEXEX_VALUE_NONMANIFOLD_BOUNDARY_EDGES, static_cast<double>(c.nonmanifold_boundary_edges));
        set(HEXEX_VALUE_NONMANIFOLD_BOUNDARY_VERTICES, static_cast<double>(c.nonmanifold_boundary_vertices));
        set(HEXEX_VALUE_INVALID_CELLS, static_cast<double>(c.invalid_cells));
        set(HEXEX_VALUE_EULER_CHARACTERISTIC, static_cast<double>(c.euler_characteristic));
    });
}

hexex_status hexex_untangle(double* points, int64_t n_points, const int32_t* hexes, int64_t n_hexes,
                            const hexex_untangle_options* options, hexex_result** result) {
    const hexex_status s = HexExC::newResult(result);
    if (s != HEXEX_OK) return s;
    hexex_result* r = *result;
    return HexExC::guarded(r, [&] {
        const HexEx::HexMesh hm = HexExC::hexMeshFromArrays(points, n_points, hexes, n_hexes);
        HexEx::HexMesh untangled;
        const HexEx::UntangleReport u = HexExC::untangleCopy(hm, options, untangled);
        r->json = HexExC::untangleToJson(u);
        HexExC::setUntangleValues(r, u);
        HexExC::setQualityValues(r, HexEx::computeQuality(untangled));
        r->values[HEXEX_VALUE_VERTICES] = static_cast<double>(n_points);
        r->values[HEXEX_VALUE_HEXES] = static_cast<double>(n_hexes);
        if (n_points > 0) std::copy(untangled.vertices.data()->data(), untangled.vertices.data()->data() + 3 * n_points, points);
        r->untangle = u;
    });
}

hexex_status hexex_result_untangle(hexex_result* result, const hexex_untangle_options* options) {
    if (!result) return HEXEX_ERROR_INVALID_ARGUMENT;
    if (result->status != HEXEX_OK)
        return HexExC::fail(result, HEXEX_ERROR_INVALID_ARGUMENT, "untangle: the result holds an error, not a mesh");
    return HexExC::guarded(result, [&] {
        HexEx::HexMesh untangled;
        const HexEx::UntangleReport u = HexExC::untangleCopy(result->mesh, options, untangled);
        // Same sizes: copying keeps the pointers the caller already has valid.
        std::copy(untangled.vertices.begin(), untangled.vertices.end(), result->mesh.vertices.begin());
        result->untangle = u;
        HexExC::setUntangleValues(result, u);
        const HexEx::QualityStats q = HexEx::computeQuality(result->mesh);
        HexExC::setQualityValues(result, q);
        if (result->extraction) {
            result->extras.quality = q;
            result->extras.untangle = &*result->untangle;
            result->json = HexEx::reportToJson(*result->extraction, result->extras);
        } else {
            result->json = HexExC::untangleToJson(u);
        }
    });
}

} // extern "C"
