// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// CRC-32 as Ethernet and zlib compute it (reflected polynomial 0xEDB88320, initial and final
// value inverted), so the build's Python (zlib.crc32) and the bootloader agree on an image.
#ifndef RG_CRC32_H
#define RG_CRC32_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

// Continues `crc` (0 to start) over `len` bytes: rg_crc32(rg_crc32(0, a), b) is the CRC of a then b.
uint32_t rg_crc32(uint32_t crc, const uint8_t *data, size_t len);

#ifdef __cplusplus
}
#endif

#endif  // RG_CRC32_H
