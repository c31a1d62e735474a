/* SPDX-License-Identifier: MIT */
/*
 * zline on a real display: the bunny turning on the LM3S6965 evaluation
 * board's 128x64 OLED (SSD0323 over SPI), rendered in scanline mode with
 * everything in the part's 64 KiB of SRAM. Run under QEMU:
 *
 *   qemu-system-arm -M lm3s6965evb -serial none -monitor none -icount shift=5,sleep=off \
 *     -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi \
 *     -kernel oled_demo.elf
 *
 * (a window shows the OLED; add -display none for none). After each frame the
 * firmware prints "frame N shown" and waits for one character from the
 * host on the semihosting console (press Enter; the CI test sends one after
 * taking a screendump), so every frame can be captured while it is on the
 * panel. At the end it prints the RAM map and the instructions per frame
 * (exact under -icount shift=5: see ticks_to_instructions; sleep=off keeps
 * virtual time still while the firmware waits, so runs repeat exactly)
 * and exits 0.
 */
#include <stdint.h>

#include "lm3s_board.h"
#include "oled_scene.h"
#include "semihosting.h"
#include "ssd0323.h"

/* The work buffer: zl_frame_bytes() of the scene's configuration on this
 * 32-bit target (a 64-bit host needs a little more: pointers), checked at
 * start-up (12-byte cached vertices since issue 22). */
#define WORK_BYTES 42328u
static uint64_t work[(WORK_BYTES + 7u) / 8u];

/* Under QEMU -icount shift=5 every instruction takes 2^5 = 32 ns of virtual
 * time, and SysTick counts the 50 MHz processor clock: 1.6 ticks per
 * instruction, exactly. On real silicon the same ticks are cycles. */
#define ICOUNT_SHIFT 5
static uint64_t ticks_to_instructions(uint64_t ticks)
{
    return ticks * 1000000000u / ((uint64_t)LM3S_SYSCLK_HZ << ICOUNT_SHIFT);
}

/* Text out through semihosting, without stdio (no heap, no locale, a few
 * hundred bytes of flash instead of newlib's printf). */
static void print(const char *s)
{
    zl_semi_puts(s);
}

static void print_num(uint64_t v)
{
    char digits[24];
    int n = (int)sizeof digits - 1;
    digits[n] = '\0';
    do {
        digits[--n] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0 && n > 0);
    print(&digits[n]);
}

/* "text" value "text" ... for one line of figures. */
static void print_fig(const char *before, uint64_t v, const char *after)
{
    print(before);
    print_num(v);
    print(after);
}

extern uint32_t __data_start[], __data_end[], __bss_start[], __bss_end[];
extern uint32_t __stack_bottom[], __stack_top[], __flash_used[];

static uint32_t span(const void *a, const void *b)
{
    return (uint32_t)((uintptr_t)b - (uintptr_t)a);
}

/* What uses the 64 KiB, from the linker's symbols and the objects' sizes. */
static void print_ram_map(void)
{
    uint32_t bss = span(__bss_start, __bss_end), data = span(__data_start, __data_end);
    uint32_t stack = span(__stack_bottom, __stack_top), total = data + bss + stack;
    print("RAM map (SRAM 65536 bytes):\n");
    print_fig("  work buffer (zline scanline mode, .bss)  ", sizeof work, " bytes\n");
    print_fig("  other .bss                               ", bss - sizeof work, " bytes\n");
    print_fig("  .data                                    ", data, " bytes\n");
    print_fig("  stack reserved                           ", stack, " bytes, of which\n");
    print_fig("    used at most                           ", lm3s_stack_used(), " bytes, including\n");
    print_fig("    zl_frame state                         ", sizeof(zl_frame), " bytes\n");
    print_fig("    driver row buffer                      ", SSD0323_WIDTH / 2, " bytes\n");
    print_fig("  total                                    ", total, " bytes");
    print_fig(" (", 65536u - total, " free)\n");
    print_fig("flash: ", (uintptr_t)__flash_used, " bytes of 262144\n");
}

int main(void)
{
    zl_frame_config cfg;
    uint64_t least = UINT64_MAX, most = 0, sum = 0, fps10;
    int i;
    oled_scene_config(&cfg);
    if (zl_frame_bytes(&cfg) == 0 || zl_frame_bytes(&cfg) > WORK_BYTES) {
        print_fig("oled_demo: the scene needs a work buffer of ", zl_frame_bytes(&cfg), " bytes: fix WORK_BYTES\n");
        return 1;
    }
    if (lm3s_clock_init() != 0)
        print("oled_demo: the PLL did not lock\n");
    ssd0323_init();
    lm3s_ticks_start();
    for (i = 0; i < OLED_SCENE_FRAMES; i++) {
        uint64_t t0 = lm3s_ticks(), n;
        int r = ssd0323_window(0, 0, SSD0323_WIDTH - 1, SSD0323_HEIGHT - 1);
        if (r == 0)
            r = oled_scene_render(i, work, sizeof work, ssd0323_send_band, NULL, NULL);
        n = ticks_to_instructions(lm3s_ticks() - t0);
        if (r != 0) {
            print_fig("oled_demo: frame ", (uint64_t)i, " failed\n");
            return 1;
        }
        least = n < least ? n : least;
        most = n > most ? n : most;
        sum += n;
        print_fig("frame ", (uint64_t)i, " shown");
        print_fig(" (", n, " instructions)\n");
        lm3s_wait_host();
    }
    print_ram_map();
    print("instructions per frame (render + grey conversion + SPI writes), QEMU -icount:\n");
    print_fig("  min ", least, "");
    print_fig(", max ", most, "");
    print_fig(", mean ", sum / OLED_SCENE_FRAMES, "\n");
    /* An estimate, not a measurement: QEMU counts instructions, and a
     * Cortex-M3 takes more than one cycle for loads, branches and divides. */
    fps10 = (uint64_t)LM3S_SYSCLK_HZ * 10u * OLED_SCENE_FRAMES / sum;
    print_fig("ESTIMATE at 50 MHz if every instruction took one cycle: ", fps10 / 10u, ".");
    print_fig("", fps10 % 10u, " frames/s (an upper bound; SPI transfer time not included)\n");
    return 0;
}
