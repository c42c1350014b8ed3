// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Pin set-up by register: mode, alternate function, pull.
#ifndef GPIO_H
#define GPIO_H

#include <stdint.h>

enum { GPIO_INPUT = 0u, GPIO_OUTPUT = 1u, GPIO_ALTERNATE = 2u, GPIO_ANALOG = 3u };
enum { GPIO_NO_PULL = 0u, GPIO_PULL_UP = 1u, GPIO_PULL_DOWN = 2u };

// `port` is GPIOA_BASE or GPIOB_BASE.
void gpio_mode(uint32_t port, unsigned pin, unsigned mode, unsigned pull);
void gpio_alternate(uint32_t port, unsigned pin, unsigned function);
void gpio_write(uint32_t port, unsigned pin, int high);
int gpio_read(uint32_t port, unsigned pin);

#endif  // GPIO_H
