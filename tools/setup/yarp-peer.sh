#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Build a real YARP 3 peer (yarp-middleware 3.5.0 from PyPI: C++ libraries, the yarp/yarpserver/yarpdev
# tools and the SWIG `yarp` Python module) into .yarp-venv, for the interoperability tests.
# Idempotent: a stamp inside the venv records what was built, so a second run returns at once. The
# wheel is kept in a cache keyed by this script and the pinned build requirements, so rebuilding the
# venv on the same machine takes seconds instead of ~25 minutes (pip's own wheel cache is keyed by
# the sdist URL only and would hand back a wheel built with other settings).
# Usage: tools/setup/yarp-peer.sh [VENV_DIR]      (default: <repo>/.yarp-venv)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
venv=${1:-$root/.yarp-venv}
version=3.5.0
python=${PYTHON3:-python3}
constraints=$root/tools/setup/requirements-yarp-peer.txt
key=$(cat "${BASH_SOURCE[0]}" "$constraints" | sha256sum | cut -c1-16)
stamp=$venv/.robogene-yarp-peer
wheels=${YARP_PEER_WHEEL_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/robogene/yarp-peer/$key}

if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$key" ] && [ -x "$venv/bin/yarp" ]; then
  exit 0
fi

"$root/tools/setup/apt-install.sh" "$root/tools/setup/apt/yarp-peer.txt"
[ -x "$venv/bin/python" ] || "$python" -m venv "$venv"
export PIP_CONSTRAINT=$constraints   # also reaches pip's isolated build environment

if ! ls "$wheels"/yarp_middleware-$version-*.whl >/dev/null 2>&1; then
  # yarp-middleware 3.5.0 predates the cmake and gcc on this platform: pip's build env pulls a cmake
  # that refuses the project's old cmake_minimum_required, and gcc 12 no longer includes these
  # standard headers transitively, so several YARP sources fail to compile without them.
  export CMAKE_POLICY_VERSION_MINIMUM=3.5
  export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2}
  CXXFLAGS="${CXXFLAGS:-}"
  for h in utility cstdint limits iterator algorithm functional memory string array cmath; do
    CXXFLAGS="$CXXFLAGS -include $h"
  done
  # The PyPI build is static (BUILD_SHARED_LIBS=OFF), where YARP_init must call the generated
  # add_yarp{car,pm,mod}_plugins() to register carrier/monitor/device plugins. YARP 3.5.0 sets those
  # calls as properties of a source named CustomInit.cpp, but the file is yarp/os/Network.CustomInit.cpp,
  # so without these definitions yarpdev knows no device at all ("not built in").
  CXXFLAGS="$CXXFLAGS -Dyarpcar_INIT_FUNCTION=add_yarpcar_plugins -Dyarppm_INIT_FUNCTION=add_yarppm_plugins"
  CXXFLAGS="$CXXFLAGS -Dyarpmod_INIT_FUNCTION=add_yarpmod_plugins"
  export CXXFLAGS
  # fakeMotionControl is off by default in 3.5.0; the tests need it behind controlboardwrapper2.
  devices="ENABLE_yarpmod_fakeMotionControl:BOOL=ON"
  mkdir -p "$wheels.tmp"
  "$venv/bin/python" -m pip wheel --disable-pip-version-check --no-cache-dir --no-deps -w "$wheels.tmp" \
    --config-settings="--build-option=build_ext --define=$devices" "yarp-middleware==$version"
  rm -rf "$wheels" && mv "$wheels.tmp" "$wheels"
fi
"$venv/bin/python" -m pip install --disable-pip-version-check --force-reinstall --no-deps \
  "$wheels"/yarp_middleware-$version-*.whl

# The tests need these; fail here, not in the middle of a test run.
for tool in yarp yarpserver yarpdev; do
  [ -x "$venv/bin/$tool" ] || { echo "yarp-peer: $venv/bin/$tool was not built" >&2; exit 1; }
done
"$venv/bin/python" -c 'import yarp; yarp.Network.init(); b = yarp.Bottle("1 [ok]"); assert b.size() == 2' \
  || { echo "yarp-peer: the yarp Python module does not work" >&2; exit 1; }
if ! "$venv/bin/yarpdev" --list 2>&1 | grep -q fakeMotionControl; then
  echo "yarp-peer: yarpdev was built without the fakeMotionControl device" >&2; exit 1
fi

echo "$key" > "$stamp"
echo "yarp-peer: YARP $version ready in $venv"
