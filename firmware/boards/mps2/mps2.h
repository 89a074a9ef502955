/*
 * mps2.h - memory map of the Arm MPS2 FPGA boards as emulated by QEMU (AN385, AN386).
 *
 * Sources: Arm AN385/AN386 application notes and QEMU hw/arm/mps2.c.  Both images put the
 * CMSDK peripherals at the same addresses and clock the CPU at 25 MHz.
 */
#ifndef KF_MPS2_H
#define KF_MPS2_H

#include <stdint.h>

#define MPS2_SYSCLK_HZ      25000000u   /* CPU clock, also SysTick's processor clock source */

#define MPS2_UART0_BASE     0x40004000u /* CMSDK APB UART 0: QEMU's first -serial */
#define MPS2_UART1_BASE     0x40005000u
#define MPS2_UART2_BASE     0x40006000u

/* System control space (ARMv6-M and ARMv7-M share these addresses). */
#define SCS_SYST_CSR  (*(volatile uint32_t *)0xE000E010u)  /* SysTick control and status */
#define SCS_SYST_RVR  (*(volatile uint32_t *)0xE000E014u)  /* SysTick reload value (24 bit) */
#define SCS_SYST_CVR  (*(volatile uint32_t *)0xE000E018u)  /* SysTick current value */
#define SCS_ICSR      (*(volatile uint32_t *)0xE000ED04u)  /* interrupt control and state */
#define SCS_AIRCR     (*(volatile uint32_t *)0xE000ED0Cu)  /* application interrupt/reset control */
#define SCS_CPACR     (*(volatile uint32_t *)0xE000ED88u)  /* coprocessor access (ARMv7-M only) */
#define NVIC_ISER0    (*(volatile uint32_t *)0xE000E100u)  /* interrupt set-enable, IRQ 0..31 */

#define MPS2_IRQ_UART0_RX  0u          /* QEMU hw/arm/mps2.c: UART0 RX = IRQ 0, TX = IRQ 1 */

#define SYST_CSR_ENABLE    (1u << 0)
#define SYST_CSR_TICKINT   (1u << 1)
#define SYST_CSR_CLKSOURCE (1u << 2)   /* 1 = processor clock */
#define SYST_CSR_COUNTFLAG (1u << 16)

#define ICSR_PENDSTSET     (1u << 26)  /* SysTick exception pending */

#define AIRCR_VECTKEY      (0x05FAu << 16)
#define AIRCR_SYSRESETREQ  (1u << 2)

#endif /* KF_MPS2_H */
