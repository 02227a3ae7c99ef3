"""The functions of the hexex package: thin wrappers that check the arguments and call the
C++ core (hexex._core), which runs the library's own code."""

from __future__ import annotations

import json
import warnings
from typing import Optional, Union

import numpy as np

from . import _core
from ._arrays import as_float_array, as_index_array, as_map_arrays, as_path, as_polyhedra
from ._types import ExtractionResult, HexMesh, OptimizeResult, TetMap, UntangleResult


class HexExWarning(UserWarning):
    """A warning of the library (reader repairs, writer limits)."""


def _warn(messages) -> None:
    for m in messages:
        warnings.warn(m, HexExWarning, stacklevel=3)


def _check_int(value, name: str, minimum: Optional[int] = None, maximum: int = 2**31 - 1) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an int, got {type(value).__name__}")
    value = int(value)
    if minimum is not None and value < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {value}")
    if value > maximum:
        raise ValueError(f"{name} is too large: {value}")
    return value


def _check_seed(seed) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise TypeError(f"seed must be an int, got {type(seed).__name__}")
    if not 0 <= int(seed) < 2**32:
        raise ValueError(f"seed must be in [0, 2**32), got {seed}")
    return int(seed)


def _check_float(value, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name} must be a number, got {type(value).__name__}")
    return float(value)


def extract(points, tets, params, *, threads: int = 0, epsilon: float = 1e-6, merge: bool = True,
            rotations=None, max_memory: int = 0, cheap_folds: bool = True, untangle: bool = False,
            annihilation_retries: bool = True, optimize: bool = False, pillow=None,
            provenance: bool = False) -> ExtractionResult:
    """Extracts the hex mesh of a tet mesh with an integer-grid map.

    Args:
        points: vertex positions, shape (n, 3), float64 (other real dtypes are converted).
        tets: four vertex indices per tet, shape (m, 4), int32 or int64 (used in place);
            tets should be positively oriented in 3D.
        params: parameter of every tet corner in that tet's own chart, shape (m, 4, 3).
        threads: worker threads, 0 = all hardware threads. The output is identical for
            any value.
        epsilon: parameter coordinates this close to an integer are snapped.
        merge: annihilate regular/anti dart pairs and merge the vertices they duplicate.
        rotations: optional given transition rotation per halfface, shape (m, 4), values
            0..23: ``rotations[t, i]`` is the rotation from tet t into its neighbour across
            the face opposite corner i (ignored on the boundary). By default the
            transitions are inferred from the parameters.
        max_memory: memory budget in bytes; 0 = half of the memory available at the call.
            The extractor estimates what it needs before allocating and raises
            ``MemoryError`` (naming the tets with the largest parametric images) if the
            estimate exceeds the budget.
        cheap_folds: skip grid points where a fold layer exactly cancels a proper layer
            (their darts would all annihilate); False extracts and annihilates them like
            all others (``hexex extract --full-annihilation``).
        annihilation_retries: where the annihilation leaves broken hex cells (heavy folds
            over several layers), run it again phase by phase or in other fixed orders and
            keep the run with the fewest (report keys ``darts.annihilation_order``,
            ``darts.broken_cells_after_annihilation``); False keeps the first order
            (``hexex extract --no-annihilation-retries``).
        untangle: afterwards move vertices so that no hex is inverted (see
            :func:`untangle`), boundary vertices on the boundary of the input tet mesh
            (``hexex extract --untangle``). The report then has the key ``untangle`` (the
            untangling report) and its ``quality`` is measured after untangling.
        optimize: afterwards raise the worst scaled Jacobian (see :func:`optimize`),
            boundary vertices on the boundary of the input tet mesh; implies ``untangle``
            (``hexex extract --optimize``). The report then also has the key ``optimize``
            and its ``quality`` is measured after optimising.
        pillow: True: before optimising, insert a layer of hexes along the boundary (see
            :func:`optimize`); implies ``optimize`` (``hexex extract --pillow``). None (the
            default): with ``untangle`` or ``optimize``, only if untangling alone leaves
            hexes not certified valid; hexes outside the input's boundary are then removed,
            the layer is added, and the mesh is untangled and optimised (the report's
            ``warnings`` say so; not with ``provenance``). False: never
            (``hexex extract --no-pillow``).
        provenance: also return where each hex and vertex comes from, as
            ``result.provenance``: a dict of int32 arrays ``hex_source_tet`` (h,) (the tet
            whose parameter image contains the hex's centre), ``hex_grid_cell`` (h, 3) (the
            smallest corner of the hex's integer grid cell in that tet's chart),
            ``vertex_source_tet`` (k,) and ``vertex_grid_coords`` (k, 3) (the vertex's grid
            point in the chart of that tet; -1 / 0 for a vertex of no hex). Not with
            ``pillow`` (which adds hexes).

    Returns:
        ExtractionResult with ``points`` (k, 3), ``hexes`` (h, 8) in VTK order,
        ``polyhedra``, ``report`` (dict, the JSON report's keys) and ``valid_all_hex``.

    Raises:
        TypeError / ValueError for arrays of the wrong dtype or shape; ValueError with the
        library's message for unusable input (index out of range, repeated vertex,
        non-manifold mesh, non-finite parameters, ...); MemoryError if the memory budget
        would be exceeded. Defective maps do not raise: what
        could not be resolved is in the report, non-hex cells are in ``polyhedra``.

    The GIL is released while the C++ library converts and extracts.
    """
    points, tets, params = as_map_arrays(points, tets, params)
    threads = _check_int(threads, "threads", 0)
    epsilon = _check_float(epsilon, "epsilon")
    if rotations is not None:
        rotations = as_index_array(rotations, "rotations", (tets.shape[0], 4), dtypes=(np.int32,))
    max_memory = _check_int(max_memory, "max_memory", 0, maximum=2**64 - 1)
    if provenance and pillow:
        raise ValueError("provenance=True cannot be combined with pillow=True (pillowing adds hexes)")
    pts, hexes, polyhedra, report, prov = _core.extract(points, tets, params, threads, epsilon, bool(merge), rotations,
                                                        max_memory, bool(cheap_folds), bool(annihilation_retries),
                                                        bool(provenance))
    report = json.loads(report)
    if pillow is not None and not isinstance(pillow, bool):
        raise TypeError(f"pillow must be True, False or None, got {type(pillow).__name__}")
    optimize = optimize or bool(pillow)
    if untangle or optimize:
        boundary = _boundary_triangles(tets)
        # As hexex extract (HexEx::untangleWithRepair): untangling, optimising if asked, and the
        # layer of --pillow as the repair where untangling alone leaves hexes not certified
        # valid (policy 1), unless pillow=False (0), pillow=True (2) or provenance=True, whose
        # hex numbers the layer would break.
        policy = 2 if pillow else 0 if pillow is False or provenance else 1
        pts, hexes, polyhedra, u, o, note = _core.untangle_with_repair(pts, hexes, polyhedra, points, boundary,
                                                                       threads, bool(optimize), policy)
        report["untangle"] = u
        if o is not None:
            report["optimize"] = o
        bad = u["invalid_after"] + u["undecided_after"]
        if pillow is None and provenance and bad > 0:
            note = (f"untangling alone left {bad} hexes not certified valid; no pillowing repair: "
                    "provenance=True (pillowing adds hexes)")
        if note:
            report.setdefault("warnings", []).append(note)
        # The quality keys of the report, measured on the moved mesh (as hexex extract does).
        quality = _core.validate(pts, hexes, polyhedra)["quality"]
        report["quality"] = {k: quality[k] for k in ("min_scaled_jacobian", "mean_scaled_jacobian", "inverted_hexes",
                                                     "invalid_hexes", "undecided_hexes", "certified_valid")}
    return ExtractionResult(pts, hexes, polyhedra, report, prov)


def _boundary_triangles(tets: np.ndarray) -> np.ndarray:
    """The faces of ``tets`` that belong to one tet only, int32 (b, 3), one orientation for all."""
    faces = np.asarray(tets)[:, [[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]]].reshape(-1, 3)
    _, inverse, counts = np.unique(np.sort(faces, axis=1), axis=0, return_inverse=True, return_counts=True)
    return np.ascontiguousarray(faces[counts[inverse.reshape(-1)] == 1], dtype=np.int32)


def _surface_arrays(surface, fixed_boundary):
    """The ``surface=`` argument of :func:`untangle` and :func:`optimize` as (points, triangles)
    arrays, or (None, None) without one; it excludes ``fixed_boundary``."""
    if surface is None:
        return None, None
    if fixed_boundary:
        raise ValueError("surface and fixed_boundary exclude each other")
    if not isinstance(surface, tuple) or len(surface) != 2:
        raise TypeError("surface must be a tuple (points, triangles)")
    return (as_float_array(surface[0], "surface points", (None, 3)),
            as_index_array(surface[1], "surface triangles", (None, 3), dtypes=(np.int32,)))


def untangle(points, hexes, *, polyhedra=None, surface=None, fixed_boundary: bool = False, threads: int = 0,
             rings: int = 1, feature_angle: float = 40.0, keep_features: bool = False,
             quality_iterations: int = 10) -> UntangleResult:
    """Moves the vertices of a hex mesh so that every hex is certified valid: its Jacobian
    determinant is proved positive on the whole hex (the test of :func:`validate`), not only
    at its 8 corners (regularised elliptic energy of Garanzha et al. 2021, minimised with
    L-BFGS; see Documentation/algorithm.md). Only vertices near invalid hexes move; a mesh
    without invalid hexes comes back unchanged. The input arrays are not modified.

    Args:
        points: vertex positions, shape (k, 3).
        hexes: hexahedra in VTK order, shape (h, 8), int32.
        polyhedra: non-hex cells (their vertices never move), as in :class:`HexMesh`.
        surface: ``(surface_points (n, 3), triangles (t, 3))`` that boundary vertices stay
            on (e.g. the boundary of the input tet mesh); default: the mesh's own boundary.
        fixed_boundary: boundary vertices do not move at all.
        threads: worker threads (0 = all); the result is identical for any value.
        rings: hex rings around the inverted hexes that may move at first (grown by 4x
            and then to the whole mesh if needed).
        feature_angle: surface edges sharper than this (degrees) are feature curves;
            vertices on them move along them, feature corners stay fixed.
        keep_features: never let vertices leave feature curves and corners (``hexex untangle
            --keep-features``). By default, the feature vertices of hexes that stay inverted
            while they are held are released onto the surface (``report["released_feature_vertices"]``).
        quality_iterations: L-BFGS iterations that raise the worst scaled Jacobian of an
            untangled neighbourhood (``--quality-iterations``; 0 = off).

    Returns:
        UntangleResult: ``points``, ``hexes``, ``polyhedra`` and ``report`` (dict);
        ``report["invalid_after"]`` (certified invalid hexes), ``report["undecided_after"]``,
        ``report["inverted_after"]`` (hexes with a corner Jacobian <= 0) and
        ``report["message"]`` say what could not be untangled (no exception is raised for
        that); ``report["success"]`` is True when every hex is certified valid.
    """
    points = as_float_array(points, "points", (None, 3))
    hexes = as_index_array(hexes, "hexes", (None, 8), dtypes=(np.int32,))
    polyhedra = as_polyhedra(polyhedra)
    threads = _check_int(threads, "threads", 0)
    rings = _check_int(rings, "rings", 0)
    feature_angle = _check_float(feature_angle, "feature_angle")
    quality_iterations = _check_int(quality_iterations, "quality_iterations", 0, maximum=1000000)
    surface_points, surface_triangles = _surface_arrays(surface, fixed_boundary)
    pts, hx, poly, report = _core.untangle(points, hexes, polyhedra, surface_points, surface_triangles,
                                           bool(fixed_boundary), threads, rings, feature_angle, bool(keep_features),
                                           quality_iterations)
    return UntangleResult(pts, hx, poly, report)


def optimize(points, hexes, *, polyhedra=None, surface=None, fixed_boundary: bool = False, threads: int = 0,
             target: float = 0.9, feature_angle: float = 40.0, max_blocks: int = 40,
             max_passes: int = 60, pillow: bool = False) -> OptimizeResult:
    """Raises the worst scaled Jacobian of a valid hex mesh (``hexex optimize``): L-BFGS on a
    soft minimum of the corner scaled Jacobians, then vertex-by-vertex max-min moves; every
    accepted step keeps every hex certified valid and never lowers the worst scaled Jacobian
    (see Documentation/algorithm.md, "Mesh optimisation"). Boundary vertices stay on the
    surface, feature-curve vertices on their curve, corner vertices at their corner. A mesh
    with inverted hexes is refused (``report["success"]`` False): untangle it first
    (:func:`untangle`). The input arrays are not modified.

    Args:
        points: vertex positions, shape (k, 3).
        hexes: hexahedra in VTK order, shape (h, 8), int32.
        polyhedra: non-hex cells (their vertices never move), as in :class:`HexMesh`.
        surface: ``(surface_points (n, 3), triangles (t, 3))`` that boundary vertices stay
            on; default: the mesh's own boundary.
        fixed_boundary: boundary vertices do not move at all.
        threads: worker threads (0 = all); the result is identical for any value.
        target: stop once the worst scaled Jacobian reaches this.
        feature_angle: surface edges sharper than this (degrees) are feature curves.
        max_blocks: L-BFGS blocks of the global phase at most (0: none).
        max_passes: vertex-by-vertex passes of the local phase at most (0: none).
        pillow: first insert a layer of hexes along the boundary, one per boundary quad
            (patches with flat corners along feature curves get a strip of quads instead;
            ``hexex optimize --pillow``): lifts the bound sin(angle) of hexes with two
            boundary faces meeting almost flat. The result has more hexes and vertices
            (``report["pillowed_hexes"]``, ``report["pillow_vertices"]``); the input's
            vertices come first, unchanged in number. Needs an all-hex mesh with a
            manifold boundary (ValueError otherwise).

    Returns:
        OptimizeResult: ``points``, ``hexes``, ``polyhedra`` and ``report`` (dict).
    """
    points = as_float_array(points, "points", (None, 3))
    hexes = as_index_array(hexes, "hexes", (None, 8), dtypes=(np.int32,))
    polyhedra = as_polyhedra(polyhedra)
    threads = _check_int(threads, "threads", 0)
    target = _check_float(target, "target")
    feature_angle = _check_float(feature_angle, "feature_angle")
    max_blocks = _check_int(max_blocks, "max_blocks", 0, maximum=1000000)
    max_passes = _check_int(max_passes, "max_passes", 0, maximum=1000000)
    surface_points, surface_triangles = _surface_arrays(surface, fixed_boundary)
    pts, hx, poly, report = _core.optimize(points, hexes, polyhedra, surface_points, surface_triangles,
                                           bool(fixed_boundary), threads, target, feature_angle, max_blocks,
                                           max_passes, bool(pillow))
    return OptimizeResult(pts, hx, poly, report)


def read_map(path) -> TetMap:
    """Reads a tet mesh with its map from ``.hexex`` or OpenVolumeMesh ``.ovm`` (ASCII) /
    ``.ovmb`` (binary), chosen by extension. Repairs the reader made (e.g. a mirrored mesh reoriented) are
    issued as :class:`HexExWarning`. Raises ValueError "<file>:<line>: <reason>" for
    malformed files and "<file>: <reason>" for missing ones."""
    points, tets, params, messages = _core.read_map(as_path(path))
    _warn(messages)
    return TetMap(points, tets, params)


def write_map(path, points, tets=None, params=None) -> None:
    """Writes a tet mesh with its map as ``.hexex``. Pass the three arrays, or a
    :class:`TetMap` as ``points``: ``write_map("out.hexex", tet_map)``."""
    path = as_path(path)
    if tets is None and params is None and isinstance(points, tuple) and len(points) == 3:
        points, tets, params = points
    if not path.lower().endswith(".hexex"):
        raise ValueError(f"{path}: write_map writes the .hexex format only (extension .hexex)")
    _core.write_map(path, *as_map_arrays(points, tets, params))


def map_statistics(points, tets, params) -> dict:
    """Counts and measures of a map (as ``hexex info``): vertices, tets, boundary_faces,
    flipped_tets, degenerate_tets, parametric_volume, param_bbox_min, param_bbox_max."""
    return _core.map_statistics(*as_map_arrays(points, tets, params))


def _as_hex_mesh(mesh) -> tuple:
    for attr in ("points", "hexes"):
        if not hasattr(mesh, attr):
            raise TypeError(f"expected a HexMesh (with points, hexes, polyhedra), got {type(mesh).__name__}")
    points = as_float_array(mesh.points, "points", (None, 3))
    hexes = as_index_array(mesh.hexes, "hexes", (None, 8), dtypes=(np.int32,))
    return points, hexes, as_polyhedra(getattr(mesh, "polyhedra", None))


def read_hex_mesh(path) -> HexMesh:
    """Reads a hex mesh (``.vtu``, ``.vtk``, ``.ovm``, ``.ovmb``, ``.mesh``, by extension)."""
    return HexMesh(*_core.read_hex_mesh(as_path(path)))


def write_hex_mesh(path, mesh: HexMesh, *, encoding: str = "binary") -> None:
    """Writes ``mesh`` (a HexMesh or ExtractionResult) as ``.vtu``, ``.vtk``, ``.ovm``,
    ``.ovmb`` or ``.mesh`` (by extension), byte for byte as ``hexex extract`` writes it.
    ``encoding`` is the ``.vtu`` data encoding as ``hexex extract --encoding``: "binary"
    (raw appended data), "compressed" (zlib) or "ascii". Cells a format cannot store
    (polyhedra in ``.mesh``) are reported as :class:`HexExWarning`."""
    if not isinstance(encoding, str):
        raise TypeError(f"encoding must be a str, got {type(encoding).__name__}")
    _warn(_core.write_hex_mesh(as_path(path), *_as_hex_mesh(mesh), encoding))


def validate(mesh: Union[HexMesh, str, "os.PathLike"]) -> dict:
    """Checks a hex mesh (a HexMesh, or a path to read) as ``hexex validate`` does: all
    cells hexes, faces shared by at most two cells, closed 2-manifold boundary, Euler
    characteristic, quality. Returns a dict of counts with ``valid_all_hex``."""
    if not hasattr(mesh, "points"):
        mesh = read_hex_mesh(mesh)
    return _core.validate(*_as_hex_mesh(mesh))


def generate_cube(n: int = 3, scale: int = 3) -> TetMap:
    """The unit cube split into n^3 boxes of six tets, map = scale * position:
    scale^3 hexes, (scale+1)^3 vertices."""
    return TetMap(*_core.generate_cube(_check_int(n, "n", 1), _check_int(scale, "scale", 1)))


def generate_cylinder(valence: int = 3, radius: int = 2, height: int = 2, n: int = 2, m: int = 2) -> TetMap:
    """A cylinder of ``valence`` wedges around a singular edge of that valence:
    valence * radius^2 * height hexes."""
    return TetMap(*_core.generate_cylinder(_check_int(valence, "valence", 3), _check_int(radius, "radius", 1),
                                           _check_int(height, "height", 1), _check_int(n, "n", 1),
                                           _check_int(m, "m", 1)))


def generate_ring(length: int = 6, width: int = 2, height: int = 2, nu: int = 6, nv: int = 2, nw: int = 2) -> TetMap:
    """A ring periodic in the first parameter (glued by a translation): length * width *
    height hexes."""
    return TetMap(*_core.generate_ring(_check_int(length, "length", 1), _check_int(width, "width", 1),
                                       _check_int(height, "height", 1), _check_int(nu, "nu", 3),
                                       _check_int(nv, "nv", 1), _check_int(nw, "nw", 1)))


def generate_twisted_ring(length: int = 8, width: int = 2, nu: int = 8, nv: int = 2) -> TetMap:
    """A square ring glued by a quarter turn (nv even): length * width^2 hexes."""
    return TetMap(*_core.generate_twisted_ring(_check_int(length, "length", 1), _check_int(width, "width", 1),
                                               _check_int(nu, "nu", 3), _check_int(nv, "nv", 2)))


def random_charts(tet_map: TetMap, seed: int) -> TetMap:
    """A copy of ``tet_map`` with every tet re-expressed in a random grid chart (random
    rotation and integer translation per tet): same hex mesh, non-trivial transitions."""
    return TetMap(*_core.random_charts(*as_map_arrays(*tet_map), _check_seed(seed)))


def parameter_noise(tet_map: TetMap, amplitude: float, seed: int = 1) -> TetMap:
    """A copy of ``tet_map`` with uniform noise in [-amplitude, amplitude] added to every
    corner parameter (coordinates on boundary planes kept)."""
    return TetMap(*_core.parameter_noise(*as_map_arrays(*tet_map), _check_float(amplitude, "amplitude"),
                                         _check_seed(seed)))


def perturb_hex_mesh(mesh: HexMesh, fraction: float, seed: int = 1, *, return_stats: bool = False):
    """A tangled copy of the hex mesh ``mesh`` (``hexex perturb HEX.vtu -a fraction``), to test
    the untangler: every interior vertex moves by a vector uniform in [-d, d]^3, d =
    ``fraction`` times the mean length of its edges; boundary vertices and vertices of
    polyhedra keep their positions bit for bit, so the input stays a valid placement with the
    same boundary. A fraction around 1 inverts most hexes of a regular mesh. The same seed
    gives the same result on every platform. With ``return_stats=True`` returns
    ``(HexMesh, stats dict)`` (vertices, interior_vertices, moved_vertices, inverted_before,
    inverted_after, max_displacement)."""
    points, hexes, polyhedra = _as_hex_mesh(mesh)
    *arrays, stats = _core.perturb_hex_mesh(points, hexes, polyhedra, _check_float(fraction, "fraction"),
                                            _check_seed(seed))
    result = HexMesh(*arrays)
    return (result, stats) if return_stats else result


def perturb(tet_map: TetMap, amplitude: float, seed: int = 1, *, return_stats: bool = False):
    """A copy of ``tet_map`` whose vertex parameters are moved by uniform noise in
    [-amplitude, amplitude] consistently in all charts (paper section 5.1; boundary planes
    and singular edges keep their alignment), as ``hexex perturb``. With
    ``return_stats=True`` returns ``(TetMap, stats dict)``."""
    *arrays, stats = _core.perturb(*as_map_arrays(*tet_map), _check_float(amplitude, "amplitude"), _check_seed(seed))
    result = TetMap(*arrays)
    return (result, stats) if return_stats else result
