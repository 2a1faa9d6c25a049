"""Builds the `hexgait` extension module with the project's own CMake (the same build as
`cmake --build build --target hexgait_python`) for the Python that runs pip, and installs it.

HEXGAIT_BUILD_DIR=DIR reuses an already configured build tree of this checkout (seconds when
it is up to date; what the test suite does); otherwise the module is built in build/pip.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(hexgait VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = pathlib.Path(os.environ.get("HEXGAIT_BUILD_DIR") or ROOT / "build" / "pip")
        if not (build_dir / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                            "-DCMAKE_BUILD_TYPE=Release", f"-DPython_EXECUTABLE={sys.executable}",
                            "-DHEXGAIT_BUILD_TESTS=OFF", "-DHEXGAIT_BUILD_BENCHMARKS=OFF"],
                           check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "hexgait_python",
                        "-j", str(os.cpu_count() or 2)], check=True)
        suffix = self.get_ext_filename("hexgait").removeprefix("hexgait")
        built = build_dir / "python" / f"hexgait{suffix}"
        if not built.exists():
            sys.exit(f"hexgait: {built} was not built: the build tree's Python is not "
                     f"{sys.executable} (configure it with -DPython_EXECUTABLE={sys.executable})")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(version=project_version(),
      ext_modules=[Extension("hexgait", sources=[])],
      cmdclass={"build_ext": CMakeBuild})
