// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What the motor board (revision D, hardware/electronics/generator/design.py) wires to each pin of
// its STM32G431KBT6 (LQFP-32), with the alternate function that pin needs (datasheet DS12589).
#ifndef BOARD_PINS_H
#define BOARD_PINS_H

// Port A
#define PIN_M1_QA 0u      // PA0  TIM2_CH1 AF1, motor 1 encoder A
#define PIN_M1_QB 1u      // PA1  TIM2_CH2 AF1
#define PIN_M2_IN1 2u     // PA2  TIM15_CH1 AF9, H-bridge 2
#define PIN_M2_IN2 3u     // PA3  TIM15_CH2 AF9
#define PIN_M2_BRAKE 4u   // PA4  brake 2 switch gate, output, high = released (100 k pull-down; rev C: the LED)
#define PIN_M2_AEA_CS 5u  // PA5  joint encoder 2 chip select (active low, 10 k pull-up; rev B had it on PB5)
#define PIN_M1_ISENSE 6u  // PA6  ADC2_IN3, motor 1 current (INA240A1)
#define PIN_M2_ISENSE 7u  // PA7  ADC2_IN4, motor 2 current
#define PIN_M1_IN1 8u     // PA8  TIM1_CH1 AF6, H-bridge 1
#define PIN_M1_IN2 9u     // PA9  TIM1_CH2 AF6
#define PIN_MOT_FAULT 10u // PA10 both DRV8872 nFAULT, open drain with a 10 k pull-up: low = fault
#define PIN_CAN_RX 11u    // PA11 FDCAN1_RX AF9
#define PIN_CAN_TX 12u    // PA12 FDCAN1_TX AF9
#define PIN_M1_AEA_CS 15u // PA15 joint encoder 1 chip select
// Port B
#define PIN_VBUS_SENSE 0u // PB0  ADC1_IN15, 12 V through 47 k / 10 k
#define PIN_AEA_CLK 3u    // PB3  SPI1_SCK AF5
#define PIN_AEA_DO 4u     // PB4  SPI1_MISO AF5
#define PIN_M1_BRAKE 5u   // PB5  brake 1 switch gate, output, high = released (100 k pull-down; rev C: AEA MOSI,
                          //      now held high by R11 alone: 0xFFFF is the AS5048A's read-angle command)
#define PIN_M2_QA 6u      // PB6  TIM4_CH1 AF2, motor 2 encoder A
#define PIN_M2_QB 7u      // PB7  TIM4_CH2 AF2
#define PIN_BOOT0 8u      // PB8  BOOT0 at reset, then the status LED, output (rev C had the LED on PA4)

#define ADC_CH_M1_ISENSE 3u   // on ADC2
#define ADC_CH_M2_ISENSE 4u   // on ADC2
#define ADC_CH_VBUS 15u       // on ADC1

#endif  // BOARD_PINS_H
