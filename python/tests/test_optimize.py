"""hexex.optimize: the worst scaled Jacobian rises, hexes stay certified valid, the
boundary stays put or on its surface, inverted input is refused."""

import numpy as np
import pytest

import hexex


def grid_cube(n):
    i = np.arange(n + 1)
    z, y, x = np.meshgrid(i, i, i, indexing="ij")
    points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1) / n

    def vid(a, b, c):
        return (c * (n + 1) + b) * (n + 1) + a

    hexes = [[vid(a, b, c), vid(a + 1, b, c), vid(a + 1, b + 1, c), vid(a, b + 1, c), vid(a, b, c + 1),
              vid(a + 1, b, c + 1), vid(a + 1, b + 1, c + 1), vid(a, b + 1, c + 1)]
             for c in range(n) for b in range(n) for a in range(n)]
    return points, np.array(hexes, dtype=np.int32)


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
