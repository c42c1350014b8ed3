# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Interoperability with real YARP 3: a YARP 3.5.0 peer built from PyPI into .yarp-venv (about 25 minutes
# on 2 cores the first time, about a minute afterwards: the wheel is cached under ~/.cache/robogene),
# and the tests that run it against our CLI (build/bin/robogene). See docs/interop.md.

YARP_PEER_INPUTS := tools/setup/yarp-peer.sh tools/setup/apt/yarp-peer.txt tools/setup/requirements-yarp-peer.txt

$(STAMPS)/yarp-peer: $(YARP_PEER_INPUTS) $(wildcard tests/interop/yarpdev_static/*) | $(STAMPS)
	tools/setup/yarp-peer.sh $(ROOT)/.yarp-venv
	touch $@

.PHONY: yarp-peer test-interop
yarp-peer: $(STAMPS)/yarp-peer

test-interop: runtime python yarp-peer
	ROBOGENE_BIN=$${ROBOGENE_BIN:-$(BUILD)/bin/robogene} YARP_PEER_VENV=$(ROOT)/.yarp-venv \
	  $(PY) -m pytest -q -p no:cacheprovider tests/interop

TEST_TARGETS += test-interop
HELP_LINES += "make yarp-peer  build the real YARP 3.5.0 peer into .yarp-venv (~25 min the first time)" \
              "make test-interop run our CLI and Python package against the real YARP peer"
