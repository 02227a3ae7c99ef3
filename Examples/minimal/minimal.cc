/// @file minimal.cc
/// Smallest program against an installed HexEx: builds a unit cube out of six tets,
/// builds the adjacency and checks the entity counts, then extracts the hex mesh of the
/// map "parameter = 2 * position" (a 2x2x2 grid of hexes). Exits 0 only if all is right.

#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/TetMesh.hh>

#include <array>
#include <cstdlib>
#include <iostream>

namespace {

/// Unit cube, vertex i at (i&1, (i>>1)&1, (i>>2)&1), split into six tets around the
/// diagonal 0-7. Corners are ordered so that every tet has positive volume.
HexEx::TetMesh makeCube() {
    HexEx::TetMesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.add_vertex(HexEx::Vec3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    const int tets[6][4] = {{0, 1, 3, 7}, {0, 5, 1, 7}, {0, 3, 2, 7},
                            {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 6, 4, 7}};
    for (const auto& t : tets)
        mesh.add_cell({HexEx::VertexHandle(t[0]), HexEx::VertexHandle(t[1]),
                       HexEx::VertexHandle(t[2]), HexEx::VertexHandle(t[3])});
    return mesh;
}

/// Signed volume of cell @p c (times 6).
double orientedVolume6(const HexEx::TetMesh& mesh, HexEx::CellHandle c) {
    const auto& v = mesh.cell_vertices(c);
    const HexEx::Vec3d a = mesh.position(v[1]) - mesh.position(v[0]);
    const HexEx::Vec3d b = mesh.position(v[2]) - mesh.position(v[0]);
    const HexEx::Vec3d d = mesh.position(v[3]) - mesh.position(v[0]);
    return (a % b) | d;  // OpenMesh: % is the cross product, | the dot product
}

} // namespace

int main() {
    HexEx::TetMesh mesh = makeCube();
    mesh.build_adjacency();

    int flipped = 0;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
        if (orientedVolume6(mesh, HexEx::CellHandle(static_cast<int>(c))) <= 0) ++flipped;

    std::cout << "vertices:       " << mesh.n_vertices() << "\n"
              << "edges:          " << mesh.n_edges() << "\n"
              << "faces:          " << mesh.n_faces() << "\n"
              << "cells:          " << mesh.n_cells() << "\n"
              << "boundary faces: " << mesh.n_boundary_faces() << "\n"
              << "flipped cells:  " << flipped << "\n";

    // 12 cube edges + 6 face diagonals + 1 body diagonal; 12 boundary + 6 inner faces.
    const bool ok = mesh.n_vertices() == 8 && mesh.n_edges() == 19 && mesh.n_faces() == 18 &&
                    mesh.n_cells() == 6 && mesh.n_boundary_faces() == 12 && flipped == 0 &&
                    mesh.check_manifold().empty();
    if (!ok) {
        std::cout << "FAILED: unexpected tet mesh counts\n";
        return EXIT_FAILURE;
    }

    // Extraction: every tet corner gets the parameter 2 * position (one chart for all tets).
    HexEx::ParametrizedTetMesh input;
    input.mesh = makeCube();
    input.mesh.build_adjacency();
    input.params.resize(input.mesh.n_cells());
    for (std::size_t c = 0; c < input.mesh.n_cells(); ++c)
        for (int i = 0; i < 4; ++i)
            input.params[c][static_cast<std::size_t>(i)] =
                2.0 * input.mesh.position(input.mesh.cell_vertex(HexEx::CellHandle(static_cast<int>(c)), i));

    HexEx::HexMesh hexes;
    const HexEx::ExtractionReport report = HexEx::extractHexMesh(input, hexes);
    std::cout << "hex vertices:   " << hexes.vertices.size() << "\n"
              << "hexes:          " << hexes.hexes.size() << "\n"
              << "non-hex cells:  " << hexes.polyhedra.size() << "\n"
              << "valid all-hex:  " << (report.valid_all_hex ? "yes" : "no") << "\n";

    const bool extracted = hexes.hexes.size() == 8 && hexes.vertices.size() == 27 && hexes.polyhedra.empty() &&
                           report.output.hexes == 8 && report.output.vertices == 27 && report.valid_all_hex;
    std::cout << (extracted ? "OK" : "FAILED: unexpected hex mesh") << "\n";
    return extracted ? EXIT_SUCCESS : EXIT_FAILURE;
}
