"""Checks and conversions of the arrays handed to the C++ core.

Every public function passes its arrays through these helpers, so a wrong shape or dtype
is a clear ``TypeError``/``ValueError`` here and the C++ side only sees C-contiguous
arrays of the dtypes it reads in place (no copy when the caller's arrays already are).
"""

from __future__ import annotations

import os

import numpy as np


def as_path(path) -> str:
    """``path`` (str or os.PathLike) as a str; ``TypeError`` otherwise."""
    try:
        return os.fspath(path)
    except TypeError:
        raise TypeError(f"path must be a str or os.PathLike, got {type(path).__name__}") from None


def _array(a, name: str) -> np.ndarray:
    if a is None:
        raise TypeError(f"{name} must be an array, got None")
    arr = np.asarray(a)
    if arr.dtype == object:
        raise TypeError(f"{name} must be a numeric array, got dtype object")
    return arr


def _check_shape(arr: np.ndarray, name: str, shape: tuple) -> None:
    ok = arr.ndim == len(shape) and all(e is None or e == s for e, s in zip(shape, arr.shape))
    if not ok:
        want = "(" + ", ".join("n" if e is None else str(e) for e in shape) + ")"
        raise ValueError(f"{name} must have shape {want}, got {tuple(arr.shape)}")


def as_float_array(a, name: str, shape: tuple) -> np.ndarray:
    """``a`` as a C-contiguous float64 array of ``shape`` (``None`` = any extent).

    Integer and float arrays are accepted (converted only when not already float64);
    booleans, complex numbers and other dtypes raise ``TypeError``.
    """
    arr = _array(a, name)
    if arr.dtype.kind not in "fiu":
        raise TypeError(f"{name} must be a float array (float64 preferred), got dtype {arr.dtype}")
    _check_shape(arr, name, shape)
    return np.ascontiguousarray(arr, dtype=np.float64)


def as_index_array(a, name: str, shape: tuple, dtypes=(np.int32, np.int64)) -> np.ndarray:
    """``a`` as a C-contiguous integer array of ``shape``.

    Native int32 and int64 arrays are used as they are (the first of ``dtypes`` that
    matches); other integer dtypes are converted to the last of ``dtypes``. Non-integer
    dtypes raise ``TypeError``.
    """
    arr = _array(a, name)
    if arr.dtype.kind not in "iu":
        raise TypeError(f"{name} must be an integer array, got dtype {arr.dtype}")
    _check_shape(arr, name, shape)
    for dt in dtypes:
        if arr.dtype == np.dtype(dt):
            return np.ascontiguousarray(arr)
    target = np.dtype(dtypes[-1])
    if arr.size and (arr.max() > np.iinfo(target).max or arr.min() < np.iinfo(target).min):
        raise ValueError(f"{name} has indices outside the range of {target}")
    return np.ascontiguousarray(arr, dtype=target)


def as_map_arrays(points, tets, params):
    """Checks a tet mesh with its map: points (n,3), tets (m,4), params (m,4,3)."""
    points = as_float_array(points, "points", (None, 3))
    tets = as_index_array(tets, "tets", (None, 4))
    params = as_float_array(params, "params", (tets.shape[0], 4, 3))
    return points, tets, params


def as_polyhedra(polyhedra, name: str = "polyhedra") -> list:
    """``polyhedra`` (a sequence of cells, each a sequence of faces, each a sequence of
    vertex indices) as nested lists of Python ints; ``TypeError`` for anything else."""
    if polyhedra is None:
        return []
    out = []
    try:
        for c, cell in enumerate(polyhedra):
            faces = []
            for face in cell:
                loop = np.asarray(face)
                if loop.ndim != 1 or (loop.size and loop.dtype.kind not in "iu"):
                    raise TypeError(f"{name}[{c}]: every face must be a sequence of integer vertex indices")
                faces.append([int(v) for v in loop])
            out.append(faces)
    except TypeError as e:
        if str(e).startswith(name):
            raise
        raise TypeError(f"{name} must be a list of cells, each a list of faces (lists of vertex indices)") from None
    return out
