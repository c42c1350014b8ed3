// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "joint_encoders.h"

#include "board_pins.h"
#include "gpio.h"
#include "generated/stm32g431_regs.h"

// The data register takes 16-bit accesses for 16-bit frames (a 32-bit write would queue two frames).
#define SPI1_DR16 (*(volatile uint16_t *)(uintptr_t)(SPI1_BASE + SPI1_DR_OFFSET))
#define FRAME_TIMEOUT_POLLS 2000u  // far beyond the 1.7 us a frame takes at 9.4 MHz
#define NO_FRAME 0x8000u           // odd parity: the core counts it as a bad frame

static const uint32_t cs_port[2] = {GPIOA_BASE, GPIOA_BASE};
static const unsigned cs_pin[2] = {PIN_M1_AEA_CS, PIN_M2_AEA_CS};

// At least 120 core cycles (0.8 us at 150 MHz): CSn's set-up before the first clock and its high time
// between frames. Not SysTick: the control loop's period runs on it.
static void settle(void) {
  for (volatile unsigned i = 0; i < 30u; ++i) {
  }
}

void joint_encoders_init(void) {
  for (unsigned i = 0; i < 2u; ++i) {
    gpio_write(cs_port[i], cs_pin[i], 1);  // high before it drives: no encoder selected
    gpio_mode(cs_port[i], cs_pin[i], GPIO_OUTPUT, GPIO_NO_PULL);
  }
  // PB3 and PB4 leave their reset function (JTDO, NJTRST; SWD on PA13/PA14 stays).
  gpio_alternate(GPIOB_BASE, PIN_AEA_CLK, 5u);
  gpio_alternate(GPIOB_BASE, PIN_AEA_DO, 5u);
  RCC_APB2ENR |= RCC_APB2ENR_SPI1EN_Msk;
  SPI1_CR1 = 0u;
  SPI1_CR2 = 15u << SPI1_CR2_DS_Pos;  // 16-bit frames; RXNE at 16 bits (FRXTH 0)
  // Master with software slave management (SSI high keeps it master), fPCLK / 16, mode 1, MSB first.
  SPI1_CR1 = SPI1_CR1_MSTR_Msk | SPI1_CR1_SSM_Msk | SPI1_CR1_SSI_Msk | (3u << SPI1_CR1_BR_Pos) | SPI1_CR1_CPHA_Msk;
  SPI1_CR1 |= SPI1_CR1_SPE_Msk;
}

uint16_t joint_encoders_frame(unsigned axis) {
  const unsigned a = axis & 1u;
  while (SPI1_SR & SPI1_SR_RXNE_Msk) (void)SPI1_DR16;  // nothing left from an earlier frame
  gpio_write(cs_port[a], cs_pin[a], 0);
  settle();
  SPI1_DR16 = 0xFFFFu;  // what the encoder gets is R11's 0xFFFF whatever is sent: MOSI has no pin
  uint32_t polls = 0;
  while (!(SPI1_SR & SPI1_SR_RXNE_Msk) && ++polls < FRAME_TIMEOUT_POLLS) {
  }
  const uint16_t frame = (SPI1_SR & SPI1_SR_RXNE_Msk) ? SPI1_DR16 : (uint16_t)NO_FRAME;
  while ((SPI1_SR & SPI1_SR_BSY_Msk) && ++polls < 2u * FRAME_TIMEOUT_POLLS) {
  }
  gpio_write(cs_port[a], cs_pin[a], 1);
  settle();
  return frame;
}
