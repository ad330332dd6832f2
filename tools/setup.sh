#!/usr/bin/env bash
# Installs the Debian 12 packages the build needs; only the missing ones, so it is quick to rerun.
#   tools/setup.sh [PACKAGE...]   also these (a tool's own needs, e.g. tools/slurm-check.sh's Slurm)
#   tools/setup.sh --demo         only what the demo's build needs (the preset demo: acoplan and the
#                                 plugins), a few minutes on a fresh machine; tools/test.sh adds the rest
set -euo pipefail
# The demo's: the compiler, CMake, the libraries acoplan and the plugins link (libssl-dev: SHA-256
# of plugin files, provenance; libsqlite3-dev: the studies' library, which the configuration finds)
# and ccache, which gives the later builds back what the demo compiled.
demo_packages=(g++ cmake make libboost-dev libboost-program-options-dev libeigen3-dev libtbb-dev
               nlohmann-json3-dev libyaml-cpp-dev libsqlite3-dev libssl-dev ccache)
# The rest. catch2: the tests. clang: the test that loads a clang-built
# plugin, and with libclang-rt-14-dev tools/fuzz.sh (libFuzzer, sanitizers). chromium: the tests
# that open the HTML report and player. python3: the player test's arithmetic. openmpi-bin and
# libopenmpi-dev: acobench under mpirun (the release and debug presets build it with MPI).
# python3-dev, pybind11-dev, python3-numpy: the Python package (python/) and the python bridge
# plugins; python3-pandas, python3-pytest, python3-matplotlib: its DataFrames, tests and examples.
# python3-venv, python3-pip, python3-setuptools, python3-wheel: pip install ./python (the test
# python_pip_install), with ccache, which compiles that build from the release build's objects;
# mypy: the test python_mypy (the package's types and the examples).
# python3-nbclient, python3-nbformat, python3-ipykernel: the test that runs the example notebook.
# clang-format-14: the test that the sources are formatted as .clang-format says (tools/format.sh).
# libompl-dev: the 'ompl' planner (baselines/ompl; without it the build leaves the planner out) and
# an OMPL benchmark log for the test that OMPL's own tools read our databases, with ompl-demos
# (ompl_benchmark_statistics) and sqlite3.
# liboctomap-dev: the map plugin map/octomap (.bt and .ot voxel worlds) and tools/octomapgen,
# which made data/maps/octomap (without it the build leaves both out).
# ROS 1 (Debian's own packages): libroscpp-dev and libnav-msgs-dev build aco-ros-planner
# (hosts/ros_planner; without them the build leaves it out); python3-rosmaster, python3-rospy,
# python3-nav-msgs, python3-roslaunch and python3-rosservice run its test (a real master, a map
# published with rospy) and its launch file.
extra=("$@")
[ "${1:-}" != --demo ] || extra=()
packages=("${demo_packages[@]}" catch2 clang libclang-rt-14-dev
          chromium python3 openmpi-bin libopenmpi-dev python3-dev pybind11-dev python3-numpy python3-pandas
          python3-pytest python3-matplotlib python3-venv python3-pip python3-setuptools python3-wheel mypy
          python3-nbclient python3-nbformat python3-ipykernel clang-format-14 libompl-dev ompl-demos sqlite3
          liboctomap-dev libroscpp-dev libnav-msgs-dev python3-rosmaster python3-rospy python3-nav-msgs
          python3-roslaunch python3-rosservice "${extra[@]}")
# r-cran-irace: tools/irace/run.sh and the irace_tuning_run test. Installed without its
# recommended packages: they pull in hundreds of R packages (GDAL, spatial statistics) irace never loads.
packages_without_recommends=(r-cran-irace)
if [ "${1:-}" = --demo ]; then
  packages=("${demo_packages[@]}")
  packages_without_recommends=()
fi

missing() {
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || echo "$package"
  done
}
mapfile -t missing_packages < <(missing "${packages[@]}")
mapfile -t missing_without_recommends < <(missing "${packages_without_recommends[@]}")
if ((${#missing_packages[@]} + ${#missing_without_recommends[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing_packages[*]} ${missing_without_recommends[*]}"
  $sudo apt-get update -qq
  install() { DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$@" >/dev/null; }
  ((${#missing_packages[@]} == 0)) || install "${missing_packages[@]}"
  ((${#missing_without_recommends[@]} == 0)) || install --no-install-recommends "${missing_without_recommends[@]}"
fi
