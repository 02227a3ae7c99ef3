#pragma once
/// @file HexArcs.hh
/// @ingroup kernel
/// The exact images of the hex mesh's edges and faces in the input (ExtractionOptions::arcs):
/// a polyline ("arc") per hex edge and a triangle mesh ("patch") per hex face.

#include "../Core/Vec.hh"

#include <array>
#include <cstddef>
#include <vector>

namespace HexEx {

/// Edge arcs and face patches of an extracted hex mesh. Edges and faces are those of the
/// hexes (not of the polyhedra), numbered in order of first appearance: hexes in order, then
/// the 12 edges and 6 faces of each hex in the order of HexArcs::kHexEdges and
/// HexArcs::kHexFaces.
struct HexArcs {
    /// The 12 edges of a hex as pairs of local corners (VTK order).
    static constexpr int kHexEdges[12][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}, {4, 5}, {5, 6},
                                             {7, 6}, {4, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    /// The 6 faces of a hex as loops of local corners, oriented outward (VTK order).
    static constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                            {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

    std::vector<std::array<int, 2>> edges;   ///< per edge id: its two hex-mesh vertices, as first seen
    std::vector<std::array<int, 4>> faces;   ///< per face id: its vertex loop, outward of the first hex that has it
    std::vector<std::array<int, 12>> hex_edges;  ///< per hex: edge ids of its kHexEdges
    std::vector<std::array<int, 6>> hex_faces;   ///< per hex: face ids of its kHexFaces
    /// Per hex and local face: +1 if the face's stored loop is outward of this hex, -1 if inward.
    std::vector<std::array<signed char, 6>> hex_face_sign;

    /// Arc of edge e: arc_points[arc_offset[e] .. arc_offset[e+1]), from edges[e][0] to
    /// edges[e][1]; empty if the arc could not be formed.
    std::vector<std::size_t> arc_offset;
    std::vector<Vec3d> arc_points;  ///< the points of all arcs, arc after arc

    /// Patch of face f: patch_triangles[patch_offset[f] .. patch_offset[f+1]) (indices into
    /// patch_points), oriented like faces[f]'s loop in proper regions; empty if the patch
    /// could not be formed.
    std::vector<std::size_t> patch_offset;
    std::vector<std::array<int, 3>> patch_triangles;  ///< the triangles of all patches, patch after patch
    std::vector<Vec3d> patch_points;                  ///< corners of the patch triangles

    std::vector<int> failed_edges;  ///< edge ids whose arc could not be formed, ascending
    std::vector<int> failed_faces;  ///< face ids whose patch is missing or incomplete, ascending
};

} // namespace HexEx
