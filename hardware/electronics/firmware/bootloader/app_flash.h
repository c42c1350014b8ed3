// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The bootloader's flash HAL (core/rg_boot.h) on the STM32G431's FLASH registers (RM0440 3.3):
// page erase and 64-bit programming of the application region, nothing outside it.
#ifndef APP_FLASH_H
#define APP_FLASH_H

#include <stdbool.h>
#include <stdint.h>

#define APP_FLASH_PAGE_BYTES 2048u

uint32_t app_flash_base(void);
uint32_t app_flash_size(void);
// `page` counts from the application region's start.
bool app_flash_erase_page(void *ctx, uint32_t page);
bool app_flash_program(void *ctx, uint32_t offset, const uint8_t *data);
bool app_flash_read(void *ctx, uint32_t offset, uint8_t *out, uint32_t len);

#endif  // APP_FLASH_H
