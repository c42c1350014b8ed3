#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Build a real YARP 3 peer (yarp-middleware 3.5.0 from PyPI: C++ libraries, the yarp/yarpserver/yarpdev
# tools and the SWIG `yarp` Python module) into .yarp-venv, for the interoperability tests.
# Idempotent: a stamp inside the venv records what was built, so a second run returns at once;
# pip's wheel cache makes a rebuild on the same machine take seconds instead of ~25 minutes.
# Usage: tools/setup/yarp-peer.sh [VENV_DIR]      (default: <repo>/.yarp-venv)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
venv=${1:-$root/.yarp-venv}
version=3.5.0
python=${PYTHON3:-python3}
stamp=$venv/.robogene-yarp-peer
want="yarp-middleware==$version $(sha256sum "${BASH_SOURCE[0]}" | cut -c1-16)"

if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -x "$venv/bin/yarp" ]; then
  exit 0
fi

"$root/tools/setup/apt-install.sh" "$root/tools/setup/apt/yarp-peer.txt"

# yarp-middleware 3.5.0 predates the cmake and gcc on this platform: pip's build env pulls a cmake
# that refuses the project's old cmake_minimum_required, and gcc 12 no longer includes these
# standard headers transitively, so several YARP sources fail to compile without them.
export CMAKE_POLICY_VERSION_MINIMUM=3.5
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2}
headers="utility cstdint limits iterator algorithm functional memory string array cmath"
CXXFLAGS="${CXXFLAGS:-}"
for h in $headers; do CXXFLAGS="$CXXFLAGS -include $h"; done
export CXXFLAGS

# fakeMotionControl is off by default in 3.5.0; the tests need it behind controlboardwrapper2.
devices="ENABLE_yarpmod_fakeMotionControl:BOOL=ON"

[ -x "$venv/bin/python" ] || "$python" -m venv "$venv"
PIP_CONSTRAINT="$root/tools/setup/requirements-yarp-peer.txt" \
  "$venv/bin/python" -m pip install --disable-pip-version-check \
  --config-settings="--build-option=build_ext --define=$devices" "yarp-middleware==$version"

# The tests need these; fail here, not in the middle of a test run.
for tool in yarp yarpserver yarpdev; do
  [ -x "$venv/bin/$tool" ] || { echo "yarp-peer: $venv/bin/$tool was not built" >&2; exit 1; }
done
"$venv/bin/python" -c 'import yarp; yarp.Network.init(); b = yarp.Bottle("1 [ok]"); assert b.size() == 2' \
  || { echo "yarp-peer: the yarp Python module does not work" >&2; exit 1; }

echo "$want" > "$stamp"
echo "yarp-peer: YARP $version ready in $venv"
