"""Builds coatfft's extension with the project's own CMake (pyproject.toml says why).

Only the library and the module are built (no CLI, tests, benchmarks or tables), in Release,
with the interpreter that runs pip; the extension lands where setuptools packs it.
"""
import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        source = Path(__file__).resolve().parent
        # get_ext_fullpath: .../coatfft/_coatfft.cpython-*.so; the package folder's parent is
        # what COATFFT_PYTHON_OUTPUT_DIR names.
        package_parent = Path(self.get_ext_fullpath(ext.name)).resolve().parent.parent
        build = Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(source), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
            "-DCOATFFT_PYTHON=ON", "-DCOATFFT_BUILD_CLI=OFF", "-DCOATFFT_BUILD_TESTS=OFF",
            "-DCOATFFT_BUILD_BENCH=OFF", "-DCOATFFT_BUILD_TABLES=OFF",
            "-DCOATFFT_BUILD_EXAMPLES=OFF", f"-DPython3_EXECUTABLE={sys.executable}",
            # Built once: the library, the scene layer and the module as unity builds; without
            # the distributed layer, which the module does not offer (docs/scale.md).
            "-DCOATFFT_UNITY=ON", "-DCOATFFT_MPI=OFF",
            f"-DCOATFFT_PYTHON_OUTPUT_DIR={package_parent}",
        ]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", "_coatfft", "-j", jobs],
                       check=True)


# setuptools' build folders go to build-pip/, not build/ (README's CMake build).
setup(
    ext_modules=[CMakeExtension("coatfft._coatfft")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-pip"}},
)
