"""Builds the C libraries with the repository's make before packaging them (docs/python.md):
`pip install ./python` from a clone runs `make python` in the clone (the libraries go to its
build/ folder as usual) and copies libedgeflag.so and libefpy.so into the package's _native/."""
import os
import pathlib
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent


class BuildWithMake(build_py):
    def run(self):
        build = pathlib.Path(os.environ.get("EF_BUILD_DIR", ROOT / "build"))
        if (ROOT / "Makefile").is_file() and (ROOT / "python" / "module.mk").is_file():
            subprocess.run(["make", "-C", str(ROOT), "-j2", "--no-print-directory", f"BUILD={build}", "python"],
                           check=True)
        super().run()
        dest = pathlib.Path(self.build_lib) / "edgeflag" / "_native"
        dest.mkdir(parents=True, exist_ok=True)
        for name in ("libedgeflag.so", "libefpy.so"):
            src = build / name
            if not src.is_file():
                raise SystemExit(f"edgeflag: {src} was not built (run make python in {ROOT})")
            shutil.copy2(src, dest / name)


setup(cmdclass={"build_py": BuildWithMake})
