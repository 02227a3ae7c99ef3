#ifndef HEXEX_H
#define HEXEX_H
/**
 * @file hexex.h
 * @ingroup capi
 * The C API of HexEx (C99): hex-mesh extraction, validation and untangling on flat arrays,
 * for callers in C and in any language with a C foreign-function interface (Python's
 * ctypes, Julia's ccall, Rust, C#). Installed as `include/hexex.h`; link the shared library
 * `hexex_c` (CMake: `find_package(HexEx)` and `target_link_libraries(app HexEx::C)`).
 *
 * Conventions:
 * - Every fallible function returns a ::hexex_status; HEXEX_OK is 0.
 * - Functions that compute something return it in a ::hexex_result handle through an
 *   out-parameter. The handle is created even when the call fails, and then carries the
 *   status and the error message (hexex_result_status(), hexex_result_error_message());
 *   only when not even the handle can be allocated is it NULL (status
 *   HEXEX_ERROR_RESOURCE). Free every handle with hexex_result_free().
 * - Arrays passed in are only read during the call (hexex_untangle() writes its points) and
 *   never kept. Arrays returned by a handle are owned by it and valid until it is freed or
 *   changed by hexex_result_untangle().
 * - No C++ exception crosses this interface; the library keeps no global state, so
 *   different handles may be used from different threads at the same time.
 * - Options structs are initialised by their `*_init()` function, which also sets their
 *   `size` member: fields added in later versions go at the end, and a library reads only
 *   the fields that fit in `size`, so code compiled against an older header keeps working.
 *
 * Example (error handling shortened):
 * @code
 * hexex_extraction_options opt;
 * hexex_extraction_options_init(&opt);
 * opt.threads = 4;
 * hexex_result* r = NULL;
 * if (hexex_extract(points, n_points, tets, n_tets, params, &opt, &r) != HEXEX_OK) {
 *     fprintf(stderr, "hexex: %s\n", hexex_result_error_message(r));
 * } else {
 *     printf("%lld hexes\n", (long long)hexex_result_n_hexes(r));
 * }
 * hexex_result_free(r);
 * @endcode
 */

#include <stddef.h>
#include <stdint.h>

/** @addtogroup capi
 *  @{ */

#if defined(_WIN32)
#  if defined(HEXEX_C_BUILDING)
#    define HEXEX_C_API __declspec(dllexport)
#  else
#    define HEXEX_C_API __declspec(dllimport)
#  endif
#else
/** Marks the functions exported by the shared library `hexex_c`. */
#  define HEXEX_C_API __attribute__((visibility("default")))
#endif

/** Version of this interface: raised when functions, values or option fields are added. */
#define HEXEX_C_API_VERSION 3

#ifdef __cplusplus
extern "C" {
#endif

/** Outcome of a call. */
typedef enum hexex_status {
    HEXEX_OK = 0,                     /**< success */
    HEXEX_ERROR_INVALID_ARGUMENT = 1, /**< a null pointer, a negative count, an option out of range, or a value the result does not have */
    HEXEX_ERROR_INPUT = 2,            /**< unusable mesh: vertex index out of range, repeated vertex, non-manifold faces, non-finite numbers */
    HEXEX_ERROR_RESOURCE = 3,         /**< the memory budget (hexex_extraction_options::max_memory) is exceeded or an allocation failed */
    HEXEX_ERROR_INTERNAL = 4          /**< any other failure inside the library (a bug: please report it with the message) */
} hexex_status;

/** Values a ::hexex_result may hold, read with hexex_result_get(). Which ones a result has
 *  depends on the call that made it (listed per value); numbers never change meaning, new
 *  ones are added at the end. Counts are exact in a double up to 2^53. */
typedef enum hexex_value {
    /* Any result with a mesh: extraction, validation, untangling. */
    HEXEX_VALUE_VALID_ALL_HEX = 0,          /**< 1 if every cell is a hex and the mesh (extraction: the map) is valid, else 0 */
    HEXEX_VALUE_VERTICES = 1,               /**< vertices of the hex mesh */
    HEXEX_VALUE_HEXES = 2,                  /**< hexahedra */
    HEXEX_VALUE_NON_HEX_CELLS = 3,          /**< cells that are not hexahedra (polyhedra) */
    HEXEX_VALUE_QUADS = 4,                  /**< distinct quads (extraction, validation) */
    HEXEX_VALUE_BOUNDARY_QUADS = 5,         /**< quads of exactly one cell (extraction, validation) */
    HEXEX_VALUE_INVERTED_HEXES = 6,         /**< hexes with a corner Jacobian <= 0 */
    HEXEX_VALUE_MIN_SCALED_JACOBIAN = 7,    /**< minimum scaled Jacobian over the hexes (0 without hexes) */
    HEXEX_VALUE_MEAN_SCALED_JACOBIAN = 8,   /**< mean scaled Jacobian over the hexes (0 without hexes) */
    HEXEX_VALUE_INVALID_HEXES = 9,          /**< hexes certified to have a non-positive Jacobian somewhere inside (HexEx::hexValidity()) */
    HEXEX_VALUE_UNDECIDED_HEXES = 10,       /**< hexes the certified validity test left undecided */
    /* Extraction (hexex_extract()). */
    HEXEX_VALUE_INPUT_VERTICES = 20,        /**< tet-mesh vertices */
    HEXEX_VALUE_INPUT_TETS = 21,            /**< tets */
    HEXEX_VALUE_FLIPPED_TETS = 22,          /**< tets with negative parametric volume */
    HEXEX_VALUE_DEGENERATE_TETS = 23,       /**< tets with zero parametric volume */
    HEXEX_VALUE_SINGULAR_EDGES = 24,        /**< interior edges whose holonomy is not the identity */
    HEXEX_VALUE_SINGULAR_VERTICES = 25,     /**< vertices on a number of singular edges other than 0 or 2 */
    HEXEX_VALUE_PARAMETRIC_VOLUME = 26,     /**< sum of the signed parametric tet volumes */
    HEXEX_VALUE_EXTRACTED_DARTS = 27,       /**< darts extracted (regular and anti) */
    HEXEX_VALUE_ANTI_DARTS = 28,            /**< anti darts (from flipped tets) */
    HEXEX_VALUE_UNCONNECTED_DARTS = 29,     /**< missing dart links in the final map */
    HEXEX_VALUE_THREADS = 30,               /**< worker threads used */
    HEXEX_VALUE_SECONDS = 31,               /**< wall-clock seconds of the extraction */
    /* Validation (hexex_validate()). */
    HEXEX_VALUE_CELLS = 40,                 /**< hexes + polyhedra */
    HEXEX_VALUE_EDGES = 41,                 /**< distinct edges of all cell faces */
    HEXEX_VALUE_FACES = 42,                 /**< distinct faces of all cells */
    HEXEX_VALUE_BOUNDARY_FACES = 43,        /**< faces of any size of exactly one cell */
    HEXEX_VALUE_FACES_SHARED_BY_MORE_THAN_TWO = 44, /**< faces of three or more cells */
    HEXEX_VALUE_NONMANIFOLD_BOUNDARY_EDGES = 45,    /**< boundary edges not in exactly two boundary faces */
    HEXEX_VALUE_NONMANIFOLD_BOUNDARY_VERTICES = 46, /**< boundary vertices whose boundary faces form more than one fan */
    HEXEX_VALUE_INVALID_CELLS = 47,         /**< cells with an out-of-range or repeated vertex index (skipped) */
    HEXEX_VALUE_EULER_CHARACTERISTIC = 48,  /**< V - E + F - C */
    /* Untangling (hexex_untangle(), hexex_result_untangle()). */
    HEXEX_VALUE_UNTANGLE_SUCCESS = 60,              /**< 1 if every hex is certified valid afterwards (no invalid or undecided hex), else 0 */
    HEXEX_VALUE_UNTANGLE_INVERTED_BEFORE = 61,      /**< inverted hexes before */
    HEXEX_VALUE_UNTANGLE_INVERTED_AFTER = 62,       /**< inverted hexes after */
    HEXEX_VALUE_UNTANGLE_MIN_SCALED_JACOBIAN_BEFORE = 63, /**< minimum scaled Jacobian before */
    HEXEX_VALUE_UNTANGLE_MIN_SCALED_JACOBIAN_AFTER = 64,  /**< minimum scaled Jacobian after */
    HEXEX_VALUE_UNTANGLE_MOVED_VERTICES = 65,       /**< vertices whose position changed */
    HEXEX_VALUE_UNTANGLE_MAX_DISPLACEMENT = 66,     /**< largest displacement / bounding-box diagonal */
    HEXEX_VALUE_UNTANGLE_SECONDS = 67,              /**< wall-clock seconds of the untangling */
    HEXEX_VALUE_UNTANGLE_INVALID_BEFORE = 68,       /**< hexes not certified valid (invalid) before */
    HEXEX_VALUE_UNTANGLE_INVALID_AFTER = 69,        /**< and after */
    /* Optimisation (hexex_optimize(), hexex_result_optimize()). */
    HEXEX_VALUE_OPTIMIZE_SUCCESS = 80,              /**< 1 if the input was accepted (no inverted hex), else 0 */
    HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_BEFORE = 81,  /**< worst scaled Jacobian before */
    HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_AFTER = 82,   /**< worst scaled Jacobian after (never lower) */
    HEXEX_VALUE_OPTIMIZE_MEAN_SCALED_JACOBIAN_BEFORE = 83, /**< mean scaled Jacobian before */
    HEXEX_VALUE_OPTIMIZE_MEAN_SCALED_JACOBIAN_AFTER = 84,  /**< mean scaled Jacobian after */
    HEXEX_VALUE_OPTIMIZE_REACHED_TARGET = 85,       /**< 1 if the worst scaled Jacobian reached the target */
    HEXEX_VALUE_OPTIMIZE_INVALID_AFTER = 86,        /**< hexes not certified valid afterwards */
    HEXEX_VALUE_OPTIMIZE_MAX_SURFACE_DISTANCE = 87, /**< largest distance of a boundary vertex to the surface */
    HEXEX_VALUE_OPTIMIZE_SECONDS = 88,              /**< wall-clock seconds of the optimisation */
    HEXEX_VALUE_OPTIMIZE_PILLOWED_HEXES = 89,       /**< hexes added by the boundary layer (`pillow`; since version 3) */
    HEXEX_VALUE_OPTIMIZE_TRIMMED_HEXES = 90         /**< hexes of a flap outside the surface removed before the layer (`pillow`; since version 3) */
} hexex_value;

/** Options of hexex_extract(); set the defaults with hexex_extraction_options_init(). The
 *  fields mirror HexEx::ExtractionOptions. Boolean fields are 0 (off) or non-zero (on). */
typedef struct hexex_extraction_options {
    size_t size;                 /**< sizeof(hexex_extraction_options), set by the init function */
    int threads;                 /**< worker threads, 0 = all hardware threads (default 0); the output does not depend on it */
    double epsilon;              /**< parameter coordinates this close to an integer are snapped (default 1e-6; must be in [0, 0.5)) */
    int merge;                   /**< annihilate regular/anti dart pairs (default 1) */
    int implicit_cells;          /**< build cells strictly inside one tet from the grid (default 1; same output) */
    int cheap_folds;             /**< skip the darts of grid points of simple folds (default 1) */
    int annihilation_retries;    /**< retry the annihilation where it left broken cells (default 1) */
    double max_hexes;            /**< refuse maps with a larger parametric volume (default 4e7) */
    uint64_t max_memory;         /**< memory budget in bytes, 0 = half of the available memory (default 0) */
    /** Optional given transitions, 4 per tet: `given_rotations[4*t+i]` (0..23, 0 = identity)
     *  maps the chart of tet t into its neighbour's across the face opposite corner i
     *  (HexEx::ExtractionOptions::given_rotations); NULL (default) infers them from the parameters. */
    const int32_t* given_rotations;
} hexex_extraction_options;

/** Options of hexex_untangle() and hexex_result_untangle(); set the defaults with
 *  hexex_untangle_options_init(). The fields mirror HexEx::UntangleOptions. */
typedef struct hexex_untangle_options {
    size_t size;                /**< sizeof(hexex_untangle_options), set by the init function */
    int threads;                /**< worker threads, 0 = all (default 0); the result does not depend on it */
    int fixed_boundary;         /**< non-zero: boundary vertices stay; 0: they slide on the boundary surface (default 0) */
    int rings;                  /**< hex rings around inverted hexes whose vertices move at first (default 1, >= 1) */
    int max_outer_iterations;   /**< regularisation steps per attempt (default 60, >= 1) */
    int max_lbfgs_iterations;   /**< L-BFGS iterations per regularisation step (default 300, >= 1) */
    int quality_iterations;     /**< L-BFGS iterations raising the worst scaled Jacobian afterwards (default 10, 0 = off) */
    double feature_angle_deg;   /**< boundary edges with a larger normal angle are feature curves (default 40) */
    int release_features;       /**< let feature vertices slide if hexes stay inverted (default 1) */
    /** Optional boundary surface (3 doubles per point) the boundary vertices stay on; NULL
     *  (default): the boundary of the hex mesh itself. */
    const double* surface_points;
    int64_t n_surface_points;          /**< points in surface_points */
    const int32_t* surface_triangles;  /**< 3 point indices per triangle (with surface_points) */
    int64_t n_surface_triangles;       /**< triangles in surface_triangles */
} hexex_untangle_options;

/** Options of hexex_optimize() and hexex_result_optimize(); set the defaults with
 *  hexex_optimize_options_init(). The fields mirror HexEx::OptimizeOptions. */
typedef struct hexex_optimize_options {
    size_t size;                /**< sizeof(hexex_optimize_options), set by the init function */
    int threads;                /**< worker threads, 0 = all (default 0); the result does not depend on it */
    int fixed_boundary;         /**< non-zero: boundary vertices stay; 0: they slide on the surface (default 0) */
    double target;              /**< stop once the worst scaled Jacobian reaches this (default 0.9, in (-1, 1]) */
    double feature_angle_deg;   /**< surface edges sharper than this are feature curves (default 40) */
    int max_global_blocks;      /**< L-BFGS blocks of the global phase at most (default 40, 0 = none) */
    int max_local_passes;       /**< vertex-by-vertex passes at most (default 60, 0 = none) */
    /** Optional boundary surface (3 doubles per point) the boundary vertices stay on; NULL
     *  (default): the boundary of the hex mesh itself. */
    const double* surface_points;
    int64_t n_surface_points;          /**< points in surface_points */
    const int32_t* surface_triangles;  /**< 3 point indices per triangle (with surface_points) */
    int64_t n_surface_triangles;       /**< triangles in surface_triangles */
    /** Since HEXEX_C_API_VERSION 2. Non-zero: first insert a layer of hexes along the
     *  boundary (one per boundary quad, HexEx::OptimizeOptions::pillow); the mesh then has
     *  more hexes and vertices, so only hexex_result_optimize() accepts it (its arrays are
     *  replaced: fetch the pointers again). Default 0. */
    int pillow;
} hexex_optimize_options;

/** Opaque result of a call: a hex mesh as flat arrays, values, a JSON report, or an error. */
typedef struct hexex_result hexex_result;

/** The library version, "x.y.z" (a static string). */
HEXEX_C_API const char* hexex_version(void);

/** HEXEX_C_API_VERSION of the library that is loaded (compare with the header's). */
HEXEX_C_API int hexex_c_api_version(void);

/** A static English description of @p status, e.g. "invalid argument". */
HEXEX_C_API const char* hexex_status_string(hexex_status status);

/** Fills @p options with the defaults (does nothing if @p options is NULL). */
HEXEX_C_API void hexex_extraction_options_init(hexex_extraction_options* options);

/** Fills @p options with the defaults (does nothing if @p options is NULL). */
HEXEX_C_API void hexex_untangle_options_init(hexex_untangle_options* options);

/** Fills @p options with the defaults (does nothing if @p options is NULL). */
HEXEX_C_API void hexex_optimize_options_init(hexex_optimize_options* options);

/** Extracts the hex mesh of a tet mesh with an integer-grid map.
 *  @param points   3 doubles (x, y, z) per vertex
 *  @param n_points number of vertices
 *  @param tets     4 vertex indices (0-based) per tet; tets should be positively oriented
 *  @param n_tets   number of tets
 *  @param params   12 doubles per tet: the parameters (u, v, w) of its 4 corners, each in
 *                  the tet's own chart (so maps with seams are given directly)
 *  @param options  NULL for the defaults
 *  @param result   receives the result (free it with hexex_result_free())
 *  @return HEXEX_OK, or HEXEX_ERROR_INPUT for unusable input (the message names the tet,
 *  e.g. "tet 3: vertex index 9 out of range (the mesh has 8 vertices)"). A map with
 *  defects is not an error: the cells that are not hexes come back as polyhedra and the
 *  report counts what could not be resolved. */
HEXEX_C_API hexex_status hexex_extract(const double* points, int64_t n_points, const int32_t* tets, int64_t n_tets,
                                       const double* params, const hexex_extraction_options* options,
                                       hexex_result** result);

/** hexex_extract() with 64-bit vertex indices. */
HEXEX_C_API hexex_status hexex_extract64(const double* points, int64_t n_points, const int64_t* tets, int64_t n_tets,
                                         const double* params, const hexex_extraction_options* options,
                                         hexex_result** result);

/** Checks a hex mesh (HexEx::checkHexMesh()): face sharing, closed 2-manifold boundary,
 *  Euler characteristic and hex quality. The result holds the HEXEX_VALUE_* counts of
 *  validation and a JSON report with the keys of `hexex validate --json`, but no mesh.
 *  An out-of-range index is not an error here: such cells are counted in
 *  HEXEX_VALUE_INVALID_CELLS.
 *  @param points   3 doubles per vertex
 *  @param n_points number of vertices
 *  @param hexes    8 vertex indices per hex, VTK order
 *  @param n_hexes  number of hexes
 *  @param result   receives the result */
HEXEX_C_API hexex_status hexex_validate(const double* points, int64_t n_points, const int32_t* hexes, int64_t n_hexes,
                                        hexex_result** result);

/** Untangles a hex mesh in place (HexEx::untangleHexMesh()): moves vertices, changing the
 *  mesh only near inverted hexes, so that every hex has positive corner Jacobians.
 *  @param points   3 doubles per vertex, overwritten with the new positions
 *  @param n_points number of vertices
 *  @param hexes    8 vertex indices per hex, VTK order
 *  @param n_hexes  number of hexes
 *  @param options  NULL for the defaults
 *  @param result   receives the report (HEXEX_VALUE_UNTANGLE_* and the quality values,
 *                  JSON with the field names of HexEx::UntangleReport), no mesh
 *  @return HEXEX_OK also when hexes remain inverted (see HEXEX_VALUE_UNTANGLE_SUCCESS);
 *  HEXEX_ERROR_INPUT for an index out of range (points are then unchanged). */
HEXEX_C_API hexex_status hexex_untangle(double* points, int64_t n_points, const int32_t* hexes, int64_t n_hexes,
                                        const hexex_untangle_options* options, hexex_result** result);

/** Untangles the mesh held by @p result (e.g. from hexex_extract()) in place; vertices of
 *  polyhedra do not move. Adds the HEXEX_VALUE_UNTANGLE_* values, updates the quality
 *  values and adds the key "untangle" to the JSON report. Pointers obtained from the
 *  result before stay valid (the arrays keep their size).
 *  @return HEXEX_OK (also when hexes remain inverted), HEXEX_ERROR_INVALID_ARGUMENT if
 *  @p result is NULL, failed or bad options were given; the error is also stored in
 *  @p result (its mesh is then unchanged). */
HEXEX_C_API hexex_status hexex_result_untangle(hexex_result* result, const hexex_untangle_options* options);

/** Raises the worst scaled Jacobian of a hex mesh in place (HexEx::optimizeHexMesh()): every
 *  accepted step keeps every hex certified valid and never lowers the worst scaled Jacobian;
 *  boundary vertices stay on the surface, feature curves and corners are kept.
 *  @param points   3 doubles per vertex, overwritten with the new positions
 *  @param n_points number of vertices
 *  @param hexes    8 vertex indices per hex, VTK order
 *  @param n_hexes  number of hexes
 *  @param options  NULL for the defaults
 *  @param result   receives the report (HEXEX_VALUE_OPTIMIZE_* and the quality values, JSON
 *                  with the field names of HexEx::OptimizeReport), no mesh
 *  @return HEXEX_OK also when the input is refused because a hex is inverted (then
 *  HEXEX_VALUE_OPTIMIZE_SUCCESS is 0, the points are unchanged and
 *  hexex_result_error_message() is empty; the JSON's "message" says why: untangle first);
 *  HEXEX_ERROR_INPUT for an index out of range (points unchanged). */
HEXEX_C_API hexex_status hexex_optimize(double* points, int64_t n_points, const int32_t* hexes, int64_t n_hexes,
                                        const hexex_optimize_options* options, hexex_result** result);

/** Optimises the mesh held by @p result (e.g. from hexex_extract(), after
 *  hexex_result_untangle() if it has inverted hexes) in place; vertices of polyhedra do not
 *  move. Adds the HEXEX_VALUE_OPTIMIZE_* values, updates the quality values and adds the
 *  key "optimize" to the JSON report of an extraction. Pointers obtained before stay valid.
 *  @return as hexex_result_untangle(). */
HEXEX_C_API hexex_status hexex_result_optimize(hexex_result* result, const hexex_optimize_options* options);

/** Frees @p result and all arrays it owns (NULL is allowed). */
HEXEX_C_API void hexex_result_free(hexex_result* result);

/** Status of the call that made @p result (or of the last hexex_result_untangle() on it);
 *  HEXEX_ERROR_RESOURCE for NULL. */
HEXEX_C_API hexex_status hexex_result_status(const hexex_result* result);

/** The error message of @p result, "" on success; for NULL, the text of HEXEX_ERROR_RESOURCE.
 *  Owned by @p result. */
HEXEX_C_API const char* hexex_result_error_message(const hexex_result* result);

/** Reads value @p key of @p result into @p *out.
 *  @return HEXEX_OK, or HEXEX_ERROR_INVALID_ARGUMENT (and @p *out unchanged) if @p result
 *  or @p out is NULL or the result has no such value. */
HEXEX_C_API hexex_status hexex_result_get(const hexex_result* result, hexex_value key, double* out);

/** The report as a JSON document: for an extraction the `--report` file of `hexex extract`
 *  (Documentation/cli.md), for a validation the output of `hexex validate --json`. Owned
 *  by @p result; "" for NULL or a failed call. */
HEXEX_C_API const char* hexex_result_report_json(const hexex_result* result);

/** Number of vertices of the result's mesh (0 for NULL and for results without a mesh:
 *  validation, hexex_untangle(), a failed extraction). */
HEXEX_C_API int64_t hexex_result_n_vertices(const hexex_result* result);

/** The vertex positions, 3 doubles per vertex; NULL if there are none. */
HEXEX_C_API const double* hexex_result_vertices(const hexex_result* result);

/** Number of hexahedra of the result's mesh. */
HEXEX_C_API int64_t hexex_result_n_hexes(const hexex_result* result);

/** The hexahedra, 8 vertex indices each in VTK order (bottom quad 0-1-2-3 counter-clockwise
 *  seen from the top quad 4-5-6-7, vertex 4 above vertex 0); NULL if there are none. */
HEXEX_C_API const int32_t* hexex_result_hexes(const hexex_result* result);

/** Number of polyhedra (cells that are not hexahedra) of the result's mesh. */
HEXEX_C_API int64_t hexex_result_n_polyhedra(const hexex_result* result);

/** Polyhedra as compressed arrays: the faces of polyhedron p are
 *  `face_offsets[p] .. face_offsets[p+1]-1`, the vertices of face f (an outward-oriented
 *  loop) are `vertices[vertex_offsets[f] .. vertex_offsets[f+1]-1]`. Each pointer may be
 *  NULL if not wanted; the arrays have n_polyhedra + 1, n_faces + 1 and
 *  vertex_offsets[n_faces] entries, where n_faces = face_offsets[n_polyhedra]. They are
 *  NULL when there are no polyhedra. */
HEXEX_C_API void hexex_result_polyhedra(const hexex_result* result, const int64_t** face_offsets,
                                        const int64_t** vertex_offsets, const int32_t** vertices);

#ifdef __cplusplus
} /* extern "C" */
#endif

/** @} */

#endif /* HEXEX_H */
