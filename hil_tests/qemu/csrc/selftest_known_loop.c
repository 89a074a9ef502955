/*
 * selftest_known_loop.c - a function whose executed instruction count is known by hand,
 * for checking the instruction counter (Thumb-1 only, so it runs on ARMv6-M and ARMv7-M).
 *
 *   kf_known_loop(n), n >= 1: movs; n x (adds, subs, bne); movs; bx lr  =>  3n + 3
 *   from kf_known_loop up to (not including) kf_known_loop_end      =>  3n + 2
 * Returns 3n.
 */
#include <stdint.h>

uint32_t kf_known_loop(uint32_t n);

__asm__(
    "    .syntax unified\n"
    "    .thumb\n"
    "    .text\n"
    "    .balign 4\n"
    "    .global kf_known_loop\n"
    "    .global kf_known_loop_end\n"
    "    .type kf_known_loop, %function\n"
    "    .thumb_func\n"
    "kf_known_loop:\n"
    "    movs r1, #0\n"
    "1:  adds r1, r1, #3\n"
    "    subs r0, r0, #1\n"
    "    bne 1b\n"
    "    movs r0, r1\n"
    "kf_known_loop_end:\n"
    "    bx lr\n"
    "    .size kf_known_loop, .-kf_known_loop\n");
