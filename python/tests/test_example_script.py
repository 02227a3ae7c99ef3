"""Examples/python/extract_and_render.py runs and writes its mesh, report and picture."""

import json
import subprocess
import sys

import pytest

import hexex


def test_example_writes_vtu_report_and_png(repo_root, tmp_path):
    pytest.importorskip("matplotlib")
    script = repo_root / "Examples" / "python" / "extract_and_render.py"
    proc = subprocess.run([sys.executable, str(script), "--out-dir", str(tmp_path), "--threads", "2"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert "wrote" in proc.stdout and "216 hexes, 343 vertices, valid all-hex" in proc.stdout
    png = (tmp_path / "sphere.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10000
    report = json.loads((tmp_path / "sphere-report.json").read_text())
    assert report["output"]["hexes"] == 216 and report["valid_all_hex"] is True
    mesh = hexex.read_hex_mesh(tmp_path / "sphere.vtu")
    assert (len(mesh.hexes), len(mesh.points)) == (216, 343)


def test_example_reports_bad_input(repo_root, tmp_path):
    script = repo_root / "Examples" / "python" / "extract_and_render.py"
    bad = tmp_path / "bad.hexex"
    bad.write_text("1\n0 0\n")
    proc = subprocess.run([sys.executable, str(script), str(bad), "--out-dir", str(tmp_path)],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert proc.stderr.startswith(f"extract_and_render.py: error: {bad}:")
