# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# libFuzzer targets for every place input enters (runtime/fuzz/, docs/security.md): a short smoke
# run of each in `make test`, and a longer campaign on demand whose corpus grows in build/fuzz.

FUZZ_SECONDS ?= 6
FUZZ_CAMPAIGN_SECONDS ?= 1800

.PHONY: test-fuzz fuzz-campaign
test-fuzz: $(STAMPS)/apt-fuzz $(STAMPS)/apt-runtime
	runtime/fuzz/run.sh $(FUZZ_SECONDS)

fuzz-campaign: $(STAMPS)/apt-fuzz $(STAMPS)/apt-runtime
	runtime/fuzz/run.sh $(FUZZ_CAMPAIGN_SECONDS)

TEST_TARGETS += test-fuzz
HELP_LINES += "make test-fuzz  build the fuzz targets (clang, ASan, UBSan) and run each for FUZZ_SECONDS (6)" \
              "make fuzz-campaign run every fuzz target for FUZZ_CAMPAIGN_SECONDS (1800) each; results in build/fuzz/results.txt"
