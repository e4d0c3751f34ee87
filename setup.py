"""`pip install --no-build-isolation .` (pyproject.toml): builds the Python module `hertzdash` with
CMake for the interpreter that runs pip, and puts it with the data tables into the wheel.

The module is the CMake target hertzdash_python, configured with -DPython_EXECUTABLE=<this
interpreter> and the hertzdash libraries static (-DBUILD_SHARED_LIBS=OFF): the installed module is
one file that needs no build tree and no installed libhertzdash_*.so. It finds the data tables as a
library finds them (simulation/paper/paper_parameters.hpp): share/hertzdash/data beside it, in
site-packages.

Environment:
  CMAKE_ARGS                  more arguments for CMake's configure step, split as a shell would
                              (-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); they come last and win.
  CMAKE_BUILD_PARALLEL_LEVEL  the build's jobs (CMake's own variable); else every core.
  HERTZDASH_PYTHON_BUILD_DIR  where setuptools and CMake build (default: build-python/ in the
                              source tree, git-ignored; build/ is the CMake build of `make`).
  HERTZDASH_CMAKE_BUILD_DIR   a configured CMake build tree of this source with the Python module
                              (`make`'s build/): the module is then linked there from the objects
                              it already compiled (target hertzdash_python_wheel,
                              python/CMakeLists.txt), the same one-file module with no run path,
                              instead of compiling everything again (tests/python_package.sh).
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent
BUILD = Path(os.environ.get("HERTZDASH_PYTHON_BUILD_DIR") or SOURCE / "build-python").resolve()
DATA_BELOW_MODULE = Path("share", "hertzdash", "data")  # paper_parameters.hpp: data_dir_below_prefix


def project_version():
    """The version of CMakeLists.txt's project(), the one version of hertzdash."""
    match = re.search(r"project\(hertzdash VERSION ([0-9.]+)", (SOURCE / "CMakeLists.txt").read_text())
    if not match:
        sys.exit("setup.py: no 'project(hertzdash VERSION x.y.z' in CMakeLists.txt")
    return match.group(1)


class CMakeBuild(build_ext):
    """Builds the module with CMake: its target only, or linked in a given build tree."""

    def build_extension(self, ext):
        prebuilt = os.environ.get("HERTZDASH_CMAKE_BUILD_DIR")
        if prebuilt:
            cmake_build = Path(prebuilt).resolve()
            built = cmake_build / "python" / "wheel" / Path(self.get_ext_filename(ext.name)).name
            self.run_cmake([], ["cmake", "--build", str(cmake_build), "--target", "hertzdash_python_wheel"], built,
                           f"is {cmake_build} a build tree with the Python module for {sys.executable}?")
        else:
            cmake_build = Path(self.build_temp).resolve() / "cmake"
            self.build_standalone(cmake_build)
            built = cmake_build / "python" / Path(self.get_ext_filename(ext.name)).name
        module = Path(self.get_ext_fullpath(ext.name))
        module.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, module)
        shutil.copytree(SOURCE / "data", module.parent / DATA_BELOW_MODULE, dirs_exist_ok=True)

    def build_standalone(self, cmake_build):
        """Configures a build of the module's target only, the parts the module does not use off."""
        # No run path: the module holds the hertzdash libraries, the others are the system's (without
        # CMAKE_SKIP_RPATH the build tree's module has an empty one, padded for cmake --install, and
        # ld.so reads an empty entry as the current directory).
        configure = ["cmake", "-S", str(SOURCE), "-B", str(cmake_build), f"-DPython_EXECUTABLE={sys.executable}",
                     "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_SHARED_LIBS=OFF", "-DHERTZDASH_WITH_PYTHON=ON",
                     "-DHERTZDASH_WITH_MPI=OFF", "-DHERTZDASH_WITH_BENCH=OFF", "-DCMAKE_SKIP_RPATH=ON",
                     *shlex.split(os.environ.get("CMAKE_ARGS", ""))]
        build = ["cmake", "--build", str(cmake_build), "--target", "hertzdash_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(self.parallel or os.cpu_count() or 1)]
        self.run_cmake(configure, build, cmake_build / "python" / Path(self.get_ext_filename("hertzdash")).name,
                       "the configure step's 'hertzdash:' lines say what is missing (python3-dev and "
                       f"pybind11-dev for this interpreter, {sys.executable})")

    @staticmethod
    def run_cmake(configure, build, built, hint):
        """Runs CMake's configure (if any) and build steps; exits, with `hint`, unless `built` is then a file."""
        if configure:
            subprocess.run(configure, check=True)
        if subprocess.run(build).returncode != 0 or not built.is_file():
            sys.exit(f"setup.py: {built} was not built; {hint}")


BUILD.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    ext_modules=[Extension("hertzdash", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Out of the source tree's build/ (CMake's) and, with HERTZDASH_PYTHON_BUILD_DIR, out of the tree.
    options={"build": {"build_base": str(BUILD)}, "egg_info": {"egg_base": str(BUILD)}},
)
