"""The installed package: version, public names, docstrings."""

import importlib.metadata
import re

import hexex


def test_version_matches_package_metadata():
    # hexex.__version__ comes from the C++ library (HexEx::version()); the wheel's version
    # from project(HexEx VERSION ...) in CMakeLists.txt. They must agree.
    assert re.fullmatch(r"\d+\.\d+\.\d+", hexex.__version__)
    assert importlib.metadata.version("hexex") == hexex.__version__


def test_public_api_is_documented():
    for name in hexex.__all__:
        if name == "__version__":
            continue
        obj = getattr(hexex, name)
        assert obj.__doc__ and len(obj.__doc__.strip()) > 20, name


def test_report_version_is_library_version():
    r = hexex.extract(*hexex.generate_cube(1, 1))
    assert r.report["version"] == hexex.__version__
