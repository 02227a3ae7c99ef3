#pragma once
/// @file CResult.hh
/// Internals of the C API (hexex.h): the result handle and the wrapper that turns every
/// C++ exception into a status and a message. Not installed.

#include "hexex.h"

#include <HexEx/Extraction/ExtractionReport.hh>
#include <HexEx/IO/ReportJson.hh>
#include <HexEx/Mesh/HexMesh.hh>
#include <HexEx/Untangling/HexOptimizer.hh>
#include <HexEx/Untangling/Untangler.hh>

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

/// The opaque result handle of the C API: a mesh, values, a JSON report, or an error.
struct hexex_result {
    hexex_status status = HEXEX_OK;             ///< outcome of the last call on this handle
    std::string message;                        ///< error message ("" on success)
    HexEx::HexMesh mesh;                        ///< the mesh (empty for results without one)
    std::vector<std::int64_t> face_offsets;     ///< polyhedra: first face of each, plus the end
    std::vector<std::int64_t> vertex_offsets;   ///< polyhedra: first vertex of each face, plus the end
    std::vector<std::int32_t> face_vertices;    ///< polyhedra: the face loops, concatenated
    std::map<int, double> values;               ///< the HEXEX_VALUE_* the result has
    std::string json;                           ///< the JSON report
    std::optional<HexEx::ExtractionReport> extraction;  ///< the extraction report (extraction results)
    HexEx::ReportExtras extras;                 ///< quality etc. for the extraction report's JSON
    std::optional<HexEx::UntangleReport> untangle;      ///< the last untangling run, if any
    std::optional<HexEx::OptimizeReport> optimize;      ///< the last optimisation run, if any
};

namespace HexExC {

/// A bad argument of a C API call (HEXEX_ERROR_INVALID_ARGUMENT).
class ArgumentError : public std::invalid_argument {
public:
    /// An error with a complete message.
    explicit ArgumentError(const std::string& what) : std::invalid_argument(what) {}
};

/// Stores @p status and @p message in @p r without throwing; returns @p status.
hexex_status fail(hexex_result* r, hexex_status status, const char* message) noexcept;

/// Runs @p body, turning every exception into a status stored in @p r with its message.
template <class Body>
hexex_status guarded(hexex_result* r, Body&& body) noexcept;

/// Allocates a result for @p out (NULL if that fails); returns HEXEX_ERROR_INVALID_ARGUMENT
/// if @p out is NULL, HEXEX_ERROR_RESOURCE if the allocation fails, else HEXEX_OK.
hexex_status newResult(hexex_result** out) noexcept;

/// Throws ArgumentError unless @p n >= 0 and @p p is non-null when @p n > 0.
void requireArray(const void* p, std::int64_t n, const char* name);

/// Copies the caller's options struct @p in over @p defaults, reading only the fields
/// that fit in `in->size`; throws ArgumentError if `size` was not set or is too large.
template <class Options>
Options readOptions(const Options* in, const Options& defaults);

/// Throws ArgumentError "<what> options: <name> must be >= <min>, got <v>" if @p v < @p min.
void requireAtLeast(const char* what, const char* name, int v, int min);

/// Throws ArgumentError unless @p deg (a feature angle of the @p what options) is in [0, 180].
void requireFeatureAngle(const char* what, double deg);

/// Sets the values the quality gives (HEXEX_VALUE_INVERTED_HEXES, ...) on @p r.
void setQualityValues(hexex_result* r, const HexEx::QualityStats& q);

/// Sets the HEXEX_VALUE_UNTANGLE_* values of @p u on @p r.
void setUntangleValues(hexex_result* r, const HexEx::UntangleReport& u);

/// Fills the polyhedron arrays of @p r from r->mesh.polyhedra.
void flattenPolyhedra(hexex_result* r);

/// Converts a C untangle options struct (after readOptions()) to the C++ options; checks
/// the ranges and fills @p surface from the optional surface arrays.
HexEx::UntangleOptions untangleOptions(const hexex_untangle_options& o, HexEx::TriangleSurface& surface,
                                       bool& has_surface);

/// The defaults of hexex_untangle_options.
hexex_untangle_options defaultUntangleOptions();

} // namespace HexExC

#include "CResult_impl.hh"
