# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The motor board's firmware (hardware/electronics/firmware, docs/firmware.md): the control core and
# the STM32G431 layer cross-compiled with Debian's gcc-arm-none-eabi and newlib, one image per board
# of the head table, as ELF, HEX and BIN with a size report, into the fab package.
#   make firmware        build/fab/firmware/robogene-motor-board-<address>-<name>.{elf,hex,bin,size.txt}
#                        (the application, its image header stamped) and
#                        build/fab/firmware/robogene-bootloader-<address>-<name>.{elf,hex,bin,size.txt}
#   make test-firmware   the control core's host tests and the image checks

FW_DIR    := hardware/electronics/firmware
FW_OUT    := $(BUILD)/fab/firmware
FW_OBJ    := $(BUILD)/firmware-obj
FW_CC     := arm-none-eabi-gcc
FW_ARCH   := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
# The board revision, from its one source (the schematic, the board and the catalog take it there too).
FW_REVISION_SOURCE := hardware/electronics/generator/design.py
FW_REVISION := $(shell sed -n 's/^REVISION = "\([A-Z]\)".*/\1/p' $(FW_REVISION_SOURCE))
ifeq ($(FW_REVISION),)
$(error $(FW_REVISION_SOURCE): no line REVISION = "<letter>" (the board revision the firmware is built for))
endif
FW_CFLAGS := $(FW_ARCH) -Os -g -std=c11 -Wall -Wextra -Wpedantic -Werror -Wdouble-promotion -Wshadow \
             -ffunction-sections -fdata-sections -I$(FW_DIR)/core -I$(FW_DIR) -I$(FW_DIR)/stm32 \
             -DROBOGENE_BOARD_REVISION=\'$(FW_REVISION)\'
FW_SOURCES := $(sort $(wildcard $(FW_DIR)/core/*.c) $(wildcard $(FW_DIR)/stm32/*.c))
FW_HEADERS := $(wildcard $(FW_DIR)/generated/*.h $(FW_DIR)/core/*.h $(FW_DIR)/stm32/*.h $(FW_DIR)/bootloader/*.h)
# The bootloader: its protocol from the core, the STM32 layer's start-up, pins, CAN and settings.
FW_BOOT_SOURCES := $(addprefix $(FW_DIR)/core/,rg_boot.c rg_image.c rg_crc32.c) \
                   $(addprefix $(FW_DIR)/stm32/,startup.c gpio.c fdcan.c settings.c handoff.c) \
                   $(sort $(wildcard $(FW_DIR)/bootloader/*.c))
FW_APP_FLASH  := 112640
FW_BOOT_FLASH := 16384
# address:name of every board in the generated table, e.g. 3:eyes-pan
FW_BOARDS := $(shell sed -n 's/^  {"\([a-z0-9-]*\)", \([0-9]*\)u,.*/\2-\1/p' $(FW_DIR)/generated/robogene_head_board_config.h)
FW_IMAGES := $(foreach b,$(FW_BOARDS),$(FW_OUT)/robogene-motor-board-$(b) $(FW_OUT)/robogene-bootloader-$(b))

# $(STAMPS)/apt-firmware installs tools/setup/apt/firmware.txt (the pattern rule of mk/setup.mk); kept, not
# an intermediate file of the image rule.
.SECONDARY: $(STAMPS)/apt-firmware

# One object set per board: ROBOGENE_BOARD_ADDRESS selects its table entry. The linked image is
# then stamped (size and CRC-32 into its header, tools/stamp_image.py); HEX and BIN come from the
# stamped ELF.
$(FW_OUT)/robogene-motor-board-%.elf: $(FW_SOURCES) $(FW_HEADERS) $(FW_DIR)/stm32/stm32g431kb.ld \
                                      $(FW_DIR)/tools/stamp_image.py $(FW_REVISION_SOURCE) $(STAMPS)/apt-firmware
	@mkdir -p $(FW_OBJ)/$* $(FW_OUT)
	set -e; objs=; for src in $(FW_SOURCES); do \
	  obj=$(FW_OBJ)/$*/$$(basename $$src .c).o; \
	  $(FW_CC) $(FW_CFLAGS) -DROBOGENE_BOARD_ADDRESS=$(firstword $(subst -, ,$*)) -c $$src -o $$obj; objs="$$objs $$obj"; \
	done; \
	$(FW_CC) $(FW_ARCH) --specs=nano.specs -nostartfiles -Wl,--gc-sections -Wl,-Map=$(FW_OBJ)/$*.map \
	  -T $(FW_DIR)/stm32/stm32g431kb.ld $$objs -lm -o $(FW_OBJ)/$*.unstamped.elf
	$(PYTHON3) $(FW_DIR)/tools/stamp_image.py $(FW_OBJ)/$*.unstamped.elf $@

$(FW_OUT)/robogene-bootloader-%.elf: $(FW_BOOT_SOURCES) $(FW_HEADERS) $(FW_DIR)/bootloader/stm32g431kb_bootloader.ld \
                                     $(FW_REVISION_SOURCE) $(STAMPS)/apt-firmware
	@mkdir -p $(FW_OBJ)/boot-$* $(FW_OUT)
	set -e; objs=; for src in $(FW_BOOT_SOURCES); do \
	  obj=$(FW_OBJ)/boot-$*/$$(basename $$src .c).o; \
	  $(FW_CC) $(FW_CFLAGS) -I$(FW_DIR)/bootloader -DROBOGENE_BOARD_ADDRESS=$(firstword $(subst -, ,$*)) \
	    -c $$src -o $$obj; objs="$$objs $$obj"; \
	done; \
	$(FW_CC) $(FW_ARCH) --specs=nano.specs -nostartfiles -Wl,--gc-sections -Wl,-Map=$(FW_OBJ)/boot-$*.map \
	  -T $(FW_DIR)/bootloader/stm32g431kb_bootloader.ld $$objs -o $@

$(FW_OUT)/%.hex: $(FW_OUT)/%.elf
	arm-none-eabi-objcopy -O ihex $< $@
$(FW_OUT)/%.bin: $(FW_OUT)/%.elf
	arm-none-eabi-objcopy -O binary $< $@
$(FW_OUT)/robogene-motor-board-%.size.txt: $(FW_OUT)/robogene-motor-board-%.elf $(FW_DIR)/tools/size_report.py
	$(PYTHON3) $(FW_DIR)/tools/size_report.py $< $@ --flash $(FW_APP_FLASH)
$(FW_OUT)/robogene-bootloader-%.size.txt: $(FW_OUT)/robogene-bootloader-%.elf $(FW_DIR)/tools/size_report.py
	$(PYTHON3) $(FW_DIR)/tools/size_report.py $< $@ --flash $(FW_BOOT_FLASH)

.PHONY: firmware test-firmware
firmware: $(foreach i,$(FW_IMAGES),$(i).elf $(i).hex $(i).bin $(i).size.txt)

test-firmware: firmware runtime $(VENV)/.stamp
	cd $(BUILD) && ctest -R '^Core' --output-on-failure --no-tests=error -j $(JOBS) --timeout 120
	$(PY) -m pytest -q -p no:cacheprovider tests/firmware

ALL_TARGETS  += firmware
TEST_TARGETS += test-firmware
HELP_LINES   += "make firmware   build the motor-board firmware and bootloader images into build/fab/firmware/" \
                "make test-firmware  the control core's host tests and the firmware image checks"
