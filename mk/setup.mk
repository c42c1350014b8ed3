# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Machine set-up shared by every area: Debian packages (only the missing ones) and the .venv.

$(STAMPS):
	mkdir -p $@

# $(STAMPS)/apt-<list> installs tools/setup/apt/<list>.txt.
$(STAMPS)/apt-%: tools/setup/apt/%.txt tools/setup/apt-install.sh | $(STAMPS)
	tools/setup/apt-install.sh $<
	touch $@

# The head model package (hardware/head-model) that the CAD and the code generator import is installed
# editable: its sources stay where they are, so editing them needs no reinstall.
$(VENV)/.stamp: tools/setup/requirements.txt hardware/head-model/pyproject.toml $(STAMPS)/apt-runtime
	test -x $(PY) || $(PYTHON3) -m venv $(VENV)
	$(PY) -m pip install -q --disable-pip-version-check -r $<
	$(PY) -m pip install -q --disable-pip-version-check --no-build-isolation --no-deps -e hardware/head-model
	touch $@

.PHONY: setup
setup: $(VENV)/.stamp
HELP_LINES += "make setup      install Debian packages and the Python tools into .venv"
