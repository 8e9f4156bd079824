"""`pip install .`: builds the Python module grassfire with CMake and installs it.

The module is the CMake target grassfire_python (kernel/python/CMakeLists.txt); this file
only drives CMake from setuptools' build_ext and copies the built module to where the wheel
expects it. pyproject.toml holds the metadata; docs/library.md, "Python", the commands.

- By default it configures the checkout into setuptools' temporary folder (Release,
  GRASSFIRE_PYTHON=ON, this interpreter as Python_EXECUTABLE) and builds the module and the
  kernel archive it links: the same apt packages as run.sh, and on 2 cores about the time
  of the kernel's build (docs/library.md gives the measured time).
- GRASSFIRE_BUILD_DIR=DIR reuses a CMake build folder already configured with
  GRASSFIRE_PYTHON=ON (e.g. build/): it builds the target there (nothing when it is up to
  date) and installs that module. The module must have been built for this interpreter's
  ABI (its file name's suffix); otherwise the build stops with a message saying so.
- CMAKE_BUILD_PARALLEL_LEVEL sets the jobs (default 2).
"""
import importlib.machinery
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "kernel" / "grassfire_version.h").read_text(encoding="utf-8")
    return re.search(r'#define GRASSFIRE_VERSION "([^"]+)"', text).group(1)


def fail(message):
    sys.exit(f"grassfire setup.py: {message}")


def cache_value(build_dir, key):
    cache = build_dir / "CMakeCache.txt"
    if not cache.is_file():
        return None
    for line in cache.read_text(encoding="utf-8", errors="replace").splitlines():
        if line.startswith(key + ":"):
            return line.split("=", 1)[1]
    return None


class CMakeBuild(build_ext):
    """build_ext for the one extension grassfire, built by CMake."""

    def build_extension(self, ext):
        reuse = os.environ.get("GRASSFIRE_BUILD_DIR")
        if reuse:
            build_dir = Path(reuse).resolve()
            if cache_value(build_dir, "GRASSFIRE_PYTHON") not in ("ON", "TRUE", "1"):
                fail(f"GRASSFIRE_BUILD_DIR={reuse} is not a CMake build folder configured with -DGRASSFIRE_PYTHON=ON")
        else:
            build_dir = Path(self.build_temp).resolve() / "cmake"
            self.spawn(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                        "-DGRASSFIRE_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"])
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        self.spawn(["cmake", "--build", str(build_dir), "--target", "grassfire_python", "-j", jobs])
        built = sorted((build_dir / "kernel" / "python").glob("grassfire*.so"))
        if len(built) != 1:
            fail(f"expected one built module grassfire*.so in {build_dir / 'kernel' / 'python'}, found {len(built)}")
        suffix = built[0].name[len("grassfire"):]
        if suffix not in importlib.machinery.EXTENSION_SUFFIXES:
            fail(f"{built[0]} was built for another Python than {sys.executable} "
                 f"(suffix {suffix}, this one loads {importlib.machinery.EXTENSION_SUFFIXES})")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    version=project_version(),
    ext_modules=[Extension("grassfire", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own folders beside, not inside, a CMake build/ of the checkout.
    options={"build": {"build_base": "build-pip"}, "egg_info": {"egg_base": "build-pip"}},
)
