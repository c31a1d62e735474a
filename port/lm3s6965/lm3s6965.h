/* SPDX-License-Identifier: MIT */
/*
 * The LM3S6965 registers this port uses (Stellaris LM3S6965 Microcontroller
 * Data Sheet, Texas Instruments): system control, GPIO ports A, C, D, the
 * SSI0 (an ARM PL022) and SysTick. Addresses and bits as the data sheet
 * names them.
 */
#ifndef ZL_LM3S6965_H
#define ZL_LM3S6965_H

#include <stdint.h>

#define ZL_REG(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* System control */
#define SYSCTL_RIS ZL_REG(0x400FE050u)
#define SYSCTL_RCC ZL_REG(0x400FE060u)
#define SYSCTL_RCGC1 ZL_REG(0x400FE104u)
#define SYSCTL_RCGC2 ZL_REG(0x400FE108u)
#define SYSCTL_RIS_PLLLRIS (1u << 6)
#define SYSCTL_RCC_SYSDIV_SHIFT 23
#define SYSCTL_RCC_SYSDIV_MASK (15u << 23)
#define SYSCTL_RCC_USESYSDIV (1u << 22)
#define SYSCTL_RCC_PWRDN (1u << 13)
#define SYSCTL_RCC_BYPASS (1u << 11)
#define SYSCTL_RCC_XTAL_MASK (15u << 6)
#define SYSCTL_RCC_XTAL_8MHZ (14u << 6)
#define SYSCTL_RCC_OSCSRC_MASK (3u << 4)
#define SYSCTL_RCGC1_SSI0 (1u << 4)
#define SYSCTL_RCGC2_GPIOA (1u << 0)
#define SYSCTL_RCGC2_GPIOC (1u << 2)
#define SYSCTL_RCGC2_GPIOD (1u << 3)

/* GPIO ports (PL061 with the Stellaris extensions). DATA is address-masked:
 * offset (pins << 2) reads and writes only those pins. */
#define GPIO_PORTA 0x40004000u
#define GPIO_PORTC 0x40006000u
#define GPIO_PORTD 0x40007000u
#define GPIO_DATA_MASKED(port, pins) ZL_REG((port) + ((uint32_t)(pins) << 2))
#define GPIO_DIR(port) ZL_REG((port) + 0x400u)
#define GPIO_AFSEL(port) ZL_REG((port) + 0x420u)
#define GPIO_DR8R(port) ZL_REG((port) + 0x508u)
#define GPIO_DEN(port) ZL_REG((port) + 0x51Cu)

/* SSI0 (PL022) */
#define SSI0_CR0 ZL_REG(0x40008000u)
#define SSI0_CR1 ZL_REG(0x40008004u)
#define SSI0_DR ZL_REG(0x40008008u)
#define SSI0_SR ZL_REG(0x4000800Cu)
#define SSI0_CPSR ZL_REG(0x40008010u)
#define SSI_CR0_SCR_SHIFT 8
#define SSI_CR0_DSS_8BIT 7u
#define SSI_CR1_SSE (1u << 1)
#define SSI_SR_TFE (1u << 0) /* transmit FIFO empty */
#define SSI_SR_TNF (1u << 1) /* transmit FIFO not full */
#define SSI_SR_RNE (1u << 2) /* receive FIFO not empty */
#define SSI_SR_BSY (1u << 4) /* shifting a frame, or transmit FIFO not empty */

/* SysTick (ARMv7-M) */
#define SYST_CSR ZL_REG(0xE000E010u)
#define SYST_RVR ZL_REG(0xE000E014u)
#define SYST_CVR ZL_REG(0xE000E018u)
#define SYST_CSR_ENABLE (1u << 0)
#define SYST_CSR_TICKINT (1u << 1)
#define SYST_CSR_CLKSOURCE (1u << 2) /* 1: the processor clock */

#endif
