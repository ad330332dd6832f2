#!/usr/bin/env bash
# Installs the Debian 12 packages the build needs; only the missing ones, so it is quick to rerun.
set -euo pipefail
packages=(g++ cmake make libboost-dev libboost-program-options-dev libeigen3-dev libtbb-dev
          nlohmann-json3-dev libyaml-cpp-dev libsqlite3-dev catch2
          chromium python3 clang libclang-rt-14-dev)  # chromium: the tests that open the HTML report and player; python3: the player test's arithmetic; clang: tools/fuzz.sh (libFuzzer)
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
