"""Shared fixtures of the hexex pytest suite.

The CLI comparisons need the `hexex` tool of the C++ build: $HEXEX_CLI, or
<repo>/build/src/Tools/hexex/hexex (what scripts/run-tests.sh builds); they are skipped
with a message when it is absent.
"""

import os
import pathlib
import subprocess

import pytest

REPO_ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo_root() -> pathlib.Path:
    return REPO_ROOT


@pytest.fixture(scope="session")
def cli():
    """Runs the hexex command-line tool: cli(*args) -> CompletedProcess (text)."""
    path = os.environ.get("HEXEX_CLI") or str(REPO_ROOT / "build" / "src" / "Tools" / "hexex" / "hexex")
    if not os.access(path, os.X_OK):
        pytest.skip(f"hexex CLI not found at {path} (build it or set HEXEX_CLI)")

    def run(*args, check=True):
        proc = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        if check and proc.returncode not in (0, 3):
            raise AssertionError(f"hexex {' '.join(map(str, args))} failed ({proc.returncode}): {proc.stderr}")
        return proc

    return run
