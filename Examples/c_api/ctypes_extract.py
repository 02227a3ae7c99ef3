#!/usr/bin/env python3
"""Calls the HexEx C API (hexex.h) from Python through ctypes, without the extension module.

Reads a .hexex file (a tet mesh with its integer-grid map given per tet corner), extracts
the hex mesh with hexex_extract(), prints the counts and the first hex, validates the result
with hexex_validate(), and shows how an error comes back (code and message).

    python3 ctypes_extract.py --library build/src/CApi/libhexex_c.so Examples/data/sphere.hexex

--check HEXES VERTICES makes the script exit 1 unless the extraction gives these counts
(the test suite runs it so). Only the standard library is used; the same calls work from
any language with a C foreign-function interface.
"""

import argparse
import ctypes
import sys

# Values of hexex_status and hexex_value used here (hexex.h).
HEXEX_OK = 0
HEXEX_ERROR_INPUT = 2
HEXEX_VALUE_VALID_ALL_HEX = 0
HEXEX_VALUE_INVERTED_HEXES = 6
HEXEX_VALUE_MIN_SCALED_JACOBIAN = 7
HEXEX_VALUE_EULER_CHARACTERISTIC = 48


class ExtractionOptions(ctypes.Structure):
    """hexex_extraction_options, field by field in the header's order."""

    _fields_ = [
        ("size", ctypes.c_size_t),
        ("threads", ctypes.c_int),
        ("epsilon", ctypes.c_double),
        ("merge", ctypes.c_int),
        ("implicit_cells", ctypes.c_int),
        ("cheap_folds", ctypes.c_int),
        ("annihilation_retries", ctypes.c_int),
        ("max_hexes", ctypes.c_double),
        ("max_memory", ctypes.c_uint64),
        ("given_rotations", ctypes.POINTER(ctypes.c_int32)),
    ]


def load(path):
    """Loads the shared library and declares the signatures of the functions used."""
    lib = ctypes.CDLL(path)
    result_p = ctypes.c_void_p  # hexex_result* (opaque)
    dbl_p, i32_p = ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_int32)
    lib.hexex_version.restype = ctypes.c_char_p
    lib.hexex_extraction_options_init.argtypes = [ctypes.POINTER(ExtractionOptions)]
    lib.hexex_extract.argtypes = [dbl_p, ctypes.c_int64, i32_p, ctypes.c_int64, dbl_p,
                                  ctypes.POINTER(ExtractionOptions), ctypes.POINTER(result_p)]
    lib.hexex_extract.restype = ctypes.c_int
    lib.hexex_validate.argtypes = [dbl_p, ctypes.c_int64, i32_p, ctypes.c_int64, ctypes.POINTER(result_p)]
    lib.hexex_validate.restype = ctypes.c_int
    lib.hexex_result_free.argtypes = [result_p]
    lib.hexex_result_error_message.argtypes = [result_p]
    lib.hexex_result_error_message.restype = ctypes.c_char_p
    lib.hexex_result_report_json.argtypes = [result_p]
    lib.hexex_result_report_json.restype = ctypes.c_char_p
    lib.hexex_result_get.argtypes = [result_p, ctypes.c_int, dbl_p]
    lib.hexex_result_get.restype = ctypes.c_int
    for name, restype in (("n_vertices", ctypes.c_int64), ("n_hexes", ctypes.c_int64),
                          ("vertices", dbl_p), ("hexes", i32_p)):
        fn = getattr(lib, "hexex_result_" + name)
        fn.argtypes = [result_p]
        fn.restype = restype
    return lib


def read_hexex(path):
    """The .hexex file as flat ctypes arrays: (points, n_points, tets, n_tets, params)."""
    with open(path) as f:
        tokens = f.read().split()
    nv = int(tokens[0])
    coords = [float(t) for t in tokens[1:1 + 3 * nv]]
    pos = 1 + 3 * nv
    nt = int(tokens[pos])
    pos += 1
    tets, params = [], []
    for _ in range(nt):
        tets += [int(t) for t in tokens[pos:pos + 4]]
        params += [float(t) for t in tokens[pos + 4:pos + 16]]
        pos += 16
    return ((ctypes.c_double * len(coords))(*coords), nv, (ctypes.c_int32 * len(tets))(*tets), nt,
            (ctypes.c_double * len(params))(*params))


def value(lib, result, key):
    """A value of the result (hexex_result_get())."""
    out = ctypes.c_double()
    if lib.hexex_result_get(result, key, ctypes.byref(out)) != HEXEX_OK:
        raise KeyError(key)
    return out.value


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("hexex_file")
    ap.add_argument("--library", default="libhexex_c.so", help="path of the shared library hexex_c")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--check", type=int, nargs=2, metavar=("HEXES", "VERTICES"))
    args = ap.parse_args()

    lib = load(args.library)
    print("HexEx", lib.hexex_version().decode())
    points, nv, tets, nt, params = read_hexex(args.hexex_file)

    opt = ExtractionOptions()
    lib.hexex_extraction_options_init(ctypes.byref(opt))
    opt.threads = args.threads
    result = ctypes.c_void_p()
    status = lib.hexex_extract(points, nv, tets, nt, params, ctypes.byref(opt), ctypes.byref(result))
    try:
        if status != HEXEX_OK:
            print("error %d: %s" % (status, lib.hexex_result_error_message(result).decode()))
            return 1
        n_hexes = lib.hexex_result_n_hexes(result)
        n_vertices = lib.hexex_result_n_vertices(result)
        hexes = lib.hexex_result_hexes(result)
        print("%d tets -> %d hexes, %d vertices, valid all-hex: %s, min scaled Jacobian %.3f" % (
            nt, n_hexes, n_vertices, bool(value(lib, result, HEXEX_VALUE_VALID_ALL_HEX)),
            value(lib, result, HEXEX_VALUE_MIN_SCALED_JACOBIAN)))
        if n_hexes:
            print("first hex (VTK order):", [hexes[i] for i in range(8)])

        # Validation of the extracted arrays, passed back without copying.
        check = ctypes.c_void_p()
        lib.hexex_validate(lib.hexex_result_vertices(result), n_vertices, hexes, n_hexes, ctypes.byref(check))
        euler = value(lib, check, HEXEX_VALUE_EULER_CHARACTERISTIC)
        inverted = value(lib, check, HEXEX_VALUE_INVERTED_HEXES)
        print("validation: Euler characteristic %d, inverted hexes %d" % (euler, inverted))
        lib.hexex_result_free(check)
    finally:
        lib.hexex_result_free(result)

    # An error: a vertex index out of range comes back as a code and a message.
    tets[0] = nv + 5
    bad = ctypes.c_void_p()
    status = lib.hexex_extract(points, nv, tets, nt, params, None, ctypes.byref(bad))
    message = lib.hexex_result_error_message(bad).decode()
    lib.hexex_result_free(bad)
    print("out-of-range index: status %d, %s" % (status, message))

    if args.check:
        expected = "tet 0: vertex index %d out of range (the mesh has %d vertices)" % (nv + 5, nv)
        ok = ([n_hexes, n_vertices] == args.check and status == HEXEX_ERROR_INPUT and message == expected
              and euler == 1 and inverted == 0)
        print("check:", "OK" if ok else "FAILED")
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
