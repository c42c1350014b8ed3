// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "motor_io.h"

#include "board_pins.h"
#include "clock.h"
#include "gpio.h"
#include "generated/stm32g431_regs.h"

// Timer registers by base: TIM15, TIM2 and TIM4 share TIM1's offsets for what is used here.
#define TIM(base, reg) RG_REG32((base) + TIM1_##reg##_OFFSET)
#define ADC(base, reg) RG_REG32((base) + ADC1_##reg##_OFFSET)

static const uint32_t pwm_timer[2] = {TIM1_BASE, TIM15_BASE};
static const uint32_t encoder_timer[2] = {TIM2_BASE, TIM4_BASE};
static uint32_t pwm_period;  // timer counts of one PWM period
static uint16_t full_scale;

static void pwm_timer_init(uint32_t t) {
  TIM(t, PSC) = 0u;
  TIM(t, ARR) = pwm_period - 1u;
  // PWM mode 1 (110) with preload on channels 1 and 2: each drives one DRV8872 input.
  TIM(t, CCMR1) = (6u << TIM1_CCMR1_OC1M_Pos) | TIM1_CCMR1_OC1PE_Msk | (6u << TIM1_CCMR1_OC2M_Pos) | TIM1_CCMR1_OC2PE_Msk;
  TIM(t, CCR1) = 0u;
  TIM(t, CCR2) = 0u;
  TIM(t, CCER) = TIM1_CCER_CC1E_Msk | TIM1_CCER_CC2E_Msk;
  TIM(t, BDTR) = TIM1_BDTR_MOE_Msk;  // TIM1 and TIM15 gate their outputs with MOE
  TIM(t, EGR) = TIM1_EGR_UG_Msk;
  TIM(t, CR1) = TIM1_CR1_ARPE_Msk | TIM1_CR1_CEN_Msk;
}

static void encoder_timer_init(uint32_t t) {
  TIM(t, ARR) = 0xFFFFu;  // 16 bits on both timers (TIM2 is 32-bit): the core extends them alike
  // Both channels as inputs on their own pins, filtered over 8 samples (IC1F/IC2F = 0011).
  TIM(t, CCMR1) = (1u << TIM1_CCMR1_CC1S_Pos) | (3u << TIM1_CCMR1_IC1F_Pos) | (1u << TIM1_CCMR1_CC2S_Pos) |
                  (3u << TIM1_CCMR1_IC2F_Pos);
  TIM(t, CCER) = 0u;                           // non-inverted
  TIM(t, SMCR) = 3u << TIM1_SMCR_SMS_Pos;      // encoder mode 3: count on both edges of both inputs
  TIM(t, CNT) = 0u;
  TIM(t, CR1) = TIM1_CR1_CEN_Msk;
}

static void adc_init(uint32_t adc) {
  ADC(adc, CR) &= ~ADC1_CR_DEEPPWD_Msk;
  ADC(adc, CR) |= ADC1_CR_ADVREGEN_Msk;
  clock_delay_us(20u);  // the regulator's start-up time (t_ADCVREG_STUP)
  ADC(adc, CR) |= ADC1_CR_ADCAL_Msk;
  while (ADC(adc, CR) & ADC1_CR_ADCAL_Msk) {
  }
  ADC(adc, ISR) = ADC1_ISR_ADRDY_Msk;
  ADC(adc, CR) |= ADC1_CR_ADEN_Msk;
  while (!(ADC(adc, ISR) & ADC1_ISR_ADRDY_Msk)) {
  }
}

// One software-started conversion; 47.5-cycle sampling for the amplifiers' and divider's impedance.
static uint32_t adc_read(uint32_t adc, unsigned channel) {
  if (channel < 10u) {
    ADC(adc, SMPR1) = (ADC(adc, SMPR1) & ~(7u << (3u * channel))) | (4u << (3u * channel));
  } else {
    ADC(adc, SMPR2) = (ADC(adc, SMPR2) & ~(7u << (3u * (channel - 10u)))) | (4u << (3u * (channel - 10u)));
  }
  ADC(adc, SQR1) = channel << ADC1_SQR1_SQ1_Pos;  // one conversion (L = 0)
  ADC(adc, CR) |= ADC1_CR_ADSTART_Msk;
  while (!(ADC(adc, ISR) & ADC1_ISR_EOC_Msk)) {
  }
  return ADC(adc, DR) & 0xFFFu;
}

static const uint32_t brake_port[2] = {GPIOB_BASE, GPIOA_BASE};
static const unsigned brake_pin[2] = {PIN_M1_BRAKE, PIN_M2_BRAKE};
static unsigned brake_outputs;  // bit m: motor m's brake pin is an output

void motor_io_init(uint16_t pwm_full_scale_steps, unsigned brakes) {
  full_scale = pwm_full_scale_steps;
  brake_outputs = brakes & 3u;
  for (unsigned m = 0; m < 2u; ++m) {
    if (!(brake_outputs & (1u << m))) continue;
    gpio_write(brake_port[m], brake_pin[m], 0);  // low before it drives: the brake stays applied
    gpio_mode(brake_port[m], brake_pin[m], GPIO_OUTPUT, GPIO_NO_PULL);
  }
  pwm_period = SYSCLK_HZ / PWM_HZ;
  RCC_APB2ENR |= RCC_APB2ENR_TIM1EN_Msk | RCC_APB2ENR_TIM15EN_Msk;
  RCC_APB1ENR1 |= RCC_APB1ENR1_TIM2EN_Msk | RCC_APB1ENR1_TIM4EN_Msk;
  RCC_AHB2ENR |= RCC_AHB2ENR_ADC12EN_Msk;
  RCC_CCIPR = (RCC_CCIPR & ~RCC_CCIPR_ADC12SEL_Msk) | (2u << RCC_CCIPR_ADC12SEL_Pos);  // system clock
  // Synchronous clock HCLK / 4 = 37.5 MHz, within the ADC's 60 MHz.
  ADC12_COMMON_CCR = (ADC12_COMMON_CCR & ~ADC12_COMMON_CCR_CKMODE_Msk) | (3u << ADC12_COMMON_CCR_CKMODE_Pos);
  gpio_alternate(GPIOA_BASE, PIN_M1_IN1, 6u);
  gpio_alternate(GPIOA_BASE, PIN_M1_IN2, 6u);
  gpio_alternate(GPIOA_BASE, PIN_M2_IN1, 9u);
  gpio_alternate(GPIOA_BASE, PIN_M2_IN2, 9u);
  gpio_alternate(GPIOA_BASE, PIN_M1_QA, 1u);
  gpio_alternate(GPIOA_BASE, PIN_M1_QB, 1u);
  gpio_alternate(GPIOB_BASE, PIN_M2_QA, 2u);
  gpio_alternate(GPIOB_BASE, PIN_M2_QB, 2u);
  gpio_mode(GPIOA_BASE, PIN_M1_ISENSE, GPIO_ANALOG, GPIO_NO_PULL);
  gpio_mode(GPIOA_BASE, PIN_M2_ISENSE, GPIO_ANALOG, GPIO_NO_PULL);
  gpio_mode(GPIOB_BASE, PIN_VBUS_SENSE, GPIO_ANALOG, GPIO_NO_PULL);
  gpio_mode(GPIOA_BASE, PIN_MOT_FAULT, GPIO_INPUT, GPIO_NO_PULL);  // R7 pulls it up
  for (unsigned m = 0; m < 2u; ++m) {
    pwm_timer_init(pwm_timer[m]);
    encoder_timer_init(encoder_timer[m]);
  }
  adc_init(ADC1_BASE);
  adc_init(ADC2_BASE);
}

void motor_io_set_pwm(unsigned motor, int32_t duty, bool enabled) {
  const uint32_t t = pwm_timer[motor & 1u];
  const uint32_t magnitude = (uint32_t)(duty < 0 ? -duty : duty);
  const uint32_t counts = enabled ? (magnitude >= full_scale ? pwm_period : magnitude * pwm_period / full_scale) : 0u;
  // Forward: IN1 pulses, IN2 low; reverse the other way round; off: both low, the bridge coasts.
  TIM(t, CCR1) = duty > 0 ? counts : 0u;
  TIM(t, CCR2) = duty < 0 ? counts : 0u;
}

uint16_t motor_io_encoder(unsigned motor) { return (uint16_t)TIM(encoder_timer[motor & 1u], CNT); }

int32_t motor_io_current_ma(unsigned motor) {
  // INA240A1: 20 V/V across 20 mOhm = 0.4 V/A around mid-scale (REF1 = 3.3 V, REF2 = GND).
  const int32_t raw = (int32_t)adc_read(ADC2_BASE, motor ? ADC_CH_M2_ISENSE : ADC_CH_M1_ISENSE);
  return (raw - 2048) * 3300 / 4096 * 10 / 4;
}

uint32_t motor_io_supply_mv(void) {
  // 47 k over 10 k: the pin sees 10/57 of the supply.
  return adc_read(ADC1_BASE, ADC_CH_VBUS) * 3300u / 4096u * 57u / 10u;
}

bool motor_io_bridge_fault(void) { return gpio_read(GPIOA_BASE, PIN_MOT_FAULT) == 0; }

void motor_io_set_brake(unsigned motor, bool released) {
  if (!(brake_outputs & (1u << (motor & 1u)))) return;
  gpio_write(brake_port[motor & 1u], brake_pin[motor & 1u], released ? 1 : 0);
}
