#!/bin/sh
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Runs inside the test VM (run-vm-tests.sh), in a read-only chroot of the host with vcan0 up,
# vcandown down, and OUT writable. Usage: in-vm-tests.sh BUILD OUT CANUTILS_BIN
set -u
build=$1 out=$2 canutils=$3
tests="$build/bin/robogene_can_tests"
export ROBOGENE_CAN_VCAN=vcan0 ROBOGENE_CAN_VCAN_DOWN=vcandown ROBOGENE_BIN="$build/bin/robogene"
export ROBOGENE_CAN_LOG_DIR="$out" ROBOGENE_CAN_DIR=/run/robogene-can
rc=0
# Runs the tests FILTER selects; selecting none is a failure, never a silent pass.
suite() {
  filter=$1; shift
  n=$("$tests" --gtest_list_tests --gtest_filter="$filter" | grep -c '^  ')
  if [ "$n" -eq 0 ]; then echo "in-vm-tests: no test matches $filter"; rc=1; return; fi
  "$tests" --gtest_filter="$filter" "$@" || rc=1
}

echo "=== SocketCAN backend tests"
suite 'SocketCan*' --gtest_output="xml:$out/socketcan-tests.xml"

echo "=== the head simulator and the driver over vcan0, recorded by can-utils' candump"
"$canutils/candump" -L vcan0 > "$out/candump-vcan0.log" &
dump=$!
suite 'CanHeadOverSocketCan*' --gtest_output="xml:$out/head-tests.xml"
kill "$dump"; wait "$dump" 2>/dev/null

echo "=== a firmware update over vcan0: can-flash against can-sim's bootloaders, interrupted and redone"
suite 'CanFlashOverSocketCan*' --gtest_output="xml:$out/flash-tests.xml"

echo "=== candump's own recording read back by robogene's candump reader"
export ROBOGENE_CAN_CANDUMP_LOG="$out/candump-vcan0.log"
suite 'CandumpInterop*'
exit $rc
