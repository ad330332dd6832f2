#!/usr/bin/env bash
# Installs the Debian 12 packages the build needs; only the missing ones, so it is quick to rerun.
set -euo pipefail
# libssl-dev: SHA-256 of plugin files (provenance). clang: the test that loads a clang-built
# plugin, and with libclang-rt-14-dev tools/fuzz.sh (libFuzzer, sanitizers). chromium: the tests
# that open the HTML report and player. python3: the player test's arithmetic.
packages=(g++ cmake make libboost-dev libboost-program-options-dev libeigen3-dev libtbb-dev
          nlohmann-json3-dev libyaml-cpp-dev libsqlite3-dev libssl-dev catch2 clang libclang-rt-14-dev
          chromium python3)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
