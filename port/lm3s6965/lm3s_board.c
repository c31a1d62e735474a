/* SPDX-License-Identifier: MIT */
/* Board support for the LM3S6965: see lm3s_board.h. */
#include "lm3s_board.h"

#include "lm3s6965.h"
#include "semihosting.h"

/* Only the SysTick interrupt writes it; lm3s_ticks() reads it around the
 * counter to catch a wrap in between. */
static volatile uint32_t systick_wraps;

void SysTick_Handler(void);
void SysTick_Handler(void)
{
    systick_wraps++;
}

int lm3s_clock_init(void)
{
    uint32_t rcc = SYSCTL_RCC;
    uint32_t spin;
    /* Crystal, main oscillator, PLL powered up but bypassed while it locks. */
    rcc &= ~(SYSCTL_RCC_XTAL_MASK | SYSCTL_RCC_OSCSRC_MASK | SYSCTL_RCC_PWRDN);
    rcc |= SYSCTL_RCC_XTAL_8MHZ | SYSCTL_RCC_BYPASS;
    SYSCTL_RCC = rcc;
    /* 200 MHz / (SYSDIV + 1) = 50 MHz */
    rcc &= ~SYSCTL_RCC_SYSDIV_MASK;
    rcc |= (3u << SYSCTL_RCC_SYSDIV_SHIFT) | SYSCTL_RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    for (spin = 0; spin < 100000u; spin++) {
        if (SYSCTL_RIS & SYSCTL_RIS_PLLLRIS) {
            SYSCTL_RCC = rcc & ~SYSCTL_RCC_BYPASS;
            return 0;
        }
    }
    return -1;
}

void lm3s_ticks_start(void)
{
    SYST_CSR = 0;
    systick_wraps = 0;
    SYST_RVR = 0xFFFFFFu;
    SYST_CVR = 0; /* any write clears the counter: it reloads on the next tick */
    SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_TICKINT | SYST_CSR_ENABLE;
}

uint64_t lm3s_ticks(void)
{
    uint32_t wraps, count;
    do {
        wraps = systick_wraps;
        count = SYST_CVR;
    } while (wraps != systick_wraps);
    return (uint64_t)wraps * 0x1000000u + (0xFFFFFFu - count);
}

void lm3s_wait_host(void)
{
    zl_semi_call(0x07 /* SYS_READC */, 0);
}
