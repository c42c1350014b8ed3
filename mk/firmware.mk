# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The motor board's firmware (hardware/electronics/firmware, docs/firmware.md): the control core and
# the STM32G431 layer cross-compiled with Debian's gcc-arm-none-eabi and newlib, one image per board
# of the head table, as ELF, HEX and BIN with a size report, into the fab package.
#   make firmware        build/fab/firmware/robogene-motor-board-<address>-<name>.{elf,hex,bin,size.txt}
#   make test-firmware   the control core's host tests and the image checks

FW_DIR    := hardware/electronics/firmware
FW_OUT    := $(BUILD)/fab/firmware
FW_OBJ    := $(BUILD)/firmware-obj
FW_CC     := arm-none-eabi-gcc
FW_ARCH   := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
FW_CFLAGS := $(FW_ARCH) -Os -g -std=c11 -Wall -Wextra -Wpedantic -Werror -Wdouble-promotion -Wshadow \
             -ffunction-sections -fdata-sections -I$(FW_DIR)/core -I$(FW_DIR) -I$(FW_DIR)/stm32
FW_SOURCES := $(sort $(wildcard $(FW_DIR)/core/*.c) $(wildcard $(FW_DIR)/stm32/*.c))
FW_HEADERS := $(wildcard $(FW_DIR)/generated/*.h $(FW_DIR)/core/*.h $(FW_DIR)/stm32/*.h)
# address:name of every board in the generated table, e.g. 3:eyes-pan
FW_BOARDS := $(shell sed -n 's/^  {"\([a-z0-9-]*\)", \([0-9]*\)u,.*/\2-\1/p' $(FW_DIR)/generated/robogene_head_board_config.h)
FW_IMAGES := $(foreach b,$(FW_BOARDS),$(FW_OUT)/robogene-motor-board-$(b))

# $(STAMPS)/apt-firmware installs tools/setup/apt/firmware.txt (the pattern rule of mk/setup.mk); kept, not
# an intermediate file of the image rule.
.SECONDARY: $(STAMPS)/apt-firmware

# One object set per board: ROBOGENE_BOARD_ADDRESS selects its table entry.
$(FW_OUT)/robogene-motor-board-%.elf: $(FW_SOURCES) $(FW_HEADERS) $(FW_DIR)/stm32/stm32g431kb.ld $(STAMPS)/apt-firmware
	@mkdir -p $(FW_OBJ)/$* $(FW_OUT)
	set -e; objs=; for src in $(FW_SOURCES); do \
	  obj=$(FW_OBJ)/$*/$$(basename $$src .c).o; \
	  $(FW_CC) $(FW_CFLAGS) -DROBOGENE_BOARD_ADDRESS=$(firstword $(subst -, ,$*)) -c $$src -o $$obj; objs="$$objs $$obj"; \
	done; \
	$(FW_CC) $(FW_ARCH) --specs=nano.specs -nostartfiles -Wl,--gc-sections -Wl,-Map=$(FW_OBJ)/$*.map \
	  -T $(FW_DIR)/stm32/stm32g431kb.ld $$objs -lm -o $@

$(FW_OUT)/%.hex: $(FW_OUT)/%.elf
	arm-none-eabi-objcopy -O ihex $< $@
$(FW_OUT)/%.bin: $(FW_OUT)/%.elf
	arm-none-eabi-objcopy -O binary $< $@
$(FW_OUT)/%.size.txt: $(FW_OUT)/%.elf $(FW_DIR)/tools/size_report.py
	$(PYTHON3) $(FW_DIR)/tools/size_report.py $< $@

.PHONY: firmware test-firmware
firmware: $(foreach i,$(FW_IMAGES),$(i).elf $(i).hex $(i).bin $(i).size.txt)

test-firmware: firmware runtime $(VENV)/.stamp
	cd $(BUILD) && ctest -R '^Core' --output-on-failure --no-tests=error -j $(JOBS) --timeout 120
	$(PY) -m pytest -q -p no:cacheprovider tests/firmware

ALL_TARGETS  += firmware
TEST_TARGETS += test-firmware
HELP_LINES   += "make firmware   build the motor-board firmware images into build/fab/firmware/" \
                "make test-firmware  the control core's host tests and the firmware image checks"
