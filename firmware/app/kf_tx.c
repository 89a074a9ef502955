/*
 * kf_tx.c - transmit ring buffer (see kf_tx.h).
 */
#include <stdint.h>
#include <string.h>

#include "kf_hal.h"
#include "kf_tx.h"

typedef char kf_tx_size_is_power_of_two[((KF_TX_BUFFER_BYTES & (KF_TX_BUFFER_BYTES - 1u)) == 0u) ? 1 : -1];

#define KF_TX_MASK (KF_TX_BUFFER_BYTES - 1u)

void kf_tx_init(kf_tx *t)
{
    memset(t, 0, sizeof *t);
}

uint32_t kf_tx_pending(const kf_tx *t)
{
    return t->head - t->tail;
}

uint32_t kf_tx_room(const kf_tx *t)
{
    return KF_TX_BUFFER_BYTES - kf_tx_pending(t);
}

int kf_tx_push(kf_tx *t, const uint8_t *frame, uint32_t len)
{
    if (len > kf_tx_room(t)) {
        t->frames_dropped++;
        return 0;
    }
    uint32_t at = t->head & KF_TX_MASK;
    uint32_t first = KF_TX_BUFFER_BYTES - at;
    if (first > len) {
        first = len;
    }
    memcpy(&t->buf[at], frame, first);
    memcpy(&t->buf[0], frame + first, len - first);
    t->head += len;
    return 1;
}

uint32_t kf_tx_flush(kf_tx *t)
{
    uint32_t sent = 0;
    while (kf_tx_pending(t) != 0u) {
        uint32_t at = t->tail & KF_TX_MASK;
        uint32_t n = KF_TX_BUFFER_BYTES - at;
        if (n > kf_tx_pending(t)) {
            n = kf_tx_pending(t);
        }
        if (n > 0x7FFFFFFFu) {
            n = 0x7FFFFFFFu;
        }
        int32_t w = kf_hal_uart_write(&t->buf[at], (int32_t)n);
        if (w <= 0) {
            break;
        }
        if ((uint32_t)w > n) {
            w = (int32_t)n;   /* a HAL claiming more than offered: do not run past the data */
        }
        t->tail += (uint32_t)w;
        sent += (uint32_t)w;
        if ((uint32_t)w < n) {
            break;    /* the UART is full: try again next turn */
        }
    }
    t->bytes_sent += sent;
    return sent;
}
