// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The two motor channels: DRV8872 inputs driven by TIM1 (motor 1) and TIM15 (motor 2) at 20 kHz,
// quadrature encoders counted by TIM2 and TIM4 in x4 mode, currents through the INA240A1s on ADC2
// and the 12 V supply on ADC1, the bridges' shared fault line.
#ifndef MOTOR_IO_H
#define MOTOR_IO_H

#include <stdbool.h>
#include <stdint.h>

#define PWM_HZ 20000u

// brakes: bit m set when motor m has a holding brake; only those pins become outputs (driven low: applied).
void motor_io_init(uint16_t pwm_full_scale, unsigned brakes);
// Release (true) or apply (false) motor m's brake; ignored for a motor without one.
void motor_io_set_brake(unsigned motor, bool released);
// duty in steps of pwm_full_scale, sign = direction; disabled: both inputs low (coast).
void motor_io_set_pwm(unsigned motor, int32_t duty, bool enabled);
uint16_t motor_io_encoder(unsigned motor);
int32_t motor_io_current_ma(unsigned motor);
uint32_t motor_io_supply_mv(void);
bool motor_io_bridge_fault(void);

#endif  // MOTOR_IO_H
