# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Generated code: codegen/generated-manifest.yaml lists every generated file and its generator.
# `make generate` runs them all and writes what changed; `make check-generated` fails (naming each
# file) when a committed one is stale or missing, or a generated folder holds a file it does not list.
# GENERATED_NEEDS: the make targets the manifest's generators need first (their `needs:`, e.g. the
# compiled module for the type stub, the fabrication package for the tables of docs/fabricate.md).

CODEGEN := PYTHONPATH=$(ROOT)/codegen $(PY) -m robogene_codegen
GENERATED_MANIFEST := codegen/generated-manifest.yaml
GENERATED_NEEDS ?= $(sort $(shell sed -n 's/^ *needs: *\([a-z][a-z0-9-]*\) *$$/\1/p' $(GENERATED_MANIFEST)))

.PHONY: generate check-generated test-codegen test-can-protocol
# In two passes: what needs nothing built first, so that the build products (the compiled module, the
# package) are then made from the fresh sources, and after them every generator.
generate: $(VENV)/.stamp
	$(CODEGEN) generate --only sources
	$(if $(strip $(GENERATED_NEEDS)),$(MAKE) --no-print-directory $(GENERATED_NEEDS))
	$(CODEGEN) generate --fab $(FAB)

check-generated: $(VENV)/.stamp $(GENERATED_NEEDS)
	$(CODEGEN) check --fab $(FAB)

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
HELP_LINES   += "make generate   run every generator of codegen/generated-manifest.yaml (code, docs, stub, tables)" \
                "make check-generated  fail if a generated file is stale, missing or not in the manifest" \
                "make test-codegen     run the IDL and codegen tests" \
                "make test-can-protocol  CAN codecs (C++ and Python), DBC, board configs"
