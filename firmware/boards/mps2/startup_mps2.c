/*
 * startup_mps2.c - vector table and reset handler for Cortex-M0/M3/M4F on QEMU MPS2.
 *
 * Reset: enable the FPU (when compiled for one), copy .data from its load image, zero .bss,
 * run C/C++ constructors, call main(), and report its return value through semihosting
 * exit.  With newlib's rdimon crt0 (KF_NEWLIB_CRT0) everything after the .data copy is left
 * to its _start.
 * Faults also end the run through semihosting so a crashed test stops at once instead of
 * hanging until its timeout.
 */
#include <stdint.h>

#include "mps2.h"
#include "semihost.h"

#define KF_EXIT_HARDFAULT 134   /* like a POSIX abort: 128 + SIGABRT */

extern uint32_t __stack;
extern uint32_t __data_load__, __data_start__, __data_end__;
extern uint32_t __bss_start__, __bss_end__;
typedef void (*kf_ctor_fn)(void);
extern kf_ctor_fn __preinit_array_start[], __preinit_array_end[];
extern kf_ctor_fn __init_array_start[], __init_array_end[];

int main(void);
void Reset_Handler(void) __attribute__((noreturn));
void Default_Handler(void);
void HardFault_Handler(void);
void NMI_Handler(void) __attribute__((weak, alias("Default_Handler")));
void MemManage_Handler(void) __attribute__((weak, alias("HardFault_Handler")));
void BusFault_Handler(void) __attribute__((weak, alias("HardFault_Handler")));
void UsageFault_Handler(void) __attribute__((weak, alias("HardFault_Handler")));
void SVC_Handler(void) __attribute__((weak, alias("Default_Handler")));
void DebugMon_Handler(void) __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SysTick_Handler(void) __attribute__((weak, alias("Default_Handler")));
void UART0_RX_Handler(void) __attribute__((weak, alias("Default_Handler")));

typedef void (*kf_vector)(void);

/* The 16 ARMv6-M/ARMv7-M core exceptions, then IRQ 0 (UART0 RX: the board HAL's idle wait
 * wakes on it); the other peripheral IRQs stay unused (polling) and disabled. */
__attribute__((section(".vectors"), used))
const kf_vector kf_vector_table[17] = {
    (kf_vector)(uintptr_t)&__stack,
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
    UART0_RX_Handler,
};

#ifdef KF_NEWLIB_CRT0
void _start(void) __attribute__((noreturn));
#endif

void Reset_Handler(void)
{
#ifdef __ARM_FP
    SCS_CPACR |= 0xFu << 20;            /* full access to CP10/CP11 (the FPU) */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    /* .data always: QEMU, like a flash programmer, loads it at its load address only. */
    const uint32_t *src = &__data_load__;
    for (uint32_t *dst = &__data_start__; dst < &__data_end__; ++dst, ++src) {
        *dst = *src;
    }
#ifdef KF_NEWLIB_CRT0
    _start();                           /* rdimon crt0: heap, .bss, constructors, main, exit */
#else
    for (uint32_t *dst = &__bss_start__; dst < &__bss_end__; ++dst) {
        *dst = 0u;
    }
    for (kf_ctor_fn *f = __preinit_array_start; f < __preinit_array_end; ++f) {
        (*f)();
    }
    for (kf_ctor_fn *f = __init_array_start; f < __init_array_end; ++f) {
        (*f)();
    }
    kf_sh_exit(main());
#endif
}

void Default_Handler(void)
{
    kf_sh_write0("kinefuse: unexpected exception\n");
    kf_sh_exit(KF_EXIT_HARDFAULT);
}

void HardFault_Handler(void)
{
    kf_sh_write0("kinefuse: HardFault\n");
    kf_sh_exit(KF_EXIT_HARDFAULT);
}
