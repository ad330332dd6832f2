"""pip's build of the package: the native module through CMake, with what it loads at run time.

    python3 -m venv --system-site-packages v && v/bin/pip install --no-build-isolation ./python

The whole checkout is the CMake project: this configures it in release mode without the programs,
tests and benchmarks (ACO_BUILD_PROGRAMS=OFF), builds the libraries, plugins and module, installs
them with the package's own folder as the prefix, and puts them in the package beside _aco:
aco/lib (the libraries, whose names the module's RPATH $ORIGIN/lib reaches), aco/lib/aco/plugins
and aco/share/aco (presets, maps), where the installed libraries look for their plugins and data.

ACO_CMAKE_BUILD_DIR names the CMake build folder (default: under setuptools' build folder), so
that a later install rebuilds only what changed; ccache compiles when it is installed.
ACO_SETUPTOOLS_BUILD_DIR moves setuptools' build folder and egg-info out of python/ (the tests).
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

CHECKOUT = Path(__file__).resolve().parent.parent


def framework_version() -> str:
    """The project's version in CMakeLists.txt, the one acoplan --version prints."""
    found = re.search(r"project\(aco VERSION ([0-9.]+)", (CHECKOUT / "CMakeLists.txt").read_text())
    if not found:
        raise RuntimeError(f"no 'project(aco VERSION ...)' in {CHECKOUT / 'CMakeLists.txt'}")
    return found.group(1)


def runtime_libraries(libdir: Path) -> list:
    """The installed libraries under the names the loader asks for: libaco.so.0 (a link, copied as
    a file: wheels hold no links), not the linker's libaco.so nor the file libaco.so.0.1.0 it names."""
    files = sorted(libdir.glob("*.so*"))
    loaded_links = [f for f in files if f.is_symlink() and not f.name.endswith(".so")]
    named_by_link = {f.resolve() for f in loaded_links}
    return loaded_links + [f for f in files if not f.is_symlink() and f.resolve() not in named_by_link]


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build = Path(os.environ.get("ACO_CMAKE_BUILD_DIR") or Path(self.build_temp) / "cmake").resolve()
        prefix = build / "install" / "aco"  # the package's folder, as installed
        configure = ["cmake", "-S", str(CHECKOUT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DACO_BUILD_PROGRAMS=OFF", "-DACO_BUILD_TESTS=OFF", "-DACO_BUILD_BENCH=OFF",
                     "-DACO_WITH_MPI=OFF", f"-DPython3_EXECUTABLE={sys.executable}",
                     f"-DCMAKE_INSTALL_PREFIX={prefix}", "-DCMAKE_INSTALL_LIBDIR=lib", "-DACO_INSTALL_PYTHON_DIR=.."]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        # CMAKE_BUILD_PARALLEL_LEVEL, if set, is cmake's own choice of jobs.
        jobs = [] if os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") else ["-j", str(os.cpu_count() or 1)]
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build), *jobs], check=True)
        shutil.rmtree(prefix.parent, ignore_errors=True)
        subprocess.run(["cmake", "--install", str(build)], check=True, stdout=subprocess.DEVNULL)

        module = Path(self.get_ext_fullpath(ext.name))
        package = module.parent
        package.mkdir(parents=True, exist_ok=True)
        installed_module = next(prefix.glob("_aco*.so"), None)
        if installed_module is None:
            raise RuntimeError(f"cmake --install put no _aco module in {prefix}")
        shutil.copyfile(installed_module, module)
        for folder in ("lib", "share"):
            shutil.rmtree(package / folder, ignore_errors=True)
        (package / "lib").mkdir()
        for library in runtime_libraries(prefix / "lib"):
            shutil.copyfile(library, package / "lib" / library.name)
        shutil.copytree(prefix / "lib" / "aco" / "plugins", package / "lib" / "aco" / "plugins")
        shutil.copytree(prefix / "share", package / "share")


setuptools_build = os.environ.get("ACO_SETUPTOOLS_BUILD_DIR")
if setuptools_build:
    os.makedirs(setuptools_build, exist_ok=True)
setup(version=framework_version(), ext_modules=[Extension("aco._aco", sources=[])], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": setuptools_build}, "egg_info": {"egg_base": setuptools_build}}
      if setuptools_build else {})
