# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Interoperability with real YARP 3: a YARP 3.5.0 peer built from PyPI into .yarp-venv (about 25 minutes
# on 2 cores the first time, seconds afterwards thanks to pip's wheel cache), and the tests that run
# it against our CLI (build/bin/robogene) and Python package.

YARP_PEER_INPUTS := tools/setup/yarp-peer.sh tools/setup/apt/yarp-peer.txt tools/setup/requirements-yarp-peer.txt

$(STAMPS)/yarp-peer: $(YARP_PEER_INPUTS) | $(STAMPS)
	tools/setup/yarp-peer.sh $(ROOT)/.yarp-venv
	touch $@

.PHONY: yarp-peer test-interop
yarp-peer: $(STAMPS)/yarp-peer

test-interop: runtime python yarp-peer
	ROBOGENE_BIN=$${ROBOGENE_BIN:-$(BUILD)/bin/robogene} YARP_PEER_VENV=$(ROOT)/.yarp-venv \
	  $(PY) -m pytest -q -p no:cacheprovider tests/interop

HELP_LINES += "make yarp-peer  build the real YARP 3.5.0 peer into .yarp-venv (~25 min the first time)" \
              "make test-interop run our CLI and Python package against the real YARP peer"
