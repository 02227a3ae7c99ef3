/* extract.c: the HexEx C API (hexex.h) from C99 against an installed package. Extracts the
 * hex mesh of a unit cube split into six tets with the map "parameter = 2 * position"
 * (2x2x2 hexes), prints the counts and the report, and exits 0 only if there are 8 hexes
 * and 27 vertices. Build: find_package(HexEx) and target_link_libraries(app HexEx::C). */

#include <hexex.h>

#include <stdio.h>

int main(void) {
    /* Vertex i at (i&1, (i>>1)&1, (i>>2)&1); six positively oriented tets around 0-7. */
    static const double points[8 * 3] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
    static const int32_t tets[6 * 4] = {0, 1, 3, 7, 0, 5, 1, 7, 0, 3, 2, 7, 0, 2, 6, 7, 0, 4, 5, 7, 0, 6, 4, 7};
    double params[6 * 12]; /* per tet corner, in the tet's chart */
    hexex_extraction_options opt;
    hexex_result* r = NULL;
    double valid = 0;
    int t, c, k, ok;
    for (t = 0; t < 6; ++t)
        for (c = 0; c < 4; ++c)
            for (k = 0; k < 3; ++k) params[12 * t + 3 * c + k] = 2.0 * points[3 * tets[4 * t + c] + k];

    hexex_extraction_options_init(&opt);
    opt.threads = 1;
    if (hexex_extract(points, 8, tets, 6, params, &opt, &r) != HEXEX_OK) {
        fprintf(stderr, "hexex: %s\n", hexex_result_error_message(r));
        hexex_result_free(r);
        return 1;
    }
    hexex_result_get(r, HEXEX_VALUE_VALID_ALL_HEX, &valid);
    printf("HexEx %s: %lld hexes, %lld vertices, valid all-hex: %s\n", hexex_version(),
           (long long)hexex_result_n_hexes(r), (long long)hexex_result_n_vertices(r), valid == 1 ? "yes" : "no");
    printf("first hex: ");
    for (k = 0; k < 8; ++k) printf("%d ", (int)hexex_result_hexes(r)[k]);
    printf("\n");
    ok = hexex_result_n_hexes(r) == 8 && hexex_result_n_vertices(r) == 27 && valid == 1;
    hexex_result_free(r);
    return ok ? 0 : 1;
}
