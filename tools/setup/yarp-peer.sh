#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Build a real YARP 3 peer (yarp-middleware 3.5.0 from PyPI: C++ libraries, the yarp/yarpserver tools
# and the SWIG `yarp` Python module) into .yarp-venv for the interoperability tests, plus
# bin/yarpdev-static, a yarpdev that can see the statically linked devices (see its main.cpp).
# Idempotent: a stamp records what was built, so a second run returns at once. The wheel is kept in
# a cache keyed by the build settings below and the pinned build requirements, so rebuilding the venv
# on the same machine takes seconds instead of ~25 minutes (pip's own wheel cache is keyed by the
# sdist URL only and would hand back a wheel built with other settings).
# Usage: tools/setup/yarp-peer.sh [VENV_DIR]      (default: <repo>/.yarp-venv)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
venv=${1:-$root/.yarp-venv}
version=3.5.0
python=${PYTHON3:-python3}
constraints=$root/tools/setup/requirements-yarp-peer.txt
launcher=$root/tests/interop/yarpdev_static

# yarp-middleware 3.5.0 predates the cmake and gcc on this platform: pip's build env pulls a cmake
# that refuses the project's old cmake_minimum_required, and gcc 12 no longer includes these
# standard headers transitively, so several YARP sources fail to compile without them.
includes=""
for h in utility cstdint limits iterator algorithm functional memory string array cmath; do
  includes="$includes -include $h"
done
# fakeMotionControl is off by default in 3.5.0; the tests drive it behind controlboardwrapper2.
devices="ENABLE_yarpmod_fakeMotionControl:BOOL=ON"

wheel_key=$( (echo "$version|$includes|$devices"; cat "$constraints") | sha256sum | cut -c1-16)
wheels=${YARP_PEER_WHEEL_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/robogene/yarp-peer/$wheel_key}
stamp=$venv/.robogene-yarp-peer
want=$(cat "${BASH_SOURCE[0]}" "$constraints" "$launcher"/* | sha256sum | cut -c1-16)

if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -x "$venv/bin/yarpdev-static" ]; then
  exit 0
fi

"$root/tools/setup/apt-install.sh" "$root/tools/setup/apt/yarp-peer.txt"
[ -x "$venv/bin/python" ] || "$python" -m venv "$venv"
export PIP_CONSTRAINT=$constraints   # also reaches pip's isolated build environment

if ! ls "$wheels"/yarp_middleware-$version-*.whl >/dev/null 2>&1; then
  rm -rf "$wheels.tmp" && mkdir -p "$wheels.tmp"
  CMAKE_POLICY_VERSION_MINIMUM=3.5 CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2} \
  CXXFLAGS="${CXXFLAGS:-} $includes" \
    "$venv/bin/python" -m pip wheel --disable-pip-version-check --no-cache-dir --no-deps -w "$wheels.tmp" \
    --config-settings="--build-option=build_ext --define=$devices" "yarp-middleware==$version"
  rm -rf "$wheels" && mv "$wheels.tmp" "$wheels"
fi
"$venv/bin/python" -m pip install --disable-pip-version-check --force-reinstall --no-deps \
  "$wheels"/yarp_middleware-$version-*.whl
# YARP's CMake package needs YCM to be found; used only to build the launcher below.
"$venv/bin/python" -m pip install --disable-pip-version-check ycm-cmake-modules

prefix=$(echo "$venv"/lib/python3*/site-packages/yarp)
ycm=$(echo "$venv"/lib/python3*/site-packages/ycm_cmake_modules/share/cmake/YCM)
build=$(mktemp -d)
trap 'rm -rf "$build"' EXIT
CXXFLAGS="${CXXFLAGS:-} $includes" cmake -S "$launcher" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DYCM_DIR="$ycm" -DCMAKE_INSTALL_PREFIX="$venv" >/dev/null
cmake --build "$build" -j "${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
cmake --install "$build" >/dev/null

# The tests need these; fail here, not in the middle of a test run.
for tool in yarp yarpserver yarpdev-static; do
  [ -x "$venv/bin/$tool" ] || { echo "yarp-peer: $venv/bin/$tool was not built" >&2; exit 1; }
done
"$venv/bin/python" -c 'import yarp; yarp.Network.init(); b = yarp.Bottle("1 [ok]"); assert b.size() == 2' \
  || { echo "yarp-peer: the yarp Python module does not work" >&2; exit 1; }
if ! "$venv/bin/yarpdev-static" --list 2>&1 | grep -q fakeMotionControl; then
  echo "yarp-peer: yarpdev-static does not know the fakeMotionControl device" >&2; exit 1
fi

echo "$want" > "$stamp"
echo "yarp-peer: YARP $version ready in $venv"
