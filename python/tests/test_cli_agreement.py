"""The package gives the same output as the `hexex` command-line tool, bit for bit."""

import json

import numpy as np
import pytest

import hexex


def key_tree(d):
    """The nested key structure of a JSON object (values left out)."""
    return {k: key_tree(v) if isinstance(v, dict) else None for k, v in d.items()}


def without_timings(report):
    r = {k: v for k, v in report.items() if k != "timings_s"}
    return r


CASES = {
    "perturbed_cube": lambda: hexex.perturb(hexex.generate_cube(4, 4), 1.0, seed=3),
    "cylinder5": lambda: hexex.random_charts(hexex.generate_cylinder(5, 2, 2, 2, 2), seed=2),
    "twisted_ring": lambda: hexex.generate_twisted_ring(8, 2, 8, 2),
}


@pytest.mark.parametrize("case", sorted(CASES))
@pytest.mark.parametrize("ext", [".vtu", ".vtk", ".ovm", ".ovmb", ".mesh"])
def test_same_files_as_cli(cli, tmp_path, case, ext):
    src = tmp_path / "in.hexex"
    hexex.write_map(src, CASES[case]())
    cli_out, py_out = tmp_path / f"cli{ext}", tmp_path / f"py{ext}"
    cli("extract", src, "-o", cli_out, "--threads", "2", "--quiet")
    r = hexex.extract(*hexex.read_map(src), threads=2)
    hexex.write_hex_mesh(py_out, r)
    assert py_out.read_bytes() == cli_out.read_bytes()


@pytest.mark.parametrize("encoding", ["binary", "compressed", "ascii"])
def test_same_vtu_encodings_as_cli(cli, tmp_path, encoding):
    src = tmp_path / "in.hexex"
    hexex.write_map(src, CASES["cylinder5"]())
    cli_out, py_out = tmp_path / "cli.vtu", tmp_path / "py.vtu"
    cli("extract", src, "-o", cli_out, "--encoding", encoding, "--quiet")
    hexex.write_hex_mesh(py_out, hexex.extract(*hexex.read_map(src)), encoding=encoding)
    assert py_out.read_bytes() == cli_out.read_bytes()
    assert (b'format="ascii"' in py_out.read_bytes()) == (encoding == "ascii")


def test_same_report_as_cli(cli, tmp_path):
    src = tmp_path / "in.hexex"
    hexex.write_map(src, CASES["perturbed_cube"]())
    rep_path = tmp_path / "r.json"
    cli("extract", src, "-o", tmp_path / "o.vtu", "--report", rep_path, "--threads", "1", "--quiet")
    cli_report = json.loads(rep_path.read_text())
    report = hexex.extract(*hexex.read_map(src), threads=1).report
    assert key_tree(report) == key_tree(cli_report)
    assert without_timings(report) == without_timings(cli_report)
    assert report["darts"]["annihilated_pairs"] == 408


def test_written_map_reads_back_identically(cli, tmp_path):
    m = CASES["cylinder5"]()
    path = tmp_path / "m.hexex"
    hexex.write_map(path, m)
    back = hexex.read_map(path)
    for a, b in zip(m, back):
        assert a.dtype == b.dtype and np.array_equal(a, b)
    info = json.loads(cli("info", path, "--json").stdout)
    stats = hexex.map_statistics(*m)
    assert stats["tets"] == info["tets"] == len(m.tets)
    assert stats["vertices"] == info["vertices"] == len(m.points)


def test_validate_matches_cli(cli, tmp_path):
    r = hexex.extract(*hexex.generate_cylinder(3, 2, 2, 2, 2))
    path = tmp_path / "c.vtu"
    hexex.write_hex_mesh(path, r)
    cli_check = json.loads(cli("validate", path, "--json").stdout)
    mine = hexex.validate(path)
    assert mine["valid_all_hex"] is True
    assert (mine["hexes"], mine["vertices"], mine["boundary_quads"]) == (24, 57, 48)
    flat = {**{k: v for k, v in mine.items() if k != "quality"}, **mine["quality"]}
    assert flat == cli_check
