// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "fdcan.h"

#include "board_pins.h"
#include "gpio.h"
#include "generated/robogene_can_motor_control.h"
#include "generated/stm32g431_regs.h"

// The message RAM of FDCAN1 has a fixed layout on the STM32G4 (RM0440 44.3.3): 28 standard
// filters, 8 extended filters, two 3-element RX FIFOs, a 3-element TX event FIFO and 3 TX buffers,
// each RX/TX element 18 words.
#define SRAMCAN_BASE 0x4000A400u
#define MRAM_FLS (SRAMCAN_BASE + 0x000u)
#define MRAM_RXF0 (SRAMCAN_BASE + 0x0B0u)
#define MRAM_TXB (SRAMCAN_BASE + 0x278u)
#define MRAM_ELEMENT_BYTES 72u
#define MRAM_SIZE 0x350u

static void word_write(uint32_t address, uint32_t v) { RG_REG32(address) = v; }
static uint32_t word_read(uint32_t address) { return RG_REG32(address); }

// Standard filter element: classic filter (SFT = 10) of id and mask, matches to RX FIFO 0 (SFEC = 001).
static uint32_t classic_filter(uint32_t id, uint32_t mask) { return (2u << 30) | (1u << 27) | (id << 16) | mask; }

void fdcan_init(uint8_t address) {
  RCC_APB1ENR1 |= RCC_APB1ENR1_FDCANEN_Msk;
  RCC_CCIPR = (RCC_CCIPR & ~RCC_CCIPR_FDCANSEL_Msk);  // 00: the HSE crystal, 8 MHz
  gpio_alternate(GPIOA_BASE, PIN_CAN_RX, 9u);
  gpio_alternate(GPIOA_BASE, PIN_CAN_TX, 9u);
  FDCAN1_CCCR |= FDCAN1_CCCR_INIT_Msk;
  while (!(FDCAN1_CCCR & FDCAN1_CCCR_INIT_Msk)) {
  }
  FDCAN1_CCCR |= FDCAN1_CCCR_CCE_Msk;  // classic CAN: FDOE and BRSE stay 0 after reset
  // 1 Mbit/s from 8 MHz: 8 quanta a bit (1 sync + 5 + 2), sampled at 75 %, resynchronisation jump 2.
  FDCAN1_NBTP = ((2u - 1u) << FDCAN1_NBTP_NSJW_Pos) | ((1u - 1u) << FDCAN1_NBTP_NBRP_Pos) |
                ((5u - 1u) << FDCAN1_NBTP_NTSEG1_Pos) | ((2u - 1u) << FDCAN1_NBTP_NTSEG2_Pos);
  for (uint32_t a = 0; a < MRAM_SIZE; a += 4u) word_write(SRAMCAN_BASE + a, 0u);
  const uint32_t exact = 0x7FFu;
  word_write(MRAM_FLS + 0u, classic_filter(ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_POLLING_MOTOR_CONTROL, 0u, address), exact));
  word_write(MRAM_FLS + 4u, classic_filter(ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_POLLING_MOTOR_CONTROL, 0u,
                                                           ROBOGENE_CAN_BROADCAST_ADDRESS), exact));
  word_write(MRAM_FLS + 8u, classic_filter(ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_BOOTLOADER, 0u, address), exact));
  word_write(MRAM_FLS + 12u,
             classic_filter(ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_BOOTLOADER, 0u, ROBOGENE_CAN_BROADCAST_ADDRESS), exact));
  // Four standard filters; everything else, extended and remote frames included, is rejected.
  FDCAN1_RXGFC = (4u << FDCAN1_RXGFC_LSS_Pos) | (2u << FDCAN1_RXGFC_ANFS_Pos) | (2u << FDCAN1_RXGFC_ANFE_Pos) |
                 FDCAN1_RXGFC_RRFS_Msk | FDCAN1_RXGFC_RRFE_Msk;
  FDCAN1_TXBC = 0u;  // TX FIFO mode
  FDCAN1_CCCR &= ~FDCAN1_CCCR_INIT_Msk;
  while (FDCAN1_CCCR & FDCAN1_CCCR_INIT_Msk) {
  }
}

bool fdcan_receive(rg_can_frame_t *frame) {
  const uint32_t status = FDCAN1_RXF0S;
  if ((status & FDCAN1_RXF0S_F0FL_Msk) == 0u) return false;
  const uint32_t index = (status & FDCAN1_RXF0S_F0GI_Msk) >> FDCAN1_RXF0S_F0GI_Pos;
  const uint32_t element = MRAM_RXF0 + index * MRAM_ELEMENT_BYTES;
  const uint32_t r0 = word_read(element), r1 = word_read(element + 4u);
  frame->id = (uint16_t)((r0 >> 18) & 0x7FFu);
  frame->len = (uint8_t)((r1 >> 16) & 0xFu);
  if (frame->len > 8u) frame->len = 8u;  // classic CAN: DLC 9..15 still mean 8 bytes
  const uint32_t d0 = word_read(element + 8u), d1 = word_read(element + 12u);
  for (unsigned i = 0; i < 4u; ++i) {
    frame->data[i] = (uint8_t)(d0 >> (8u * i));
    frame->data[4u + i] = (uint8_t)(d1 >> (8u * i));
  }
  FDCAN1_RXF0A = index;
  return true;
}

bool fdcan_send(const rg_can_frame_t *frame) {
  const uint32_t status = FDCAN1_TXFQS;
  if (status & FDCAN1_TXFQS_TFQF_Msk) return false;
  const uint32_t index = (status & FDCAN1_TXFQS_TFQPI_Msk) >> FDCAN1_TXFQS_TFQPI_Pos;
  const uint32_t element = MRAM_TXB + index * MRAM_ELEMENT_BYTES;
  uint32_t d[2] = {0u, 0u};
  for (unsigned i = 0; i < frame->len && i < 8u; ++i) d[i / 4u] |= (uint32_t)frame->data[i] << (8u * (i % 4u));
  word_write(element, (uint32_t)(frame->id & 0x7FFu) << 18);
  word_write(element + 4u, (uint32_t)(frame->len & 0xFu) << 16);
  word_write(element + 8u, d[0]);
  word_write(element + 12u, d[1]);
  FDCAN1_TXBAR = 1u << index;
  return true;
}

bool fdcan_flush(uint32_t max_us) {
  // TFFL counts the free elements of the 3-element TX FIFO. A pass takes at least 50 ns at 150 MHz
  // (longer on the bootloader's 16 MHz): max_us bounds the wait, it does not time it.
  for (uint32_t n = 0; n < max_us * 20u; ++n) {
    if (((FDCAN1_TXFQS & FDCAN1_TXFQS_TFFL_Msk) >> FDCAN1_TXFQS_TFFL_Pos) == 3u) return true;
  }
  return false;
}

bool fdcan_recover(void) {
  if (!(FDCAN1_PSR & FDCAN1_PSR_BO_Msk)) return false;
  FDCAN1_CCCR &= ~FDCAN1_CCCR_INIT_Msk;  // starts the 128 x 11 recessive bits of recovery
  return true;
}

void fdcan_errors(uint8_t *tx_errors, uint8_t *rx_errors, uint8_t *status) {
  const uint32_t ecr = FDCAN1_ECR, psr = FDCAN1_PSR;
  *tx_errors = (uint8_t)((ecr & FDCAN1_ECR_TEC_Msk) >> FDCAN1_ECR_TEC_Pos);
  *rx_errors = (uint8_t)((ecr & FDCAN1_ECR_REC_Msk) >> FDCAN1_ECR_REC_Pos);
  uint8_t s = 0u;
  if (psr & FDCAN1_PSR_EW_Msk) s |= ROBOGENE_CAN_CAN_STATUS_RX_WARNING;
  if (psr & FDCAN1_PSR_EP_Msk) s |= ROBOGENE_CAN_CAN_STATUS_RX_ERROR;
  if (FDCAN1_RXF0S & FDCAN1_RXF0S_RF0L_Msk) s |= ROBOGENE_CAN_CAN_STATUS_HARDWARE_OVERRUN;
  *status = s;
}
