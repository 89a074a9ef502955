/*
 * kf_hal_mps2.c - firmware/app/kf_hal.h on QEMU MPS2 (AN385 / AN386).
 *
 * UART0 is the link to the host (QEMU's first -serial: pty or TCP).  The microsecond clock
 * is SysTick on the 25 MHz CPU clock with a 1 ms interrupt, because QEMU has no DWT CYCCNT;
 * under QEMU it follows host time, so it measures nothing about the emulated CPU's speed.
 * Storage is RAM in .noinit: it survives kf_hal_reboot() but not a power cycle (a new QEMU).
 * The board's state lives in this file's statics: one board, one instance.  kf_hal_micros()
 * is for thread context (not interrupt handlers).
 *
 * Idle (kf_hal_idle): WFI until the next interrupt - SysTick within 1 ms, or UART0 RX (its
 * interrupt is enabled only to wake the core; the handler just clears it, the byte is still
 * read by polling).  Under QEMU this matters for speed: a core spinning on the UART's status
 * register takes QEMU's global lock for every read, and the thread that delivers received
 * bytes (one at a time: the UART has a one-byte buffer) waits for that lock.
 */
#include <stdint.h>
#include <string.h>

#include "kf_hal.h"
#include "mps2.h"
#include "uart_cmsdk.h"

#define KF_UART_BAUD       115200u
#define KF_TICKS_PER_MS    (MPS2_SYSCLK_HZ / 1000u)
#define KF_TICKS_PER_US    (MPS2_SYSCLK_HZ / 1000000u)
#define KF_STORAGE_BYTES   4096u
#define KF_STORAGE_MAGIC   0x4B465354u   /* "KFST": storage was initialised since power-up */

typedef struct {
    uint32_t magic;
    uint8_t bytes[KF_STORAGE_BYTES];
} kf_mps2_storage;

static volatile uint32_t g_millis;   /* incremented by SysTick_Handler */
static uint32_t g_last_micros;       /* last value returned by kf_hal_micros */
static kf_mps2_storage g_storage __attribute__((section(".noinit")));

#define KF_UART0 ((kf_cmsdk_uart_regs *)MPS2_UART0_BASE)

void SysTick_Handler(void)
{
    g_millis = g_millis + 1u;
}

void UART0_RX_Handler(void)
{
    KF_UART0->intstatus = KF_CMSDK_UART_INT_RX;   /* write 1 to clear: the line drops */
}

void kf_hal_idle(void)
{
    /* with interrupts masked a pending one still ends WFI: no byte can slip in between the
     * check and the wait; the handler runs when they are unmasked */
    __asm__ volatile("cpsid i" ::: "memory");
    if (!kf_cmsdk_uart_rx_ready(KF_UART0)) {
        __asm__ volatile("wfi" ::: "memory");
    }
    __asm__ volatile("cpsie i" ::: "memory");
}

void kf_hal_init(void)
{
    kf_cmsdk_uart_init(KF_UART0, MPS2_SYSCLK_HZ, KF_UART_BAUD);
    kf_cmsdk_uart_rx_irq(KF_UART0, 1);
    NVIC_ISER0 = 1u << MPS2_IRQ_UART0_RX;

    g_millis = 0u;
    g_last_micros = 0u;
    SCS_SYST_CSR = 0u;
    SCS_SYST_RVR = KF_TICKS_PER_MS - 1u;
    SCS_SYST_CVR = 0u;
    SCS_SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_TICKINT | SYST_CSR_ENABLE;

    if (g_storage.magic != KF_STORAGE_MAGIC) {
        memset(g_storage.bytes, 0xFF, sizeof g_storage.bytes);   /* like erased flash */
        g_storage.magic = KF_STORAGE_MAGIC;
    }
}

uint32_t kf_hal_micros(void)
{
    uint32_t ms;
    uint32_t ticks_left;
    uint32_t wrapped;
    /* Re-read when the 1 ms interrupt ran between the reads.  If the counter has reloaded
     * but its interrupt is still pending (taken a few instructions later), the millisecond
     * count is one behind: a pending tick with a freshly reloaded counter means "add 1 ms". */
    do {
        ms = g_millis;
        ticks_left = SCS_SYST_CVR;
        wrapped = SCS_ICSR & ICSR_PENDSTSET;
    } while (ms != g_millis);
    if (wrapped != 0u && ticks_left > KF_TICKS_PER_MS / 2u) {
        ms++;
    }
    uint32_t elapsed = (KF_TICKS_PER_MS - 1u) - ticks_left;
    uint32_t now = ms * 1000u + elapsed / KF_TICKS_PER_US;
    /* QEMU derives the counter from host time but delivers the tick later, from another
     * thread, sometimes more than half a millisecond late (measured), so neither the
     * interrupt nor PENDSTSET is visible yet: a step backwards is a missed tick. */
    if ((int32_t)(now - g_last_micros) < 0) {
        now += 1000u;
        if ((int32_t)(now - g_last_micros) < 0) {
            now = g_last_micros;     /* more than one tick late: hold rather than go back */
        }
    }
    g_last_micros = now;
    return now;
}

int32_t kf_hal_uart_read(uint8_t *buf, int32_t max)
{
    int32_t n = 0;
    while (n < max && kf_cmsdk_uart_getc(KF_UART0, &buf[n]) != 0) {
        n++;
    }
    return n;
}

int32_t kf_hal_uart_write(const uint8_t *buf, int32_t len)
{
    for (int32_t i = 0; i < len; i++) {
        kf_cmsdk_uart_putc(KF_UART0, buf[i]);
    }
    return len < 0 ? 0 : len;
}

int kf_hal_sensor_read(kf_raw_sample *out)
{
    (void)out;   /* no sensor on this board: samples come over the link */
    return 0;
}

uint32_t kf_hal_storage_size(void)
{
    return KF_STORAGE_BYTES;
}

static int storage_range_ok(uint32_t offset, uint32_t len)
{
    return offset <= KF_STORAGE_BYTES && len <= KF_STORAGE_BYTES - offset;
}

int kf_hal_storage_read(uint32_t offset, void *buf, uint32_t len)
{
    if (!storage_range_ok(offset, len) || (buf == 0 && len != 0u)) {
        return -1;
    }
    memcpy(buf, &g_storage.bytes[offset], len);
    return 0;
}

int kf_hal_storage_write(uint32_t offset, const void *buf, uint32_t len)
{
    if (!storage_range_ok(offset, len) || (buf == 0 && len != 0u)) {
        return -1;
    }
    memcpy(&g_storage.bytes[offset], buf, len);
    return 0;
}

void kf_hal_reboot(void)
{
    __asm__ volatile("dsb" ::: "memory");
    SCS_AIRCR = AIRCR_VECTKEY | AIRCR_SYSRESETREQ;
    __asm__ volatile("dsb" ::: "memory");
    for (;;) {
    }
}
