# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The port runtime: C++ core, CLI (build/bin/robogene), unit tests, benchmarks, Python package.

CMAKE_BUILD_TYPE ?= RelWithDebInfo
RUNTIME_SOURCES := $(shell find runtime -type f -not -path '*/__pycache__/*' 2>/dev/null) CMakeLists.txt pyproject.toml
# The extension links the device layer's drivers and the boards' control core (the CAN simulator), so their
# sources are the extension's too.
PYTHON_SOURCES := $(RUNTIME_SOURCES) \
	$(shell find drivers hardware/electronics/firmware -type f -not -path '*/__pycache__/*' 2>/dev/null)

$(BUILD)/build.ninja: CMakeLists.txt runtime/CMakeLists.txt runtime/layers.cmake $(STAMPS)/apt-runtime
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=$(CMAKE_BUILD_TYPE)

.PHONY: runtime python python-stub test-cpp test-python test-layering bench
runtime: $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

# The extension is built by scikit-build-core from the same CMake project (build dir kept under
# build/python so rebuilds are incremental) and installed into .venv. The stamp takes the time the build
# started, so a source edited while it runs is newer than the stamp and rebuilds next time.
$(STAMPS)/python: $(PYTHON_SOURCES) $(VENV)/.stamp | $(STAMPS)
	touch $@.started
	$(PY) -m pip install -q --disable-pip-version-check --no-build-isolation --no-deps .
	mv $@.started $@
python: $(STAMPS)/python

# The committed type stub of robogene._core, regenerated from the built module (docs/python.md); the
# manifest's python-stub generator, which `make generate` runs too.
python-stub: python
	PYTHONPATH=$(ROOT)/codegen $(PY) -m robogene_codegen generate --only python-stub

test-cpp: runtime
	cd $(BUILD) && ctest --output-on-failure --no-tests=error -j $(JOBS) --timeout 300

test-python: python runtime
	$(PY) -m pytest -q -p no:cacheprovider tests/python

# The runtime's layers are one way: CMake's target graph, every include, and a planted upward
# include that must fail the build (tests/layering, docs/architecture.md).
test-layering: $(VENV)/.stamp $(STAMPS)/apt-runtime
	$(PY) -m pytest -q -p no:cacheprovider tests/layering

bench: runtime python
	$(PY) runtime/bench/run_benchmarks.py --build $(BUILD)

ALL_TARGETS  += runtime python
TEST_TARGETS += test-cpp test-python test-layering
HELP_LINES   += "make runtime    build the C++ runtime, CLI and unit tests into build/" \
                "make python     build and install the Python package into .venv" \
                "make python-stub regenerate runtime/python/robogene/_core.pyi from the built module" \
                "make test-cpp   run the C++ unit tests (ctest)" \
                "make test-python run the Python tests" \
                "make test-layering check that the runtime's layers depend one way" \
                "make bench      run the benchmarks and print ratios against raw sockets"
