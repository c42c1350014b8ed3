# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The IDL compiler: `make generate` rewrites the generated sources from interfaces/idl/,
# `make check-generated` fails (naming each file) when a committed one is stale.

CODEGEN := PYTHONPATH=$(ROOT)/codegen $(PY) -m robogene_codegen

.PHONY: generate check-generated test-codegen test-can-protocol
generate: $(VENV)/.stamp
	$(CODEGEN) generate

check-generated: $(VENV)/.stamp
	$(CODEGEN) check

# The Python RPC tests need the compiled core (robogene.Bottle), hence `python`; the end-to-end test
# of a new IDL method links a server against the C++ runtime and registers it with `robogene server`,
# hence `runtime`.
test-codegen: $(VENV)/.stamp python runtime
	$(PY) -m pytest -q -p no:cacheprovider tests/codegen

# The CAN protocol and board configs (interfaces/idl/can_motor_control.yaml, head_boards.yaml): codec
# vectors in C++ and Python, the DBC against cantools, the .ini through the runtime's Property reader,
# the firmware headers through gcc. Needs cantools (pinned in tools/setup/requirements-can.txt).
$(STAMPS)/py-can: tools/setup/requirements-can.txt $(VENV)/.stamp | $(STAMPS)
	$(PY) -m pip install -q --disable-pip-version-check -r $<
	touch $@

test-can-protocol: $(STAMPS)/py-can
	$(PY) -m pytest -q -p no:cacheprovider tests/can

ALL_TARGETS  += check-generated
TEST_TARGETS += check-generated test-codegen test-can-protocol
HELP_LINES   += "make generate   regenerate code and docs from interfaces/idl/" \
                "make check-generated  fail if generated files are stale" \
                "make test-codegen     run the IDL and codegen tests" \
                "make test-can-protocol  CAN codecs (C++ and Python), DBC, board configs"
