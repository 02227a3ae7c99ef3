#pragma once
/// @file OvmModel.hh
/// @ingroup io
/// The content of an OpenVolumeMesh file, ASCII (`.ovm`) or binary (`.ovmb`), as the files
/// store it: vertices, edges, faces as halfedge loops, cells as halfface lists, and the
/// integer-grid map if a property holds one. Both file formats are read into and written
/// from this one model; OvmMeshes.hh turns it into a tet mesh with its map or a hex mesh.
///
/// Numbering as in OpenVolumeMesh: halfedge 2e+o of edge e = (a, b) runs a->b for o = 0 and
/// b->a for o = 1; halfface 2f is the loop of face f, 2f+1 the reversed loop.

#include "../Mesh/HexFaceNeighbours.hh"
#include "../Mesh/HexMesh.hh"
#include "BlockOutput.hh"
#include "OvmFaces.hh"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace HexEx {

/// Topology type stored in an `.ovmb` header (OpenVolumeMesh's mesh kernels).
enum class OvmTopology {
    Polyhedral = 0,   ///< any cells
    Tetrahedral = 1,  ///< tetrahedra only
    Hexahedral = 2,   ///< hexahedra only, halffaces in the hexahedral kernel's order
};

/// An OpenVolumeMesh file in memory (see the file overview).
struct OvmModel {
    std::string name;                         ///< file name used in error messages
    bool binary = false;                      ///< positions are byte offsets (true) or lines (false)
    OvmTopology topology = OvmTopology::Polyhedral;  ///< kernel type (`.ovmb` header; ASCII: polyhedral)
    std::vector<Vec3d> vertices;              ///< vertex positions
    std::vector<std::array<int, 2>> edges;    ///< edge end points
    std::vector<std::vector<int>> faces;      ///< per face its halfedges, a closed loop
    std::vector<std::vector<int>> cells;      ///< per cell its halffaces
    std::vector<long long> facePos;           ///< where each face was read (line or byte offset)
    std::vector<long long> cellPos;           ///< where each cell was read (line or byte offset)
    std::vector<Vec3d> halffaceParams;        ///< map per halfface (2 n_f values), or empty
    std::vector<std::array<double, 12>> cellParams;  ///< map per cell (4 corners), or empty
    std::string paramLabel;                   ///< the property the map came from, or empty
    std::vector<std::string> skipped;         ///< properties read past, "ENTITY TYPE "name" (where)"
    std::vector<std::string> warnings;        ///< "<file>...: text" notes of the reader
    long long endPos = 0;                     ///< position of the end of the file

    /// Throws InputError "<name>:<line>: <reason>" (ASCII) or "<name>: byte <pos>: <reason>".
    [[noreturn]] void fail(long long pos, const std::string& reason) const;
    /// The vertex loop of halfface @p hf (for 2f+1: reversed, starting at the same vertex).
    std::vector<int> halffaceLoop(int hf) const;
    /// Checks that every face is a closed loop of halfedges over distinct vertices and that
    /// no halfface is used twice; @return for every halfface the cell using it, or -1.
    /// @throws InputError at the face or cell at fault.
    std::vector<int> checkTopology() const;
};

/// An OpenVolumeMesh mesh as the writers take it: the lists stored flat, vertex positions
/// and map borrowed from the caller (they must outlive the writing).
struct OvmFlatMesh {
    OvmTopology topology = OvmTopology::Polyhedral;    ///< kernel type for the `.ovmb` header
    const std::vector<Vec3d>* vertices = nullptr;      ///< vertex positions (not null when written)
    std::vector<std::array<int, 2>> edges;             ///< edge end points
    IntLists faces;                                    ///< per face its halfedges
    IntLists cells;                                    ///< per cell its halffaces
    const std::vector<Vec3d>* halffaceParams = nullptr;  ///< map per halfface, or null for none
};

/// The lists of @p model flattened; positions and map point into @p model.
OvmFlatMesh flatOvm(const OvmModel& model);

/// True if @p name (e.g. `HexHex::Parametrization`, `uvw`) names an integer-grid map: the
/// part after the last `::`, compared case-insensitively, is one of parametrization,
/// parameterization, param, params, parameter, parameters, uvw, igm.
bool isParametrizationName(std::string_view name);

/// Parses OpenVolumeMesh ASCII (`OVM ASCII`) @p text; @p name is used in messages.
/// @throws InputError "<name>:<line>: <reason>" for malformed input.
OvmModel parseOvmAscii(std::string_view text, const std::string& name);

/// Parses OpenVolumeMesh binary (`.ovmb`) @p data; @p name is used in messages.
/// @throws InputError "<name>: byte <offset>: <reason>" for malformed input.
OvmModel parseOvmBinary(std::string_view data, const std::string& name);

/// Parses @p data as binary if it starts with the `.ovmb` magic bytes, as ASCII otherwise.
OvmModel parseOvm(std::string_view data, const std::string& name);

/// The model as OpenVolumeMesh ASCII; the map (if any) as `HFProp vec3d "HexHex::Parametrization"`.
std::string writeOvmAscii(const OvmModel& model);

/// Appends @p mesh as OpenVolumeMesh ASCII (as writeOvmAscii(const OvmModel&)) to @p out,
/// formatting on @p threads threads (the bytes do not depend on it).
void writeOvmAscii(detail::BlockOutput& out, const OvmFlatMesh& mesh, int threads = 1);

/// Appends the hex mesh @p mesh as OpenVolumeMesh ASCII to @p out: the same bytes as
/// writeOvmAscii(out, ovmFlatFromHexMesh(mesh, threads), threads), but with @p threads > 1
/// the vertices are formatted and appended while the faces and edges are numbered.
/// With @p neighbours the faces are numbered from that table (see ovmFlatFromHexMesh()).
/// @throws std::invalid_argument as ovmFlatFromHexMesh().
void writeOvmAscii(detail::BlockOutput& out, const HexMesh& mesh, int threads, HexFaceNeighbours* neighbours = nullptr);

/// The model as OpenVolumeMesh binary (file and header version 1, exact doubles, no
/// compression); the map (if any) as halfface property `HexHex::Parametrization` of type `3d`.
std::string writeOvmBinary(const OvmModel& model);

/// Appends @p mesh as OpenVolumeMesh binary (as writeOvmBinary(const OvmModel&)) to @p out;
/// the lists are scanned for their sizes on @p threads threads (the bytes do not depend on it).
void writeOvmBinary(detail::BlockOutput& out, const OvmFlatMesh& mesh, int threads = 1);

/// The hex mesh stored in @p model: cells of six quads that close up like a hexahedron
/// become hexes (VTK order), all others polyhedra. Halffaces may point out of their cells
/// (as this library writes them) or into them: if the total signed volume is negative,
/// every face loop is reversed. @throws InputError for inconsistent topology.
HexMesh hexMeshFromOvm(const OvmModel& model);

/// The OpenVolumeMesh model of @p mesh: shared faces stored once, edges numbered in order of
/// first use, halffaces pointing out of their cells; hexes list their halffaces in the
/// order of OpenVolumeMesh's hexahedral kernel (bottom, top, then the four sides as pairs
/// of opposite faces), and a mesh of hexes only gets OvmTopology::Hexahedral.
/// @throws std::invalid_argument for vertex indices out of range or faces of < 3 vertices.
OvmModel ovmFromHexMesh(const HexMesh& mesh);

/// The same as ovmFromHexMesh() in flat form, with faces and edges found on @p threads
/// threads (the result does not depend on it); the positions point into @p mesh.
/// With @p neighbours (e.g. from the extraction, HexFaceNeighbours.hh) that fit the mesh the
/// faces are numbered from that table instead of matching the quads; the result is the same.
/// The table is used up (left empty) either way.
OvmFlatMesh ovmFlatFromHexMesh(const HexMesh& mesh, int threads = 1, HexFaceNeighbours* neighbours = nullptr);

} // namespace HexEx
