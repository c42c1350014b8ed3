# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Head mechanics, BOM and fabrication package (hardware/mechanics, hardware/bom -> build/fab).
# `make fab` builds the package; inside it every output is keyed by a content hash, so only what changed is
# rebuilt. BOARD_BOMS: CSV BOMs of the KiCad boards (Reference, Value, Footprint, MPN, Qty) merged into the
# BOM, each boards.count times per head (PATH:N for another count). BOARD_STEP: the motor board's STEP, placed
# boards.count times in the assembly. By default both come from mk/electronics.mk, which is then built first.

FAB        := $(BUILD)/fab
HW_PY      := PYTHONPATH=$(ROOT)/hardware/mechanics:$(ROOT)/hardware/bom $(PY)
ifdef ELEC_FAB
BOARD_BOMS   ?= $(ELEC_FAB)/bom.csv
BOARD_STEP   ?= $(ELEC_FAB)/board.step
HW_BOARD_DEP := $(ELEC_FAB)/.stamp
endif
HW_SOURCES := hardware/head-parameters.yaml $(shell find hardware/mechanics hardware/head-model hardware/bom -type f \
                \( -name '*.py' -o -name '*.yaml' -o -name '*.scad' \) 2>/dev/null)

# Debian packages. Once KiCad 9 has come from bookworm-backports, libhwloc15 is a backports version and
# FreeCAD's libhwloc-plugins must come from there too, or apt refuses to resolve.
$(STAMPS)/apt-hardware: tools/setup/apt/hardware.txt tools/setup/apt-install.sh | $(STAMPS)
	extra=(); \
	if dpkg-query -W -f='$${Version}' libhwloc15 2>/dev/null | grep -q bpo; then \
	  extra=(-- libhwloc-plugins/bookworm-backports); fi; \
	tools/setup/apt-install.sh $< "$${extra[@]}"
	touch $@

$(STAMPS)/py-hardware: tools/setup/requirements-hardware.txt $(VENV)/.stamp | $(STAMPS)
	$(PY) -m pip install -q --disable-pip-version-check -r $<
	touch $@

# BATCH=N prices the BOM for a batch of N heads (default: bom.batch in the parameter file). The value is kept in
# a file that changes only when BATCH does, so a new value rebuilds the package (only the BOM, by content hash).
BATCH ?=
$(FAB)/.batch: FORCE
	@mkdir -p $(@D); echo '$(strip $(BATCH))' | cmp -s - $@ || echo '$(strip $(BATCH))' > $@

$(FAB)/manifest.json: $(HW_SOURCES) $(HW_BOARD_DEP) $(wildcard $(BOARD_BOMS) $(BOARD_STEP)) $(FAB)/.batch \
                      $(STAMPS)/apt-hardware $(STAMPS)/py-hardware
	$(HW_PY) -m robogene_head.fab --out $(FAB) $(foreach b,$(BOARD_BOMS),--board-bom $(b)) \
	  $(if $(BOARD_STEP),--board-step $(BOARD_STEP)) $(if $(strip $(BATCH)),--batch $(strip $(BATCH)))

.PHONY: fab docs-pictures test-hardware test-head-model FORCE
ALL_TARGETS  += fab
TEST_TARGETS += test-head-model test-hardware
fab: $(FAB)/manifest.json

# The head model (hardware/head-model, installed into .venv by `make setup`): no CAD, no package needed.
test-head-model: $(VENV)/.stamp
	$(PY) -m pytest -q -p no:cacheprovider tests/head_model

# The hardware tests run on HW_TEST_JOBS workers (pytest-xdist; default: one per core, at most 4, each holds an
# assembly of its own in memory; HW_TEST_JOBS=0 runs them in this process). A module goes to one worker whole
# (--dist loadfile), so its module fixtures are built once.
HW_TEST_JOBS ?= $(shell n=$$(nproc 2>/dev/null || echo 1); echo $$(( n < 4 ? n : 4 )))
test-hardware: $(FAB)/manifest.json
	cd $(ROOT) && $(HW_PY) -m pytest -q -p no:cacheprovider -n $(HW_TEST_JOBS) --dist loadfile tests/hardware

# The docs' copies of the package's pictures (docs/images/pictures.yaml; test_docs_pictures fails when one is stale)
docs-pictures: $(FAB)/manifest.json
	$(HW_PY) -m robogene_head.docs_pictures --fab $(FAB) --docs $(ROOT)/docs/images

HELP_LINES += "make fab        build the head's fabrication package into build/fab (STEP, STL, drawings, URDF, BOM, renders);" \
              "                BATCH=N prices the BOM for N heads" \
              "make test-hardware  CAD validity, interference, mesh, URDF-consistency and BOM tests" \
              "                on HW_TEST_JOBS workers (default: one per core, at most 4; 0: one after another)" \
              "make test-head-model  the head model package shared by the CAD and the code generator" \
              "make docs-pictures  copy the package's renders the docs show into docs/images (docs/images/pictures.yaml)"
