/// @file minimal.cc
/// Smallest program against an installed HexEx: builds a unit cube out of six tets,
/// builds the adjacency and checks the entity counts. Exits 0 only if they are right.

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
    std::cout << (ok ? "OK" : "FAILED: unexpected counts") << "\n";
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
