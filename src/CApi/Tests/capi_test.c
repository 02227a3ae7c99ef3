/* capi_test.c: the C API (hexex.h) from a C99 program. Extracts a generated cube and the
 * bundled Examples/data/sphere.hexex (path in argv[1]), checks the counts, the errors and
 * their messages, validation and untangling. Exits 0 only if every check passes. */

#include <hexex.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <stddef.h>
#include <string.h>

static int failures = 0;

/* Counts a failed check and prints where it was. */
#define CHECK(cond)                                                        \
    do {                                                                   \
        if (!(cond)) {                                                     \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                    \
        }                                                                  \
    } while (0)

/* Value @p key of @p r, or NaN (and a failed check) if the result has none. */
static double value(const hexex_result* r, hexex_value key) {
    double v = NAN;
    if (hexex_result_get(r, key, &v) != HEXEX_OK) {
        fprintf(stderr, "value %d missing\n", (int)key);
        ++failures;
    }
    return v;
}

/* Unit cube, vertex i at (i&1, (i>>1)&1, (i>>2)&1), six positive tets around the diagonal
 * 0-7; the map is parameter = 2 * position (2x2x2 hexes). */
static const double cube_points[8 * 3] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
static const int32_t cube_tets[6 * 4] = {0, 1, 3, 7, 0, 5, 1, 7, 0, 3, 2, 7, 0, 2, 6, 7, 0, 4, 5, 7, 0, 6, 4, 7};

static void cube_params(const int32_t* tets, double* params) {
    int t, c, k;
    for (t = 0; t < 6; ++t)
        for (c = 0; c < 4; ++c)
            for (k = 0; k < 3; ++k) params[12 * t + 3 * c + k] = 2.0 * cube_points[3 * tets[4 * t + c] + k];
}

static void test_version(void) {
    CHECK(strlen(hexex_version()) >= 5);
    CHECK(hexex_c_api_version() == HEXEX_C_API_VERSION);
    CHECK(strcmp(hexex_status_string(HEXEX_ERROR_INPUT), "unusable input mesh") == 0);
}

static void test_cube(void) {
    double params[6 * 12];
    int64_t tets64[6 * 4];
    hexex_result* r = NULL;
    hexex_result* r64 = NULL;
    hexex_result* v = NULL;
    int i;
    cube_params(cube_tets, params);
    CHECK(hexex_extract(cube_points, 8, cube_tets, 6, params, NULL, &r) == HEXEX_OK);
    CHECK(hexex_result_status(r) == HEXEX_OK);
    CHECK(strcmp(hexex_result_error_message(r), "") == 0);
    CHECK(hexex_result_n_vertices(r) == 27);
    CHECK(hexex_result_n_hexes(r) == 8);
    CHECK(hexex_result_n_polyhedra(r) == 0);
    CHECK(value(r, HEXEX_VALUE_VALID_ALL_HEX) == 1);
    CHECK(value(r, HEXEX_VALUE_HEXES) == 8);
    CHECK(value(r, HEXEX_VALUE_VERTICES) == 27);
    CHECK(value(r, HEXEX_VALUE_INPUT_TETS) == 6);
    CHECK(value(r, HEXEX_VALUE_FLIPPED_TETS) == 0);
    CHECK(value(r, HEXEX_VALUE_BOUNDARY_QUADS) == 24);
    CHECK(value(r, HEXEX_VALUE_INVERTED_HEXES) == 0);
    CHECK(value(r, HEXEX_VALUE_INVALID_HEXES) == 0);
    CHECK(value(r, HEXEX_VALUE_UNDECIDED_HEXES) == 0);
    CHECK(fabs(value(r, HEXEX_VALUE_MIN_SCALED_JACOBIAN) - 1.0) < 1e-12);
    CHECK(fabs(value(r, HEXEX_VALUE_PARAMETRIC_VOLUME) - 8.0) < 1e-12);
    CHECK(strstr(hexex_result_report_json(r), "\"valid_all_hex\": true") != NULL);
    {
        double unused = -1;
        CHECK(hexex_result_get(r, HEXEX_VALUE_EULER_CHARACTERISTIC, &unused) == HEXEX_ERROR_INVALID_ARGUMENT);
        CHECK(unused == -1);
    }
    /* Every vertex is a point of the grid {0, 0.5, 1}^3. */
    for (i = 0; i < 27 * 3; ++i) {
        const double x = hexex_result_vertices(r)[i];
        CHECK(x == 0 || x == 0.5 || x == 1);
    }

    /* Given transitions (all the identity, as the map is seamless) give the same mesh. */
    {
        int32_t rotations[6 * 4] = {0};
        hexex_extraction_options opt;
        hexex_extraction_options_init(&opt);
        opt.given_rotations = rotations;
        CHECK(hexex_extract(cube_points, 8, cube_tets, 6, params, &opt, &r64) == HEXEX_OK);
        CHECK(hexex_result_n_hexes(r64) == 8 && hexex_result_n_vertices(r64) == 27);
        CHECK(value(r64, HEXEX_VALUE_VALID_ALL_HEX) == 1);
        hexex_result_free(r64);
        r64 = NULL;
    }

    /* The 64-bit entry point gives the same arrays. */
    for (i = 0; i < 24; ++i) tets64[i] = cube_tets[i];
    CHECK(hexex_extract64(cube_points, 8, tets64, 6, params, NULL, &r64) == HEXEX_OK);
    CHECK(hexex_result_n_hexes(r64) == 8);
    CHECK(memcmp(hexex_result_hexes(r), hexex_result_hexes(r64), 8 * 8 * sizeof(int32_t)) == 0);
    CHECK(memcmp(hexex_result_vertices(r), hexex_result_vertices(r64), 27 * 3 * sizeof(double)) == 0);

    /* Validation of the extracted mesh: 54 edges, 36 quads, Euler characteristic 1 (a ball). */
    CHECK(hexex_validate(hexex_result_vertices(r), 27, hexex_result_hexes(r), 8, &v) == HEXEX_OK);
    CHECK(value(v, HEXEX_VALUE_VALID_ALL_HEX) == 1);
    CHECK(value(v, HEXEX_VALUE_CELLS) == 8);
    CHECK(value(v, HEXEX_VALUE_EDGES) == 54);
    CHECK(value(v, HEXEX_VALUE_QUADS) == 36);
    CHECK(value(v, HEXEX_VALUE_BOUNDARY_QUADS) == 24);
    CHECK(value(v, HEXEX_VALUE_EULER_CHARACTERISTIC) == 1);
    CHECK(value(v, HEXEX_VALUE_INVALID_CELLS) == 0);
    CHECK(hexex_result_n_vertices(v) == 0);
    CHECK(strstr(hexex_result_report_json(v), "\"euler_characteristic\": 1,") != NULL);
    hexex_result_free(v);

    /* A hex with an index out of range is counted, not an error. */
    {
        int32_t bad[16];
        memcpy(bad, hexex_result_hexes(r), 16 * sizeof(int32_t));
        bad[9] = 27;
        CHECK(hexex_validate(hexex_result_vertices(r), 27, bad, 2, &v) == HEXEX_OK);
        CHECK(value(v, HEXEX_VALUE_INVALID_CELLS) == 1);
        CHECK(value(v, HEXEX_VALUE_VALID_ALL_HEX) == 0);
        hexex_result_free(v);
    }
    hexex_result_free(r64);
    hexex_result_free(r);
}

static void test_errors(void) {
    double params[6 * 12];
    int32_t bad[6 * 4];
    hexex_result* r = NULL;
    hexex_extraction_options opt;
    cube_params(cube_tets, params);
    memcpy(bad, cube_tets, sizeof bad);
    bad[4 * 3 + 2] = 9;
    CHECK(hexex_extract(cube_points, 8, bad, 6, params, NULL, &r) == HEXEX_ERROR_INPUT);
    CHECK(hexex_result_status(r) == HEXEX_ERROR_INPUT);
    CHECK(strcmp(hexex_result_error_message(r), "tet 3: vertex index 9 out of range (the mesh has 8 vertices)") == 0);
    CHECK(hexex_result_n_hexes(r) == 0);
    CHECK(hexex_result_hexes(r) == NULL);
    CHECK(strcmp(hexex_result_report_json(r), "") == 0);
    hexex_result_free(r);

    bad[4 * 3 + 2] = -1;
    CHECK(hexex_extract(cube_points, 8, bad, 6, params, NULL, &r) == HEXEX_ERROR_INPUT);
    CHECK(strcmp(hexex_result_error_message(r), "tet 3: vertex index -1 out of range (the mesh has 8 vertices)") == 0);
    hexex_result_free(r);

    bad[4 * 3 + 2] = bad[4 * 3 + 1];
    CHECK(hexex_extract(cube_points, 8, bad, 6, params, NULL, &r) == HEXEX_ERROR_INPUT);
    CHECK(strcmp(hexex_result_error_message(r), "tet 3: vertex 2 appears twice") == 0);
    hexex_result_free(r);

    CHECK(hexex_extract(NULL, 8, cube_tets, 6, params, NULL, &r) == HEXEX_ERROR_INVALID_ARGUMENT);
    CHECK(strcmp(hexex_result_error_message(r), "points is NULL but its count is 8") == 0);
    hexex_result_free(r);

    CHECK(hexex_extract(cube_points, 8, cube_tets, -6, params, NULL, &r) == HEXEX_ERROR_INVALID_ARGUMENT);
    CHECK(strcmp(hexex_result_error_message(r), "tets: negative count -6") == 0);
    hexex_result_free(r);

    CHECK(hexex_extract(cube_points, 8, cube_tets, 6, params, NULL, NULL) == HEXEX_ERROR_INVALID_ARGUMENT);

    hexex_extraction_options_init(&opt);
    CHECK(opt.size == sizeof opt);
    CHECK(opt.threads == 0 && opt.merge == 1 && opt.epsilon == 1e-6 && opt.given_rotations == NULL);
    opt.threads = -2;
    CHECK(hexex_extract(cube_points, 8, cube_tets, 6, params, &opt, &r) == HEXEX_ERROR_INVALID_ARGUMENT);
    CHECK(strcmp(hexex_result_error_message(r), "options: threads must be >= 0 (0 = all hardware threads), got -2") == 0);
    hexex_result_free(r);

    memset(&opt, 0, sizeof opt); /* size not set */
    CHECK(hexex_extract(cube_points, 8, cube_tets, 6, params, &opt, &r) == HEXEX_ERROR_INVALID_ARGUMENT);
    CHECK(strstr(hexex_result_error_message(r), "initialise the options") != NULL);
    hexex_result_free(r);

    params[5] = NAN;
    CHECK(hexex_extract(cube_points, 8, cube_tets, 6, params, NULL, &r) == HEXEX_ERROR_INPUT);
    CHECK(strlen(hexex_result_error_message(r)) > 0);
    hexex_result_free(r);

    CHECK(hexex_result_status(NULL) == HEXEX_ERROR_RESOURCE);
    CHECK(hexex_result_n_hexes(NULL) == 0);
    hexex_result_free(NULL);
}

/* The 2x2x2 grid of unit hexes, the centre vertex (1,1,1) pushed to (1.8,1.8,1.8): untangling
 * with a fixed boundary moves it back inside its eight hexes. The corner Jacobian of the
 * hex [1,2]^3 at the centre is then negative. */
static void test_untangle(void) {
    double points[27 * 3];
    int32_t hexes[8 * 8];
    hexex_result* r = NULL;
    hexex_untangle_options opt;
    int x, y, z, i, n = 0;
    static const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (z = 0; z < 3; ++z)
        for (y = 0; y < 3; ++y)
            for (x = 0; x < 3; ++x) {
                points[3 * (x + 3 * y + 9 * z) + 0] = x;
                points[3 * (x + 3 * y + 9 * z) + 1] = y;
                points[3 * (x + 3 * y + 9 * z) + 2] = z;
            }
    for (z = 0; z < 2; ++z)
        for (y = 0; y < 2; ++y)
            for (x = 0; x < 2; ++x, ++n)
                for (i = 0; i < 8; ++i)
                    hexes[8 * n + i] = (x + corner[i][0]) + 3 * (y + corner[i][1]) + 9 * (z + corner[i][2]);
    points[3 * 13 + 0] = points[3 * 13 + 1] = points[3 * 13 + 2] = 1.8;

    /* Validation sees the inverted hex, by its corners and by the certified test. */
    CHECK(hexex_validate(points, 27, hexes, 8, &r) == HEXEX_OK);
    CHECK(value(r, HEXEX_VALUE_INVERTED_HEXES) == 1);
    CHECK(value(r, HEXEX_VALUE_INVALID_HEXES) == 1);
    CHECK(value(r, HEXEX_VALUE_VALID_ALL_HEX) == 1); /* topology only: element quality does not count */
    hexex_result_free(r);

    hexex_untangle_options_init(&opt);
    CHECK(opt.size == sizeof opt && opt.rings == 1 && opt.fixed_boundary == 0);
    opt.fixed_boundary = 1;
    opt.threads = 1;
    CHECK(hexex_untangle(points, 27, hexes, 8, &opt, &r) == HEXEX_OK);
    CHECK(value(r, HEXEX_VALUE_UNTANGLE_INVERTED_BEFORE) == 1); /* the hex [1,2]^3 */
    CHECK(value(r, HEXEX_VALUE_UNTANGLE_MIN_SCALED_JACOBIAN_BEFORE) < 0);
    CHECK(value(r, HEXEX_VALUE_UNTANGLE_INVERTED_AFTER) == 0);
    CHECK(value(r, HEXEX_VALUE_UNTANGLE_INVALID_BEFORE) == 1);
    CHECK(value(r, HEXEX_VALUE_UNTANGLE_INVALID_AFTER) == 0);
    CHECK(value(r, HEXEX_VALUE_UNTANGLE_SUCCESS) == 1);
    CHECK(value(r, HEXEX_VALUE_INVERTED_HEXES) == 0);
    CHECK(value(r, HEXEX_VALUE_INVALID_HEXES) == 0);
    CHECK(value(r, HEXEX_VALUE_UNTANGLE_MOVED_VERTICES) == 1);
    CHECK(value(r, HEXEX_VALUE_MIN_SCALED_JACOBIAN) > 0);
    CHECK(strstr(hexex_result_report_json(r), "\"inverted_after\": 0,") != NULL);
    /* Only the centre moved, back inside the cube (0,2)^3; the corners stayed. */
    for (i = 0; i < 3; ++i) CHECK(points[3 * 13 + i] > 0.5 && points[3 * 13 + i] < 1.5);
    CHECK(points[3 * 26 + 0] == 2 && points[3 * 26 + 1] == 2 && points[3 * 26 + 2] == 2);
    hexex_result_free(r);

    /* A hex with an index out of range: an input error, the points unchanged. */
    points[0] = 0.25;
    hexex_untangle_options_init(&opt);
    hexes[3] = 99;
    CHECK(hexex_untangle(points, 27, hexes, 8, &opt, &r) == HEXEX_ERROR_INPUT);
    CHECK(strstr(hexex_result_error_message(r), "99") != NULL);
    CHECK(points[0] == 0.25);
    hexex_result_free(r);

    opt.rings = 0;
    CHECK(hexex_untangle(points, 27, hexes, 8, &opt, &r) == HEXEX_ERROR_INVALID_ARGUMENT);
    CHECK(strcmp(hexex_result_error_message(r), "untangle options: rings must be >= 1, got 0") == 0);
    hexex_result_free(r);
}

/* The optimiser on a 3x3x3 grid whose centre vertex was moved: the worst scaled Jacobian
 * rises, every hex stays certified valid, the boundary (fixed) does not move. */
static void test_optimize(void) {
    double points[64 * 3], before[64 * 3];
    int32_t hexes[27 * 8];
    hexex_result* r = NULL;
    hexex_optimize_options opt;
    int x, y, z, i, n = 0;
    static const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (z = 0; z < 4; ++z)
        for (y = 0; y < 4; ++y)
            for (x = 0; x < 4; ++x) {
                points[3 * (x + 4 * y + 16 * z) + 0] = x;
                points[3 * (x + 4 * y + 16 * z) + 1] = y;
                points[3 * (x + 4 * y + 16 * z) + 2] = z;
            }
    for (z = 0; z < 3; ++z)
        for (y = 0; y < 3; ++y)
            for (x = 0; x < 3; ++x, ++n)
                for (i = 0; i < 8; ++i)
                    hexes[8 * n + i] = (x + corner[i][0]) + 4 * (y + corner[i][1]) + 16 * (z + corner[i][2]);
    /* Interior vertices (1,1,1) .. (2,2,2): pull two of them towards each other. */
    points[3 * (1 + 4 * 1 + 16 * 1) + 0] = 1.3;
    points[3 * (1 + 4 * 1 + 16 * 1) + 1] = 1.25;
    points[3 * (2 + 4 * 2 + 16 * 2) + 2] = 1.75;
    for (i = 0; i < 64 * 3; ++i) before[i] = points[i];

    hexex_optimize_options_init(&opt);
    CHECK(opt.size == sizeof opt && opt.target == 0.9 && opt.fixed_boundary == 0);
    opt.fixed_boundary = 1;
    opt.threads = 1;
    CHECK(hexex_optimize(points, 64, hexes, 27, &opt, &r) == HEXEX_OK);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_SUCCESS) == 1);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_BEFORE) > 0);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_AFTER) >
          value(r, HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_BEFORE) + 0.1);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_INVALID_AFTER) == 0);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_PILLOWED_HEXES) == 0 && value(r, HEXEX_VALUE_OPTIMIZE_TRIMMED_HEXES) == 0);
    CHECK(value(r, HEXEX_VALUE_INVALID_HEXES) == 0);
    CHECK(value(r, HEXEX_VALUE_MIN_SCALED_JACOBIAN) == value(r, HEXEX_VALUE_OPTIMIZE_MIN_SCALED_JACOBIAN_AFTER));
    CHECK(strstr(hexex_result_report_json(r), "\"min_scaled_jacobian_after\"") != NULL);
    /* Boundary vertices (a coordinate 0 or 3) stayed bit for bit. */
    for (i = 0; i < 64; ++i) {
        const int ix = i % 4, iy = (i / 4) % 4, iz = i / 16;
        if (ix == 0 || ix == 3 || iy == 0 || iy == 3 || iz == 0 || iz == 3)
            CHECK(points[3 * i] == before[3 * i] && points[3 * i + 1] == before[3 * i + 1] &&
                  points[3 * i + 2] == before[3 * i + 2]);
    }
    hexex_result_free(r);

    /* Bad options and indices: clear errors, the points unchanged. */
    hexex_optimize_options_init(&opt);
    opt.target = 2;
    CHECK(hexex_optimize(points, 64, hexes, 27, &opt, &r) == HEXEX_ERROR_INVALID_ARGUMENT);
    CHECK(strcmp(hexex_result_error_message(r), "optimize options: target must be in (-1, 1], got 2") == 0);
    hexex_result_free(r);
    for (i = 0; i < 64 * 3; ++i) before[i] = points[i];
    hexes[5] = 64;
    CHECK(hexex_optimize(points, 64, hexes, 27, NULL, &r) == HEXEX_ERROR_INPUT);
    CHECK(strcmp(hexex_result_error_message(r), "hex 0: vertex index 64 out of range (the mesh has 64 vertices)") == 0);
    for (i = 0; i < 64 * 3; ++i) CHECK(points[i] == before[i]);
    hexex_result_free(r);
    CHECK(hexex_result_optimize(NULL, NULL) == HEXEX_ERROR_INVALID_ARGUMENT);
}

/* Optimisation with a boundary layer (pillow, since HEXEX_C_API_VERSION 2) on the extracted
 * 2x2x2 grid of the cube: 24 boundary quads and 26 boundary vertices give 8 + 24 = 32 hexes
 * and 27 + 26 = 53 vertices; an options struct of the older size ignores the field; the
 * in-place array call refuses it. */
static void test_optimize_pillow(void) {
    double params[6 * 12];
    static const int32_t one_hex[8] = {0, 1, 3, 2, 4, 5, 7, 6};
    double points[8 * 3];
    hexex_result* r = NULL;
    hexex_result* a = NULL;
    hexex_optimize_options opt;
    int i, n_face = 0;
    cube_params(cube_tets, params);
    CHECK(hexex_extract(cube_points, 8, cube_tets, 6, params, NULL, &r) == HEXEX_OK);
    hexex_optimize_options_init(&opt);
    CHECK(opt.pillow == 0);
    opt.pillow = 1;
    opt.size = offsetof(hexex_optimize_options, pillow); /* a caller built against version 1 */
    CHECK(hexex_result_optimize(r, &opt) == HEXEX_OK);
    CHECK(hexex_result_n_hexes(r) == 8 && hexex_result_n_vertices(r) == 27);
    opt.size = sizeof opt;
    opt.threads = 1;
    CHECK(hexex_result_optimize(r, &opt) == HEXEX_OK);
    CHECK(hexex_result_n_hexes(r) == 32);
    CHECK(hexex_result_n_vertices(r) == 53);
    CHECK(value(r, HEXEX_VALUE_HEXES) == 32);
    CHECK(value(r, HEXEX_VALUE_VERTICES) == 53);
    CHECK(value(r, HEXEX_VALUE_BOUNDARY_QUADS) == 24);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_INVALID_AFTER) == 0);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_MAX_SURFACE_DISTANCE) < 1e-12);
    CHECK(value(r, HEXEX_VALUE_MIN_SCALED_JACOBIAN) > 0);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_PILLOWED_HEXES) == 24);
    CHECK(value(r, HEXEX_VALUE_OPTIMIZE_TRIMMED_HEXES) == 0); /* every hex valid: no flap removed */
    CHECK(strstr(hexex_result_report_json(r), "\"pillowed_hexes\": 24") != NULL);
    /* The 26 boundary vertices stay on the faces of the unit cube; the 26 copies are inside. */
    for (i = 0; i < 53; ++i) {
        const double* p = hexex_result_vertices(r) + 3 * i;
        int k, on_face = 0;
        for (k = 0; k < 3; ++k) on_face |= fabs(p[k]) < 1e-12 || fabs(p[k] - 1) < 1e-12;
        if (i < 27) n_face += on_face;
        else CHECK(!on_face && p[0] > 0 && p[0] < 1 && p[1] > 0 && p[1] < 1 && p[2] > 0 && p[2] < 1);
    }
    CHECK(n_face == 26);
    for (i = 0; i < 8 * 3; ++i) points[i] = cube_points[i];
    CHECK(hexex_optimize(points, 8, one_hex, 1, &opt, &a) == HEXEX_ERROR_INVALID_ARGUMENT);
    CHECK(strcmp(hexex_result_error_message(a),
                 "optimize options: pillow adds hexes and vertices, which the caller's arrays cannot hold; use "
                 "hexex_result_optimize() on a result") == 0);
    hexex_result_free(a);
    hexex_result_free(r);
}

/* Reads a .hexex file into flat arrays (returns 0 on failure). */
static int read_hexex(const char* path, double** points, int64_t* n_points, int32_t** tets, double** params,
                      int64_t* n_tets) {
    FILE* f = fopen(path, "r");
    long long nv = 0, nt = 0, i;
    int k, ok = 1;
    if (!f) return 0;
    ok = fscanf(f, "%lld", &nv) == 1 && nv > 0;
    *points = ok ? (double*)malloc((size_t)nv * 3 * sizeof(double)) : NULL;
    for (i = 0; ok && i < 3 * nv; ++i) ok = fscanf(f, "%lf", &(*points)[i]) == 1;
    ok = ok && fscanf(f, "%lld", &nt) == 1 && nt > 0;
    *tets = ok ? (int32_t*)malloc((size_t)nt * 4 * sizeof(int32_t)) : NULL;
    *params = ok ? (double*)malloc((size_t)nt * 12 * sizeof(double)) : NULL;
    for (i = 0; ok && i < nt; ++i) {
        for (k = 0; ok && k < 4; ++k) {
            long idx = 0;
            ok = fscanf(f, "%ld", &idx) == 1;
            (*tets)[4 * i + k] = (int32_t)idx;
        }
        for (k = 0; ok && k < 12; ++k) ok = fscanf(f, "%lf", &(*params)[12 * i + k]) == 1;
    }
    fclose(f);
    *n_points = nv;
    *n_tets = nt;
    return ok;
}

static void test_sphere(const char* path) {
    double *points = NULL, *params = NULL;
    int32_t* tets = NULL;
    int64_t nv = 0, nt = 0;
    hexex_result *r1 = NULL, *r2 = NULL;
    hexex_extraction_options opt;
    const int64_t* face_offsets = (const int64_t*)1;
    if (!read_hexex(path, &points, &nv, &tets, &params, &nt)) {
        fprintf(stderr, "cannot read %s\n", path);
        ++failures;
        return;
    }
    hexex_extraction_options_init(&opt);
    opt.threads = 1;
    CHECK(hexex_extract(points, nv, tets, nt, params, &opt, &r1) == HEXEX_OK);
    opt.threads = 2;
    CHECK(hexex_extract(points, nv, tets, nt, params, &opt, &r2) == HEXEX_OK);
    CHECK(hexex_result_n_hexes(r1) == 216);
    CHECK(hexex_result_n_vertices(r1) == 343);
    CHECK(value(r1, HEXEX_VALUE_VALID_ALL_HEX) == 1);
    CHECK(value(r1, HEXEX_VALUE_INPUT_TETS) == (double)nt);
    CHECK(value(r1, HEXEX_VALUE_THREADS) == 1);
    CHECK(value(r2, HEXEX_VALUE_THREADS) == 2);
    /* Deterministic for any thread count. */
    CHECK(hexex_result_n_hexes(r2) == 216 && hexex_result_n_vertices(r2) == 343);
    if (hexex_result_n_hexes(r2) == 216 && hexex_result_n_vertices(r2) == 343) {
        CHECK(memcmp(hexex_result_hexes(r1), hexex_result_hexes(r2), 216 * 8 * sizeof(int32_t)) == 0);
        CHECK(memcmp(hexex_result_vertices(r1), hexex_result_vertices(r2), 343 * 3 * sizeof(double)) == 0);
    }
    hexex_result_polyhedra(r1, &face_offsets, NULL, NULL);
    CHECK(face_offsets == NULL);
    CHECK(strstr(hexex_result_report_json(r1), "\"hexes\": 216") != NULL);

    /* Untangling the result in place: nothing is inverted, so nothing moves. */
    {
        const double* before = hexex_result_vertices(r1);
        double first = before[0];
        CHECK(hexex_result_untangle(r1, NULL) == HEXEX_OK);
        CHECK(hexex_result_vertices(r1) == before);
        CHECK(before[0] == first);
        CHECK(value(r1, HEXEX_VALUE_UNTANGLE_INVERTED_BEFORE) == 0);
        CHECK(value(r1, HEXEX_VALUE_UNTANGLE_MOVED_VERTICES) == 0);
        CHECK(strstr(hexex_result_report_json(r1), "\"untangle\"") != NULL);
        CHECK(strstr(hexex_result_report_json(r1), "\"hexes\": 216") != NULL);
    }
    hexex_result_free(r1);
    hexex_result_free(r2);
    free(points);
    free(tets);
    free(params);
}

int main(int argc, char** argv) {
    test_version();
    test_cube();
    test_errors();
    test_untangle();
    test_optimize();
    test_optimize_pillow();
    if (argc > 1)
        test_sphere(argv[1]);
    else
        fprintf(stderr, "no .hexex path given: the sphere test is skipped\n");
    if (failures) {
        fprintf(stderr, "%d check(s) failed\n", failures);
        return 1;
    }
    printf("hexex C API %s: all checks passed\n", hexex_version());
    return 0;
}
