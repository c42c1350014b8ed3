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

$(VENV)/.stamp: tools/setup/requirements.txt $(STAMPS)/apt-runtime
	test -x $(PY) || $(PYTHON3) -m venv $(VENV)
	$(PY) -m pip install -q --disable-pip-version-check -r $<
	touch $@

.PHONY: setup
setup: $(VENV)/.stamp
HELP_LINES += "make setup      install Debian packages and the Python tools into .venv"
