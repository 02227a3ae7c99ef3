/// @file CResult.cc
/// The C API's result handle: accessors, free, version and status texts, and the helpers
/// shared by the entry points (CResult.hh).

#include "CResult.hh"

#include <HexEx/Core/Version.hh>

#include <cmath>
#include <cstring>

static_assert(sizeof(int) == sizeof(std::int32_t), "HexMesh indices must be int32");
static_assert(sizeof(HexEx::Vec3d) == 3 * sizeof(double), "Vec3d must be three packed doubles");

namespace HexExC {

hexex_status fail(hexex_result* r, hexex_status status, const char* message) noexcept {
    r->status = status;
    try {
        r->message = message;
    } catch (...) {
        r->message.clear();  // keeps the status; hexex_result_error_message() falls back to its text
    }
    return status;
}

hexex_status newResult(hexex_result** out) noexcept {
    if (!out) return HEXEX_ERROR_INVALID_ARGUMENT;
    *out = new (std::nothrow) hexex_result;
    return *out ? HEXEX_OK : HEXEX_ERROR_RESOURCE;
}

void requireArray(const void* p, std::int64_t n, const char* name) {
    if (n < 0) throw ArgumentError(std::string(name) + ": negative count " + std::to_string(n));
    if (n > 0 && !p) throw ArgumentError(std::string(name) + " is NULL but its count is " + std::to_string(n));
}

void setQualityValues(hexex_result* r, const HexEx::QualityStats& q) {
    r->values[HEXEX_VALUE_INVERTED_HEXES] = static_cast<double>(q.inverted_hexes);
    r->values[HEXEX_VALUE_MIN_SCALED_JACOBIAN] = q.min_scaled_jacobian;
    r->values[HEXEX_VALUE_MEAN_SCALED_JACOBIAN] = q.mean_scaled_jacobian;
    r->values[HEXEX_VALUE_INVALID_HEXES] = static_cast<double>(q.invalid_hexes);
    r->values[HEXEX_VALUE_UNDECIDED_HEXES] = static_cast<double>(q.undecided_hexes);
}

void setUntangleValues(hexex_result* r, const HexEx::UntangleReport& u) {
    r->values[HEXEX_VALUE_UNTANGLE_SUCCESS] = u.success ? 1 : 0;
    r->values[HEXEX_VALUE_UNTANGLE_INVERTED_BEFORE] = static_cast<double>(u.inverted_before);
    r->values[HEXEX_VALUE_UNTANGLE_INVERTED_AFTER] = static_cast<double>(u.inverted_after);
    r->values[HEXEX_VALUE_UNTANGLE_MIN_SCALED_JACOBIAN_BEFORE] = u.min_scaled_jacobian_before;
    r->values[HEXEX_VALUE_UNTANGLE_MIN_SCALED_JACOBIAN_AFTER] = u.min_scaled_jacobian_after;
    r->values[HEXEX_VALUE_UNTANGLE_MOVED_VERTICES] = static_cast<double>(u.moved_vertices);
    r->values[HEXEX_VALUE_UNTANGLE_MAX_DISPLACEMENT] = u.max_displacement;
    r->values[HEXEX_VALUE_UNTANGLE_SECONDS] = u.seconds;
    r->values[HEXEX_VALUE_UNTANGLE_INVALID_BEFORE] = static_cast<double>(u.invalid_before);
    r->values[HEXEX_VALUE_UNTANGLE_INVALID_AFTER] = static_cast<double>(u.invalid_after);
}

void flattenPolyhedra(hexex_result* r) {
    r->face_offsets.clear();
    r->vertex_offsets.clear();
    r->face_vertices.clear();
    if (r->mesh.polyhedra.empty()) return;
    r->face_offsets.push_back(0);
    r->vertex_offsets.push_back(0);
    for (const HexEx::Polyhedron& p : r->mesh.polyhedra) {
        for (const std::vector<int>& f : p.faces) {
            r->face_vertices.insert(r->face_vertices.end(), f.begin(), f.end());
            r->vertex_offsets.push_back(static_cast<std::int64_t>(r->face_vertices.size()));
        }
        r->face_offsets.push_back(static_cast<std::int64_t>(r->vertex_offsets.size() - 1));
    }
}

void requireAtLeast(const char* what, const char* name, int v, int min) {
    if (v < min)
        throw ArgumentError(std::string(what) + " options: " + name + " must be >= " + std::to_string(min) + ", got " +
                            std::to_string(v));
}

void requireFeatureAngle(const char* what, double deg) {
    if (!(deg >= 0 && deg <= 180))
        throw ArgumentError(std::string(what) + " options: feature_angle_deg must be in [0, 180], got " +
                            HexEx::jsonNumber(deg));
}

hexex_untangle_options defaultUntangleOptions() {
    const HexEx::UntangleOptions d;
    hexex_untangle_options o;
    std::memset(static_cast<void*>(&o), 0, sizeof o);
    o.size = sizeof o;
    o.threads = d.threads;
    o.fixed_boundary = d.boundary == HexEx::BoundaryMode::Fixed ? 1 : 0;
    o.rings = d.rings;
    o.max_outer_iterations = d.max_outer_iterations;
    o.max_lbfgs_iterations = d.max_lbfgs_iterations;
    o.quality_iterations = d.quality_iterations;
    o.feature_angle_deg = d.feature_angle_deg;
    o.release_features = d.release_features ? 1 : 0;
    o.surface_points = nullptr;
    o.n_surface_points = 0;
    o.surface_triangles = nullptr;
    o.n_surface_triangles = 0;
    return o;
}

HexEx::UntangleOptions untangleOptions(const hexex_untangle_options& o, HexEx::TriangleSurface& surface,
                                       bool& has_surface) {
    requireAtLeast("untangle", "threads", o.threads, 0);
    requireAtLeast("untangle", "rings", o.rings, 1);
    requireAtLeast("untangle", "max_outer_iterations", o.max_outer_iterations, 1);
    requireAtLeast("untangle", "max_lbfgs_iterations", o.max_lbfgs_iterations, 1);
    requireAtLeast("untangle", "quality_iterations", o.quality_iterations, 0);
    requireFeatureAngle("untangle", o.feature_angle_deg);
    HexEx::UntangleOptions u;
    u.boundary = o.fixed_boundary ? HexEx::BoundaryMode::Fixed : HexEx::BoundaryMode::Surface;
    u.threads = o.threads;
    u.rings = o.rings;
    u.max_outer_iterations = o.max_outer_iterations;
    u.max_lbfgs_iterations = o.max_lbfgs_iterations;
    u.quality_iterations = o.quality_iterations;
    u.feature_angle_deg = o.feature_angle_deg;
    u.release_features = o.release_features != 0;
    has_surface = o.surface_points != nullptr || o.surface_triangles != nullptr;
    if (!has_surface) return u;
    requireArray(o.surface_points, o.n_surface_points, "untangle options: surface_points");
    requireArray(o.surface_triangles, o.n_surface_triangles, "untangle options: surface_triangles");
    if (!o.surface_points || !o.surface_triangles)
        throw ArgumentError("untangle options: give both surface_points and surface_triangles, or neither");
    for (std::int64_t i = 0; i < o.n_surface_points; ++i) {
        const double* p = o.surface_points + 3 * i;
        surface.points.emplace_back(p[0], p[1], p[2]);
    }
    for (std::int64_t i = 0; i < o.n_surface_triangles; ++i) {
        const std::int32_t* t = o.surface_triangles + 3 * i;
        for (int k = 0; k < 3; ++k)
            if (t[k] < 0 || t[k] >= o.n_surface_points)
                throw HexEx::InputError("surface triangle " + std::to_string(i) + " references point " +
                                        std::to_string(t[k]) + " of " + std::to_string(o.n_surface_points));
        surface.triangles.push_back({{t[0], t[1], t[2]}});
    }
    return u;
}

} // namespace HexExC

extern "C" {

const char* hexex_version(void) { return HexEx::version(); }

int hexex_c_api_version(void) { return HEXEX_C_API_VERSION; }

const char* hexex_status_string(hexex_status status) {
    switch (status) {
    case HEXEX_OK: return "success";
    case HEXEX_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case HEXEX_ERROR_INPUT: return "unusable input mesh";
    case HEXEX_ERROR_RESOURCE: return "out of memory or over the memory budget";
    case HEXEX_ERROR_INTERNAL: return "internal error";
    }
    return "unknown status";
}

void hexex_result_free(hexex_result* result) { delete result; }

hexex_status hexex_result_status(const hexex_result* result) { return result ? result->status : HEXEX_ERROR_RESOURCE; }

const char* hexex_result_error_message(const hexex_result* result) {
    if (!result) return hexex_status_string(HEXEX_ERROR_RESOURCE);
    if (result->status != HEXEX_OK && result->message.empty()) return hexex_status_string(result->status);
    return result->message.c_str();
}

hexex_status hexex_result_get(const hexex_result* result, hexex_value key, double* out) {
    if (!result || !out) return HEXEX_ERROR_INVALID_ARGUMENT;
    const auto it = result->values.find(static_cast<int>(key));
    if (it == result->values.end()) return HEXEX_ERROR_INVALID_ARGUMENT;
    *out = it->second;
    return HEXEX_OK;
}

const char* hexex_result_report_json(const hexex_result* result) {
    return result && result->status == HEXEX_OK ? result->json.c_str() : "";
}

int64_t hexex_result_n_vertices(const hexex_result* result) {
    return result ? static_cast<int64_t>(result->mesh.vertices.size()) : 0;
}

const double* hexex_result_vertices(const hexex_result* result) {
    return result && !result->mesh.vertices.empty() ? result->mesh.vertices.data()->data() : nullptr;
}

int64_t hexex_result_n_hexes(const hexex_result* result) {
    return result ? static_cast<int64_t>(result->mesh.hexes.size()) : 0;
}

const int32_t* hexex_result_hexes(const hexex_result* result) {
    return result && !result->mesh.hexes.empty() ? result->mesh.hexes.data()->data() : nullptr;
}

int64_t hexex_result_n_polyhedra(const hexex_result* result) {
    return result ? static_cast<int64_t>(result->mesh.polyhedra.size()) : 0;
}

void hexex_result_polyhedra(const hexex_result* result, const int64_t** face_offsets, const int64_t** vertex_offsets,
                            const int32_t** vertices) {
    const bool any = result && !result->face_offsets.empty();
    if (face_offsets) *face_offsets = any ? result->face_offsets.data() : nullptr;
    if (vertex_offsets) *vertex_offsets = any ? result->vertex_offsets.data() : nullptr;
    if (vertices) *vertices = any && !result->face_vertices.empty() ? result->face_vertices.data() : nullptr;
}

} // extern "C"
