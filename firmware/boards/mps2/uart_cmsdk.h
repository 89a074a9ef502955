/*
 * uart_cmsdk.h - polled driver for the Arm CMSDK APB UART (MPS2 UART0..4).
 *
 * Register map (Arm CMSDK TRM, QEMU hw/char/cmsdk-apb-uart.c): DATA 0x00, STATE 0x04
 * (bit0 TX buffer full, bit1 RX buffer full), CTRL 0x08 (bit0 TX enable, bit1 RX enable,
 * bit3 RX interrupt enable), INTSTATUS/INTCLEAR 0x0C (bit1 RX; write 1 to clear), BAUDDIV 0x10
 * (>= 16).  One byte of buffering each way, so RX must
 * be polled often enough; QEMU holds further input back until the byte is read.
 */
#ifndef KF_UART_CMSDK_H
#define KF_UART_CMSDK_H

#include <stdint.h>

typedef struct {
    volatile uint32_t data;
    volatile uint32_t state;
    volatile uint32_t ctrl;
    volatile uint32_t intstatus;
    volatile uint32_t bauddiv;
} kf_cmsdk_uart_regs;

/* Enable TX and RX at `baud` for a peripheral clock of `pclk_hz` (no interrupts). */
void kf_cmsdk_uart_init(kf_cmsdk_uart_regs *uart, uint32_t pclk_hz, uint32_t baud);

/* Send one byte, waiting while the transmit buffer is full. */
void kf_cmsdk_uart_putc(kf_cmsdk_uart_regs *uart, uint8_t byte);

#define KF_CMSDK_UART_INT_RX (1u << 1)

/* RX interrupt on (`on` != 0) or off: raised when a byte arrives, until cleared through
 * INTSTATUS (the byte itself stays in the buffer). */
void kf_cmsdk_uart_rx_irq(kf_cmsdk_uart_regs *uart, int on);

/* 1 when a received byte is waiting. */
int kf_cmsdk_uart_rx_ready(const kf_cmsdk_uart_regs *uart);

/* Non-blocking receive: returns 1 and stores the byte if one was waiting, else 0. */
int kf_cmsdk_uart_getc(kf_cmsdk_uart_regs *uart, uint8_t *byte);

#endif /* KF_UART_CMSDK_H */
