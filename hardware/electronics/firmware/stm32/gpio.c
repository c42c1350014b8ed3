// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "gpio.h"

#include "generated/stm32g431_regs.h"

// Register offsets are the same on every port (GPIOB derives its layout from GPIOA).
#define PORT_REG(port, reg) RG_REG32((port) + GPIOA_##reg##_OFFSET)

void gpio_mode(uint32_t port, unsigned pin, unsigned mode, unsigned pull) {
  PORT_REG(port, MODER) = (PORT_REG(port, MODER) & ~(3u << (2u * pin))) | (mode << (2u * pin));
  PORT_REG(port, PUPDR) = (PORT_REG(port, PUPDR) & ~(3u << (2u * pin))) | (pull << (2u * pin));
  // Very high speed for the timer and CAN outputs' edges; harmless on inputs.
  PORT_REG(port, OSPEEDR) |= 3u << (2u * pin);
}

void gpio_alternate(uint32_t port, unsigned pin, unsigned function) {
  if (pin < 8u) {
    PORT_REG(port, AFRL) = (PORT_REG(port, AFRL) & ~(0xFu << (4u * pin))) | (function << (4u * pin));
  } else {
    PORT_REG(port, AFRH) = (PORT_REG(port, AFRH) & ~(0xFu << (4u * (pin - 8u)))) | (function << (4u * (pin - 8u)));
  }
  gpio_mode(port, pin, GPIO_ALTERNATE, GPIO_NO_PULL);
}

void gpio_write(uint32_t port, unsigned pin, int high) { PORT_REG(port, BSRR) = high ? (1u << pin) : (1u << (pin + 16u)); }

int gpio_read(uint32_t port, unsigned pin) { return (int)((PORT_REG(port, IDR) >> pin) & 1u); }
