# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The head's CAN boards (drivers/can): bus backends, board simulator, robogene_can driver.
#   make test-can     the CAN tests (virtual bus between processes; no kernel CAN needed)
#   make test-can-vm  the SocketCAN tests inside a qemu VM that boots Debian's stock kernel with vcan
#                     (this machine's kernel may have no CAN); logs in build/can-vm/, decoded by cantools

CAN_VM_CACHE := $(BUILD)/cache/can-vm
CAN_VM_OUT   := $(BUILD)/can-vm

# The VM's kernel, modules, busybox and can-utils, downloaded once with apt-get download.
$(STAMPS)/can-vm-parts: drivers/can/vm/fetch-vm-parts.sh $(STAMPS)/apt-can
	drivers/can/vm/fetch-vm-parts.sh $(CAN_VM_CACHE)
	touch $@

.PHONY: test-can test-can-vm head-sim
# A simulated head on the virtual bus "head", until Ctrl-C; drive it with
#   build/bin/robogene dev --device robogene_can --from drivers/can/generated/head.ini --bus virtual:head --name /head
head-sim: runtime
	$(BUILD)/bin/robogene can-sim --bus virtual:head --from drivers/can/generated/head.ini

test-can: runtime
	cd $(BUILD) && ctest -L can --output-on-failure --no-tests=error -j $(JOBS) --timeout 300

# Then cantools (installed by mk/codegen.mk) decodes the session's logs with the generated DBC.
test-can-vm: runtime $(STAMPS)/can-vm-parts $(STAMPS)/py-can
	drivers/can/vm/run-vm-tests.sh --build $(BUILD) --cache $(CAN_VM_CACHE) --out $(CAN_VM_OUT)
	$(PY) drivers/can/vm/decode_with_cantools.py drivers/can/generated/head.dbc \
	  $(CAN_VM_OUT)/candump-vcan0.log $(CAN_VM_OUT)/can-sim.log $(CAN_VM_OUT)/robogene_can.log

TEST_TARGETS += test-can test-can-vm
HELP_LINES   += "make head-sim   simulate the head's CAN boards on the virtual bus 'head' (no hardware)" \
                "make test-can   run the CAN bus, simulator and driver tests on the virtual bus" \
                "make test-can-vm run the SocketCAN tests in a qemu VM (Debian kernel, vcan)"
