# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Licensing: every file has an SPDX header or a REUSE.toml entry, and every licence text is present.

.PHONY: lint
lint: $(VENV)/.stamp
	$(VENV)/bin/reuse lint --lines
	@echo "reuse lint: compliant"

TEST_TARGETS += lint
HELP_LINES   += "make lint       check licensing (reuse lint)"
