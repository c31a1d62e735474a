/* SPDX-License-Identifier: MIT */
/*
 * Start-up and fault handling for the Cortex-M port (mps2 boards under QEMU,
 * and any Cortex-M with RAM at the linker script's addresses).
 *
 * Reset: the core loads MSP from word 0 of the vector table (the top of RAM,
 * a small stack reserved for exception handlers). Reset_Handler switches
 * thread mode to PSP on the program stack below it, so a program that
 * overflows its stack still has a good stack for the fault report. Then
 * zl_port_start copies .data, zeroes .bss, enables the fault exceptions and
 * (where there is an MPU) a no-access guard region under the program stack,
 * runs constructors and calls exit(main()): exit flushes stdio and ends in
 * _exit, which stops QEMU with main's return value as its exit code.
 *
 * Every exception without a handler of its own (all are weak) ends in
 * zl_port_fault: it prints the exception, the stacked registers and, on
 * ARMv7-M, the fault status registers through semihosting and stops with
 * exit code ZL_PORT_EXIT_FAULT_BASE + exception number (255 for interrupts),
 * so a crash fails its test at once instead of hanging until a timeout.
 * Integer division by zero stops the same way on every core (exit code 246,
 * as for the ARMv7-M UsageFault DIVBYZERO), also in 64-bit and ARMv6-M
 * software division.
 */
#include <stdint.h>
#include <stdlib.h>

#include "semihosting.h"
#include "zl_port.h"

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__) || defined(__ARM_ARCH_8M_MAIN__) || \
    defined(__ARM_ARCH_8_1M_MAIN__)
#define ZL_PORT_V7M 1 /* CFSR/HFSR/MMFAR/BFAR, SHCSR fault enables (ARMv7-M, ARMv8-M Mainline) */
#else
#define ZL_PORT_V7M 0 /* ARMv6-M: HardFault only, no fault status registers */
#endif
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
#define ZL_PORT_PMSAV7 1 /* the MPU's ARMv7-M register layout (the stack guard) */
#else
#define ZL_PORT_PMSAV7 0 /* ARMv8-M's MPU (PMSAv8) differs: no guard region */
#endif

/* Linker script symbols (mps2.ld). */
extern uint32_t __data_load[], __data_start[], __data_end[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_guard[], __stack_bottom[], __stack_top[];
extern uint32_t __ram_start[], __ram_end[];
extern void (*__preinit_array_start[])(void), (*__preinit_array_end[])(void);
extern void (*__init_array_start[])(void), (*__init_array_end[])(void);

int main(void);

void Reset_Handler(void) __attribute__((naked, noreturn));
void zl_port_start(void) __attribute__((noreturn, used));
void zl_port_fault_entry(void) __attribute__((naked));
void zl_port_fault(uint32_t exc_return, uint32_t *msp, uint32_t *psp) __attribute__((noreturn, used));

#define ZL_WEAK_HANDLER(name) \
    void name(void) __attribute__((weak, alias("zl_port_fault_entry")))
ZL_WEAK_HANDLER(NMI_Handler);
ZL_WEAK_HANDLER(HardFault_Handler);
ZL_WEAK_HANDLER(MemManage_Handler);
ZL_WEAK_HANDLER(BusFault_Handler);
ZL_WEAK_HANDLER(UsageFault_Handler);
ZL_WEAK_HANDLER(SVC_Handler);
ZL_WEAK_HANDLER(DebugMon_Handler);
ZL_WEAK_HANDLER(PendSV_Handler);
ZL_WEAK_HANDLER(SysTick_Handler);
ZL_WEAK_HANDLER(Default_IRQHandler);

/* Word 0, the initial MSP, is written by the linker script just before this
 * table, so the table holds only code addresses. 16 system entries and the
 * 32 interrupts of the mps2 boards. */
typedef void (*zl_vector)(void);
__attribute__((section(".vectors"), used)) const zl_vector zl_port_vectors[15 + 32] = {
    Reset_Handler,
    NMI_Handler,
    HardFault_Handler,
    MemManage_Handler,
    BusFault_Handler,
    UsageFault_Handler,
    0, 0, 0, 0,
    SVC_Handler,
    DebugMon_Handler,
    0,
    PendSV_Handler,
    SysTick_Handler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
    Default_IRQHandler, Default_IRQHandler, Default_IRQHandler, Default_IRQHandler,
};

/* Naked: no prologue may touch the stack before the switch to PSP.
 * Thumb-1 instructions only, so it also assembles for ARMv6-M. */
void Reset_Handler(void)
{
    __asm__ volatile(
#if defined(__ARM_FP)
        /* Hard-float or softfp build: the compiler and the C library may
         * use FPU registers anywhere, so grant CP10/CP11 (the FPU) full
         * access before any C code runs (CPACR, 0xE000ED88). */
        "ldr r0, =0xE000ED88\n\t"
        "ldr r1, [r0]\n\t"
        "ldr r2, =0x00F00000\n\t"
        "orrs r1, r2\n\t"
        "str r1, [r0]\n\t"
        "dsb\n\t"
        "isb\n\t"
#endif
        "ldr r0, =__stack_top\n\t"
        "msr psp, r0\n\t"
        "movs r0, #2\n\t" /* CONTROL.SPSEL = 1: thread mode uses PSP */
        "msr control, r0\n\t"
        "isb\n\t"
        "bl zl_port_start\n\t"
        "b .\n\t"
        ".ltorg\n\t");
}

#define REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))
#define SCB_CCR REG32(0xE000ED14u)
#define SCB_SHCSR REG32(0xE000ED24u)
#define SCB_CFSR REG32(0xE000ED28u)
#define SCB_HFSR REG32(0xE000ED2Cu)
#define SCB_MMFAR REG32(0xE000ED34u)
#define SCB_BFAR REG32(0xE000ED38u)
#define MPU_TYPE REG32(0xE000ED90u)
#define MPU_CTRL REG32(0xE000ED94u)
#define MPU_RNR REG32(0xE000ED98u)
#define MPU_RBAR REG32(0xE000ED9Cu)
#define MPU_RASR REG32(0xE000EDA0u)

/* Must match __stack_guard_size in mps2.ld (an MPU region is a power of
 * two >= 32 bytes, aligned to its size). */
#define ZL_PORT_GUARD_LOG2 12

#if ZL_PORT_PMSAV7
static void barrier(void)
{
    __asm__ volatile("dsb\n\tisb" ::: "memory");
}
#endif

static void setup_faults(void)
{
#if ZL_PORT_V7M
    /* Own handlers for MemManage, BusFault and UsageFault instead of
     * everything escalating to HardFault: the report names the cause. */
    SCB_SHCSR |= (1u << 16) | (1u << 17) | (1u << 18);
    /* Trap integer division by zero (SDIV/UDIV otherwise return 0): it is
     * undefined behaviour in C, and the host test run traps it too. */
    SCB_CCR |= 1u << 4;
#endif
#if ZL_PORT_PMSAV7
    /* Stack guard: no access at all, even privileged, to the region below
     * the program stack; the rest of memory keeps the default map. */
    if (((MPU_TYPE >> 8) & 0xffu) != 0) {
        MPU_RNR = 0;
        MPU_RBAR = (uint32_t)(uintptr_t)__stack_guard;
        MPU_RASR = (1u << 28) /* XN */ | (0u << 24) /* AP: no access */ |
                   ((ZL_PORT_GUARD_LOG2 - 1u) << 1) | 1u;
        MPU_CTRL = (1u << 2) /* PRIVDEFENA */ | 1u;
        barrier();
    }
#endif
}

/* crti.o's hooks, absent with -nostartfiles: newlib's __libc_fini_array
 * references _fini. Constructors run from the init arrays below; nothing
 * registers destructors (a test program has none). */
void _init(void);
void _fini(void);
void _init(void)
{
}
void _fini(void)
{
}

void zl_port_start(void)
{
    uint32_t *src = __data_load, *dst;
    void (**fn)(void);

    for (dst = __data_start; dst < __data_end; dst++)
        *dst = *src++;
    for (dst = __bss_start; dst < __bss_end; dst++)
        *dst = 0;
    setup_faults();
    /* So zl_port_stack_used() at any time gives the high-water mark of the
     * whole run, without a zl_port_stack_paint() of its own. */
    zl_port_stack_paint();
    for (fn = __preinit_array_start; fn < __preinit_array_end; fn++)
        (*fn)();
    for (fn = __init_array_start; fn < __init_array_end; fn++)
        (*fn)();
    exit(main());
}

/* ------------------------------------------------------------ fault report */

static void put_hex(char *out, uint32_t v)
{
    static const char digits[] = "0123456789abcdef";
    int i;
    out[0] = '0';
    out[1] = 'x';
    for (i = 0; i < 8; i++)
        out[2 + i] = digits[(v >> (28 - 4 * i)) & 0xfu];
    out[10] = '\0';
}

static void print_reg(const char *name, uint32_t v)
{
    char hex[11];
    put_hex(hex, v);
    zl_semi_puts(" ");
    zl_semi_puts(name);
    zl_semi_puts("=");
    zl_semi_puts(hex);
}

static void print_dec(uint32_t v)
{
    char buf[11];
    int i = 10;
    buf[i] = '\0';
    do {
        buf[--i] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0 && i > 0);
    zl_semi_puts(buf + i);
}

static const char *exception_name(uint32_t n)
{
    switch (n) {
    case 2: return "NMI";
    case 3: return "HardFault";
    case 4: return "MemManage fault";
    case 5: return "BusFault";
    case 6: return "UsageFault";
    case 11: return "SVCall";
    case 12: return "DebugMonitor";
    case 14: return "PendSV";
    case 15: return "SysTick";
    default: return n >= 16 ? "interrupt" : "reserved exception";
    }
}

#if ZL_PORT_V7M
static void print_cfsr_bits(uint32_t cfsr, uint32_t hfsr)
{
    static const struct {
        uint8_t bit;
        const char *name;
    } bits[] = {
        {0, "IACCVIOL"}, {1, "DACCVIOL"}, {3, "MUNSTKERR"}, {4, "MSTKERR"}, {5, "MLSPERR"},
        {8, "IBUSERR"}, {9, "PRECISERR"}, {10, "IMPRECISERR"}, {11, "UNSTKERR"}, {12, "STKERR"},
        {13, "LSPERR"}, {16, "UNDEFINSTR"}, {17, "INVSTATE"}, {18, "INVPC"}, {19, "NOCP"}, {20, "STKOF"},
        {24, "UNALIGNED"}, {25, "DIVBYZERO"},
    };
    size_t i;
    zl_semi_puts("  cause:");
    for (i = 0; i < sizeof bits / sizeof bits[0]; i++) {
        if (cfsr & (1u << bits[i].bit)) {
            zl_semi_puts(" ");
            zl_semi_puts(bits[i].name);
        }
    }
    if (hfsr & (1u << 30))
        zl_semi_puts(" FORCED");
    if (hfsr & (1u << 1))
        zl_semi_puts(" VECTTBL");
    zl_semi_puts("\n");
}
#endif

static int in_ram(const uint32_t *p)
{
    uintptr_t a = (uintptr_t)p;
    return (a & 3u) == 0 && a >= (uintptr_t)__ram_start && a + 32u <= (uintptr_t)__ram_end;
}

/* Division by zero in software division (libgcc calls these; they are weak
 * there and return 0): ARMv6-M has no divide instruction, and 64-bit
 * division has none anywhere. Stop like the hardware trap (DIVBYZERO) does
 * on ARMv7-M: division by zero is undefined behaviour, not a result. */
int __aeabi_idiv0(int r);
long long __aeabi_ldiv0(long long r);

static void division_by_zero(uintptr_t caller) __attribute__((noreturn));
static void division_by_zero(uintptr_t caller)
{
    zl_semi_puts("\n*** integer division by zero (software division) ***\n");
    print_reg("caller", (uint32_t)caller);
    zl_semi_puts("\n  cause: DIVBYZERO\n");
    zl_semi_exit(ZL_PORT_EXIT_FAULT_BASE + 6);
}

int __aeabi_idiv0(int r)
{
    (void)r;
    division_by_zero((uintptr_t)__builtin_return_address(0));
}

long long __aeabi_ldiv0(long long r)
{
    (void)r;
    division_by_zero((uintptr_t)__builtin_return_address(0));
}

/* All exceptions come here with the EXC_RETURN value and both stack
 * pointers: the frame (r0-r3, r12, lr, pc, xPSR) is on whichever stack the
 * interrupted code used. */
void zl_port_fault_entry(void)
{
    __asm__ volatile(
        "mov r0, lr\n\t"
        "mrs r1, msp\n\t"
        "mrs r2, psp\n\t"
        "bl zl_port_fault\n\t");
}

void zl_port_fault(uint32_t exc_return, uint32_t *msp, uint32_t *psp)
{
    uint32_t ipsr, exc;
    uint32_t *frame = (exc_return & 4u) ? psp : msp;
    int overflow = 0;

    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    exc = ipsr & 0x1ffu;

#if ZL_PORT_PMSAV7
    /* Off with the MPU, so the frame can be read even when it was pushed
     * into the stack guard. */
    MPU_CTRL = 0;
    barrier();
#endif

    zl_semi_puts("\n*** ");
    zl_semi_puts(exception_name(exc));
    zl_semi_puts(" (exception ");
    print_dec(exc);
    zl_semi_puts(")");
    if (exc >= 16) {
        zl_semi_puts(", IRQ ");
        print_dec(exc - 16u);
    }
    zl_semi_puts(" ***\n");

    if ((exc_return & 4u) && (uintptr_t)psp < (uintptr_t)__stack_bottom)
        overflow = 1;

    if (in_ram(frame)) {
        print_reg("pc", frame[6]);
        print_reg("lr", frame[5]);
        print_reg("xpsr", frame[7]);
        print_reg("sp", (uint32_t)(uintptr_t)(frame + 8));
        zl_semi_puts("\n");
        print_reg("r0", frame[0]);
        print_reg("r1", frame[1]);
        print_reg("r2", frame[2]);
        print_reg("r3", frame[3]);
        print_reg("r12", frame[4]);
        zl_semi_puts("\n");
    } else {
        print_reg("sp", (uint32_t)(uintptr_t)frame);
        zl_semi_puts(" (not in RAM: no stacked registers)\n");
    }
#if ZL_PORT_V7M
    {
        uint32_t cfsr = SCB_CFSR, hfsr = SCB_HFSR;
        uint32_t mmfar = SCB_MMFAR, bfar = SCB_BFAR;
        print_reg("CFSR", cfsr);
        print_reg("HFSR", hfsr);
        if (cfsr & (1u << 7)) /* MMARVALID */
            print_reg("MMFAR", mmfar);
        if (cfsr & (1u << 15)) /* BFARVALID */
            print_reg("BFAR", bfar);
        zl_semi_puts("\n");
        print_cfsr_bits(cfsr, hfsr);
        if ((cfsr & (1u << 7)) && mmfar >= (uint32_t)(uintptr_t)__stack_guard &&
            mmfar < (uint32_t)(uintptr_t)__stack_bottom)
            overflow = 1;
        if (cfsr & (1u << 4)) /* MSTKERR: pushing the frame hit the guard */
            overflow = 1;
    }
#endif
    if (overflow) {
        zl_semi_puts("  stack overflow: the program used more than its ");
        print_dec((uint32_t)zl_port_stack_size());
        zl_semi_puts(" bytes of stack (ZLINE_PORT_STACK_SIZE)\n");
    }
    zl_semi_exit(exc < 15u ? (int)(ZL_PORT_EXIT_FAULT_BASE + exc) : 255);
}
