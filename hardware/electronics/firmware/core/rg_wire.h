// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Little-endian field access and the protocol's scaled integers (docs/can-protocol.md: raw =
// round(value / scale), half away from zero; a value beyond the field saturates at its end,
// as a board reports a speed it cannot express).
#ifndef RG_WIRE_H
#define RG_WIRE_H

#include <math.h>
#include <stdint.h>

static inline void rg_put_u16(uint8_t *p, uint16_t v) {
  p[0] = (uint8_t)(v & 0xFFu);
  p[1] = (uint8_t)(v >> 8);
}
static inline void rg_put_i16(uint8_t *p, int16_t v) { rg_put_u16(p, (uint16_t)v); }
static inline void rg_put_u32(uint8_t *p, uint32_t v) {
  for (unsigned i = 0; i < 4u; ++i) p[i] = (uint8_t)(v >> (8u * i));
}
static inline void rg_put_i32(uint8_t *p, int32_t v) { rg_put_u32(p, (uint32_t)v); }
static inline uint16_t rg_get_u16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }
static inline int16_t rg_get_i16(const uint8_t *p) { return (int16_t)rg_get_u16(p); }
static inline uint32_t rg_get_u32(const uint8_t *p) {
  return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}
static inline int32_t rg_get_i32(const uint8_t *p) { return (int32_t)rg_get_u32(p); }

static inline float rg_clampf(float v, float lo, float hi) { return v < lo ? lo : (v > hi ? hi : v); }

// value / scale rounded, saturated to int16.
static inline int16_t rg_scaled_i16(float value, float scale) {
  return (int16_t)lroundf(rg_clampf(value / scale, -32768.0f, 32767.0f));
}

// A count value rounded and saturated to int32 (float holds 2^31 exactly).
static inline int32_t rg_counts_i32(float v) {
  if (v >= 2147483520.0f) return INT32_MAX;  // the largest float below 2^31
  if (v <= -2147483648.0f) return INT32_MIN;
  return (int32_t)lroundf(v);
}

#endif  // RG_WIRE_H
