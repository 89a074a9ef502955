/* uart_cmsdk.c - polled CMSDK APB UART driver (see uart_cmsdk.h). */
#include "uart_cmsdk.h"

#define STATE_TX_FULL (1u << 0)
#define STATE_RX_FULL (1u << 1)
#define CTRL_TX_EN    (1u << 0)
#define CTRL_RX_EN    (1u << 1)
#define CTRL_RX_INTEN (1u << 3)
#define BAUDDIV_MIN   16u   /* the TRM's lower limit; QEMU refuses to run the UART below it */

void kf_cmsdk_uart_init(kf_cmsdk_uart_regs *uart, uint32_t pclk_hz, uint32_t baud)
{
    uint32_t div = pclk_hz / baud;
    if (div < BAUDDIV_MIN) {
        div = BAUDDIV_MIN;
    }
    uart->ctrl = 0u;
    uart->bauddiv = div;
    uart->intstatus = 0xFu;               /* clear any pending interrupt flags */
    uart->ctrl = CTRL_TX_EN | CTRL_RX_EN;
}

void kf_cmsdk_uart_putc(kf_cmsdk_uart_regs *uart, uint8_t byte)
{
    while ((uart->state & STATE_TX_FULL) != 0u) {
    }
    uart->data = byte;
}

int kf_cmsdk_uart_getc(kf_cmsdk_uart_regs *uart, uint8_t *byte)
{
    if ((uart->state & STATE_RX_FULL) == 0u) {
        return 0;
    }
    *byte = (uint8_t)uart->data;
    return 1;
}

void kf_cmsdk_uart_rx_irq(kf_cmsdk_uart_regs *uart, int on)
{
    uart->intstatus = KF_CMSDK_UART_INT_RX;
    uart->ctrl = on ? (uart->ctrl | CTRL_RX_INTEN) : (uart->ctrl & ~CTRL_RX_INTEN);
}

int kf_cmsdk_uart_rx_ready(const kf_cmsdk_uart_regs *uart)
{
    return (uart->state & STATE_RX_FULL) != 0u;
}
