"""hexex.untangle and extract(..., untangle=True): inverted hexes go to 0, valid meshes stay."""

from pathlib import Path

import numpy as np
import pytest

import hexex
from hex_grids import grid_cube


def test_untangle_random_interior_moves():
    points, hexes = grid_cube(5)
    rng = np.random.default_rng(3)
    inner = np.all((points > 0) & (points < 1), axis=1)
    tangled = points.copy()
    tangled[inner] += rng.uniform(-0.9, 0.9, size=(inner.sum(), 3)) / 5
    before = tangled.copy()
    r = hexex.untangle(tangled, hexes, fixed_boundary=True, threads=2)
    assert r.report["inverted_before"] > 20
    assert r.report["inverted_after"] == 0 and r.success
    # success is certified validity: no hex negative anywhere inside, none undecided
    assert r.report["invalid_before"] >= r.report["inverted_before"]
    assert r.report["invalid_after"] == 0 and r.report["undecided_after"] == 0
    assert hexex.validate(r)["quality"]["inverted_hexes"] == 0
    assert np.array_equal(r.points[~inner], points[~inner])  # fixed boundary
    assert np.array_equal(tangled, before)  # the input is not modified
    r1 = hexex.untangle(tangled, hexes, fixed_boundary=True, threads=1)
    assert np.array_equal(r1.points, r.points)


def test_untangle_valid_mesh_unchanged():
    points, hexes = grid_cube(3)
    r = hexex.untangle(points, hexes)
    assert r.report["inverted_before"] == 0 and r.report["moved_vertices"] == 0
    assert np.array_equal(r.points, points)


def test_extract_untangle_on_perturbed_cylinder():
    m = hexex.perturb(hexex.generate_cylinder(5, 3, 2, 3, 2), 0.8, seed=1)
    plain = hexex.extract(*m)
    r = hexex.extract(*m, untangle=True)
    assert plain.report["quality"]["inverted_hexes"] > 0
    assert r.report["untangle"]["inverted_before"] == plain.report["quality"]["inverted_hexes"]
    assert r.report["untangle"]["inverted_after"] == 0
    assert r.report["quality"]["inverted_hexes"] == 0
    assert np.array_equal(r.hexes, plain.hexes)


def test_untangle_bad_arguments():
    points, hexes = grid_cube(1)
    with pytest.raises(ValueError):
        hexex.untangle(points, hexes, surface=(points, np.zeros((1, 3), np.int32)), fixed_boundary=True)
    with pytest.raises(ValueError, match="surface triangle 0 references point 9"):
        hexex.untangle(points, hexes, surface=(points, np.array([[0, 1, 9]], np.int32)))


FEATURE_FOLD = (Path(__file__).resolve().parents[2] / "src" / "Unittests" / "data" / "untangle"
                / "s1x2_feature_fold.vtk")


def test_untangle_releases_feature_vertices_unless_kept():
    # A 276-hex cut-out of the S1 x2 output: 3 hexes whose inversion the feature curves hold.
    mesh = hexex.read_hex_mesh(FEATURE_FOLD)
    assert mesh.hexes.shape == (276, 8)
    r = hexex.untangle(mesh.points, mesh.hexes, threads=2)
    assert r.report["inverted_before"] == 3
    assert r.report["inverted_after"] == 0, r.report["message"]
    assert 0 < r.report["released_feature_vertices"] <= 24
    kept = hexex.untangle(mesh.points, mesh.hexes, threads=2, keep_features=True)
    assert kept.report["inverted_after"] == 3
    assert kept.report["released_feature_vertices"] == 0
    assert "3 of them have vertices held on feature curves or corners" in kept.report["message"]


def test_untangle_quality_iterations():
    # The feature fold untangles to a worst scaled Jacobian near 0; the quality iterations
    # (default 10) raise it, quality_iterations=0 leaves it.
    mesh = hexex.read_hex_mesh(FEATURE_FOLD)
    plain = hexex.untangle(mesh.points, mesh.hexes, threads=2, quality_iterations=0)
    better = hexex.untangle(mesh.points, mesh.hexes, threads=2)
    assert plain.report["inverted_after"] == 0 and better.report["inverted_after"] == 0
    assert plain.report["quality_iterations"] == 0
    # 10 after the corner phase, 10 more after the certified phase (the fold's hexes are
    # positive at their corners first, then proved valid)
    assert better.report["quality_iterations"] == 20
    assert better.report["invalid_after"] == 0 and better.success
    assert better.report["min_scaled_jacobian_after"] > plain.report["min_scaled_jacobian_after"] > 0
    with pytest.raises(ValueError, match="quality_iterations must be >= 0"):
        hexex.untangle(mesh.points, mesh.hexes, quality_iterations=-1)


def test_extract_untangle_and_optimize_agree_with_the_cli(cli, tmp_path):
    # extract(..., optimize=True) runs what `hexex extract --optimize` runs: the same points.
    m = hexex.perturb(hexex.generate_cylinder(4, 3, 2, 3, 2), 0.8, seed=1)
    r = hexex.extract(*m, optimize=True, threads=2)
    q = r.report["quality"]
    assert q["inverted_hexes"] == 0 and q["invalid_hexes"] == 0 and q["certified_valid"] is True
    assert r.report["optimize"]["success"] is True
    assert r.report["optimize"]["min_scaled_jacobian_after"] >= r.report["untangle"]["min_scaled_jacobian_after"]
    assert q["min_scaled_jacobian"] == r.report["optimize"]["min_scaled_jacobian_after"]
    untangled = hexex.extract(*m, untangle=True, threads=2)
    assert untangled.report["quality"]["certified_valid"] is True
    assert "optimize" not in untangled.report
    path = tmp_path / "m.hexex"
    hexex.write_map(path, *m)
    cli("extract", path, "-o", tmp_path / "o.vtu", "--optimize", "--threads", "2")
    assert np.array_equal(hexex.read_hex_mesh(tmp_path / "o.vtu").points, r.points)


def test_perturb_hex_mesh_tangles_and_untangle_certifies():
    points, hexes = grid_cube(6)
    mesh = hexex.HexMesh(points, hexes)
    tangled, stats = hexex.perturb_hex_mesh(mesh, 1.5, seed=2, return_stats=True)
    boundary = np.any((points == 0) | (points == 1), axis=1)
    assert stats["vertices"] == 343 and stats["interior_vertices"] == 125 and stats["moved_vertices"] == 125
    assert np.array_equal(tangled.points[boundary], points[boundary])  # the boundary bit for bit
    assert not np.array_equal(tangled.points[~boundary], points[~boundary])
    assert stats["inverted_after"] > 0.8 * len(hexes)
    again = hexex.perturb_hex_mesh(mesh, 1.5, seed=2)
    assert np.array_equal(again.points, tangled.points)  # seeded
    assert hexex.validate(tangled)["quality"]["inverted_hexes"] == stats["inverted_after"]
    r = hexex.untangle(tangled.points, tangled.hexes, fixed_boundary=True, threads=2)
    assert r.report["success"] is True and r.report["invalid_after"] == 0
    assert hexex.validate(hexex.HexMesh(r.points, r.hexes))["quality"]["certified_valid"] is True
    with pytest.raises(ValueError, match="fraction"):
        hexex.perturb_hex_mesh(mesh, -1.0)
