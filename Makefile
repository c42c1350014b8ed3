# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# `make`      builds everything a lab or a developer needs (set-up included).
# `make test` runs every test (set-up included).
# Each area of the repository adds its targets in mk/<area>.mk: ALL_TARGETS for `make`,
# TEST_TARGETS for `make test`. `make help` lists the rest.

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := all
.DELETE_ON_ERROR:

ROOT    := $(abspath .)
BUILD   := $(ROOT)/build
STAMPS  := $(BUILD)/.stamps
VENV    := $(ROOT)/.venv
PY      := $(VENV)/bin/python
PYTHON3 ?= python3
JOBS    ?= $(shell nproc)

ALL_TARGETS  :=
TEST_TARGETS :=
HELP_LINES   :=

include mk/setup.mk
include $(filter-out mk/setup.mk,$(sort $(wildcard mk/*.mk)))

.PHONY: all test help clean
all: $(ALL_TARGETS)
test: $(TEST_TARGETS)
	@echo "make test: every suite passed"

help:
	@printf '%s\n' "make            build everything (runtime, CLI, Python package, generated code check, fabrication package)" \
	  "make test       run every test suite" $(HELP_LINES) "make clean      remove build/ (keeps .venv)"

clean:
	rm -rf $(BUILD)
