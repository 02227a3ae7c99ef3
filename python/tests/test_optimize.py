"""hexex.optimize: the worst scaled Jacobian rises, hexes stay certified valid, the
boundary stays put or on its surface, inverted input is refused."""

import numpy as np
import pytest

import hexex
from hex_grids import grid_cube


def perturbed_cube(n, a, seed):
    points, hexes = grid_cube(n)
    rng = np.random.default_rng(seed)
    inner = (points > 0) & (points < 1)  # per coordinate: faces move in-plane, edges along the edge
    return np.where(inner, points + rng.uniform(-a, a, size=points.shape) / n, points), hexes


def test_optimize_fixed_boundary_raises_worst():
    points, hexes = perturbed_cube(5, 0.22, 1)
    before = points.copy()
    r = hexex.optimize(points, hexes, fixed_boundary=True, threads=2)
    assert r.success
    rep = r.report
    assert rep["min_scaled_jacobian_after"] > rep["min_scaled_jacobian_before"] + 0.1
    assert rep["invalid_after"] == 0
    assert sum(rep["histogram_after"]) == 125 and len(rep["histogram_after"]) == 20
    boundary = np.any((before == 0) | (before == 1), axis=1)
    assert np.array_equal(r.points[boundary], before[boundary])
    assert np.array_equal(points, before)  # the input is not modified
    r1 = hexex.optimize(points, hexes, fixed_boundary=True, threads=1)
    assert np.array_equal(r1.points, r.points)


def test_optimize_keeps_cube_features():
    points, hexes = perturbed_cube(4, 0.22, 2)
    r = hexex.optimize(points, hexes, threads=2)
    rep = r.report
    assert rep["feature_curves"] == 12 and rep["feature_corners"] == 8
    assert rep["corner_vertices"] == 8 and rep["curve_vertices"] == 12 * 3
    assert rep["min_scaled_jacobian_after"] > rep["min_scaled_jacobian_before"]
    on = (points == 0) | (points == 1)
    assert np.abs(r.points[on] - points[on]).max() <= 1e-9 * np.sqrt(3)


def test_optimize_refuses_inverted_and_bad_arguments():
    points, hexes = grid_cube(2)
    points = points.copy()
    points[13] = [1.25, 0.5, 0.5]
    r = hexex.optimize(points, hexes)
    assert not r.success
    assert "hexes are inverted (a corner Jacobian <= 0); untangle the mesh first" in r.report["message"]
    assert np.array_equal(r.points, points)
    with pytest.raises(ValueError, match="exclude each other"):
        hexex.optimize(points, hexes, fixed_boundary=True, surface=(points, np.zeros((1, 3), np.int32)))
    with pytest.raises(ValueError):
        hexex.optimize(points, hexes, surface=(points, np.array([[0, 1, 999]], np.int32)))


def test_optimize_pillow_adds_a_boundary_layer():
    # 2x2x2 grid: 24 boundary quads -> 24 new hexes, 26 boundary vertices -> 26 copies; the
    # old vertices keep their places (a cube: all boundary vertices are on features or flat).
    points, hexes = grid_cube(2)
    r = hexex.optimize(points, hexes, pillow=True, threads=2)
    assert r.success
    assert r.report["pillowed_hexes"] == 24 and r.report["pillow_vertices"] == 26
    assert r.hexes.shape == (8 + 24, 8) and r.points.shape == (27 + 26, 3)
    assert r.report["hexes"] == 32 and r.report["invalid_after"] == 0
    assert np.abs(r.points[:27] - points).max() <= 1e-12
    assert hexex.validate(r)["quality"]["certified_valid"]
    # Without the option nothing is added.
    r0 = hexex.optimize(points, hexes, threads=2)
    assert r0.report["pillowed_hexes"] == 0 and r0.hexes.shape == (8, 8)


def test_optimize_pillow_lifts_a_flat_corner():
    # One hex whose side faces meet at 170 degrees: SJ = sin(170) = 0.174 with its topology.
    a = np.radians(10)
    base = np.array([[-1, 0, 0], [0, 0, 0], [np.cos(a), np.sin(a), 0], [-0.3, 1.2, 0]])
    points = np.vstack([base, base + [0, 0, 1]])
    hexes = np.array([[0, 1, 2, 3, 4, 5, 6, 7]], dtype=np.int32)
    plain = hexex.optimize(points, hexes, threads=1)
    assert plain.report["min_scaled_jacobian_after"] <= np.sin(np.radians(170)) + 1e-9
    r = hexex.optimize(points, hexes, pillow=True, threads=1)
    assert r.report["pillowed_hexes"] > 0
    assert r.report["min_scaled_jacobian_after"] >= 0.3
    assert r.report["invalid_after"] == 0


def test_optimize_pillow_refuses_polyhedra():
    points, hexes = grid_cube(1)
    with pytest.raises(ValueError, match="pillowing needs an all-hex mesh: the mesh has 1 polyhedra"):
        hexex.optimize(points, hexes, polyhedra=[[[0, 1, 2]]], pillow=True)
