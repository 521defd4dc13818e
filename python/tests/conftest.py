import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("EF_BUILD", ROOT / "build"))
SVG = pathlib.Path(os.environ.get("EF_SVG", ROOT / "tests" / "data" / "svg"))


@pytest.fixture(scope="session")
def cli():
    exe = BUILD / "edgeflag"
    assert exe.is_file(), f"{exe} not built (make cli)"

    def run(*args, check=True):
        return subprocess.run([str(exe), *map(str, args)], check=check, capture_output=True, text=True)
    return run


@pytest.fixture
def svg():
    return SVG
