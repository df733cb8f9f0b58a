"""The build of `pip install lib/python`: the extension stickslip._stickslip is built by the
project's own CMake (the target stickslip_python, with the library; no tests, benchmarks or command
line), then packaged with the pure-Python modules. The version is the project's (CMakeLists.txt).

STICKSLIP_CMAKE_BUILD_DIR: a CMake build tree to build in (kept, so a second install is quick);
by default a directory under setuptools' build_temp. CMAKE_BUILD_PARALLEL_LEVEL: the jobs."""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(stickslip VERSION ([0-9][0-9.]*)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("STICKSLIP_CMAKE_BUILD_DIR") or pathlib.Path(self.build_temp, "cmake")).resolve()
        generator = ["-G", "Ninja"] if shutil.which("ninja") and not (build / "Makefile").exists() else []
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), *generator, "-DCMAKE_BUILD_TYPE=Release",
                        "-DSTICKSLIP_BUILD_TESTS=OFF", "-DSTICKSLIP_BUILD_BENCHMARKS=OFF", "-DSTICKSLIP_BUILD_PYTHON=ON",
                        f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", "stickslip_python", "-j", jobs], check=True)
        built = sorted((build / "lib" / "python" / "stickslip").glob("_stickslip*.so"))
        if not built:
            raise RuntimeError(f"the CMake build in {build} made no stickslip/_stickslip*.so")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)


setup(
    version=project_version(),
    packages=["stickslip"],
    ext_modules=[Extension("stickslip._stickslip", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
)
