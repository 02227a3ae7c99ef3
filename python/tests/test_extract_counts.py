"""Exact hex and vertex counts on generated inputs whose hex mesh is known in advance."""

import numpy as np
import pytest

import hexex


def extract_checked(tet_map, **kw):
    r = hexex.extract(*tet_map, **kw)
    assert r.points.dtype == np.float64 and r.points.ndim == 2 and r.points.shape[1] == 3
    assert r.hexes.dtype == np.int32 and r.hexes.ndim == 2 and r.hexes.shape[1] == 8
    assert r.report["output"]["hexes"] == len(r.hexes)
    assert r.report["output"]["vertices"] == len(r.points)
    return r


@pytest.mark.parametrize("n,s", [(4, 3), (3, 5), (2, 1)])
def test_cube_counts(n, s):
    r = extract_checked(hexex.generate_cube(n, s))
    assert r.hexes.shape == (s**3, 8)
    assert r.points.shape == ((s + 1) ** 3, 3)
    assert r.polyhedra == []
    assert r.valid_all_hex is True
    assert r.report["input"]["tets"] == 6 * n**3
    assert r.report["input"]["parametric_volume"] == pytest.approx(s**3)
    # The hex vertices of the cube map s * position are the grid points i / s.
    assert np.allclose(np.sort(np.unique(np.round(r.points * s))), np.arange(s + 1))


@pytest.mark.parametrize("valence,radius,height,vertices", [(3, 2, 2, 57), (5, 2, 3, 124), (6, 1, 1, 26)])
def test_singular_cylinder_counts(valence, radius, height, vertices):
    r = extract_checked(hexex.generate_cylinder(valence, radius, height, 2, 2))
    assert r.hexes.shape == (valence * radius * radius * height, 8)
    assert len(r.points) == vertices  # (height + 1) * (1 + valence * radius * (radius + 1))
    assert r.report["input"]["singular_edges"] == 2  # the axis: m = 2 tet edges
    assert r.valid_all_hex


def test_rings_counts():
    r = extract_checked(hexex.generate_ring(6, 2, 2, 6, 2, 2))
    assert (len(r.hexes), len(r.points)) == (24, 54)
    assert r.valid_all_hex
    t = extract_checked(hexex.generate_twisted_ring(8, 2, 8, 2))
    assert (len(t.hexes), len(t.points)) == (32, 72)
    assert t.valid_all_hex


def test_random_charts_keep_counts():
    m = hexex.random_charts(hexex.generate_cube(3, 3), seed=5)
    assert not np.array_equal(m.params, hexex.generate_cube(3, 3).params)
    r = extract_checked(m)
    assert (len(r.hexes), len(r.points)) == (27, 64)
    assert r.valid_all_hex


@pytest.mark.parametrize("amplitude,flipped", [(0.5, 10), (1.0, 96), (2.0, 175)])
def test_perturbed_cube_keeps_exact_counts(amplitude, flipped):
    m, stats = hexex.perturb(hexex.generate_cube(4, 4), amplitude, seed=3, return_stats=True)
    assert stats["vertices"] == 125 and stats["moved_vertices"] > 0
    assert stats["max_displacement"] <= amplitude
    r = extract_checked(m)
    assert r.report["input"]["flipped_tets"] == flipped
    assert (len(r.hexes), len(r.points)) == (64, 125)
    assert r.valid_all_hex


def test_parameter_noise_is_snapped_away():
    m = hexex.parameter_noise(hexex.generate_cube(3, 3), 1e-9, seed=1)
    assert not np.array_equal(m.params, hexex.generate_cube(3, 3).params)
    r = extract_checked(m)
    assert r.report["input"]["snapped_coordinates"] > 0
    assert (len(r.hexes), len(r.points)) == (27, 64)


def test_sphere_example(repo_root):
    r = extract_checked(hexex.read_map(repo_root / "Examples" / "data" / "sphere.hexex"))
    assert (len(r.hexes), len(r.points)) == (216, 343)
    assert r.valid_all_hex


def test_no_merge_keeps_anti_darts():
    m = hexex.perturb(hexex.generate_cube(4, 4), 1.0, seed=3)
    merged = hexex.extract(*m)
    kept = hexex.extract(*m, merge=False)
    assert merged.report["darts"]["annihilated_pairs"] == 408
    assert kept.report["darts"]["annihilated_pairs"] == 0
    assert kept.report["darts"]["remaining_anti"] > 0
    assert not kept.valid_all_hex


def test_empty_mesh_gives_empty_result():
    r = hexex.extract(np.zeros((0, 3)), np.zeros((0, 4), dtype=np.int64), np.zeros((0, 4, 3)))
    assert r.points.shape == (0, 3) and r.hexes.shape == (0, 8)
    assert r.report["output"]["hexes"] == 0
    assert r.report["input"]["tets"] == 0
    # The mesh-level validator wants at least one cell.
    assert hexex.validate(r)["valid_all_hex"] is False


def test_needle_fold_is_skipped_with_the_same_mesh(repo_root):
    m = hexex.read_map(repo_root / "Examples" / "data" / "sphere.hexex")
    params = m.params.copy()
    params[m.tets == 40, 1] += 400.0  # the interior vertex 40 moved far in all its tets: a needle fold
    cheap = extract_checked((m.points, m.tets, params))
    full = extract_checked((m.points, m.tets, params), cheap_folds=False)
    assert (len(cheap.hexes), len(cheap.points)) == (216, 343) and cheap.valid_all_hex
    np.testing.assert_array_equal(cheap.points, full.points)
    np.testing.assert_array_equal(cheap.hexes, full.hexes)
    assert cheap.report["darts"]["cancelled_fold_points"] > 0
    assert full.report["darts"]["cancelled_fold_points"] == 0
    assert cheap.report["darts"]["extracted"] < full.report["darts"]["extracted"] // 4


def test_annihilation_retries_option_and_report_keys(repo_root):
    # A fold over one layer (the needle above): the first annihilation order leaves no
    # broken cell, so the retries change nothing and the report says order 0.
    m = hexex.read_map(repo_root / "Examples" / "data" / "sphere.hexex")
    params = m.params.copy()
    params[m.tets == 40, 1] += 3.0
    on = extract_checked((m.points, m.tets, params))
    off = extract_checked((m.points, m.tets, params), annihilation_retries=False)
    assert on.valid_all_hex and off.valid_all_hex
    np.testing.assert_array_equal(on.points, off.points)
    np.testing.assert_array_equal(on.hexes, off.hexes)
    assert on.report["darts"]["annihilated_pairs"] > 0
    for r in (on, off):
        assert r.report["darts"]["annihilation_order"] == 0
        assert r.report["darts"]["broken_cells_after_annihilation"] == 0
