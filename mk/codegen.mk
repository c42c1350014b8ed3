# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The IDL compiler: `make generate` rewrites the generated sources from interfaces/idl/,
# `make check-generated` fails (naming each file) when a committed one is stale.

CODEGEN := PYTHONPATH=$(ROOT)/codegen $(PY) -m robogene_codegen

.PHONY: generate check-generated test-codegen
generate: $(VENV)/.stamp
	$(CODEGEN) generate

check-generated: $(VENV)/.stamp
	$(CODEGEN) check

# The Python RPC tests need the compiled core (robogene.Bottle), hence `python`.
test-codegen: $(VENV)/.stamp python
	$(PY) -m pytest -q -p no:cacheprovider tests/codegen

ALL_TARGETS  += check-generated
TEST_TARGETS += check-generated test-codegen
HELP_LINES   += "make generate   regenerate code and docs from interfaces/idl/" \
                "make check-generated  fail if generated files are stale" \
                "make test-codegen     run the IDL and codegen tests"
