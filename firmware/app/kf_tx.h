/*
 * kf_tx.h - transmit queue: whole frames in, as many bytes as the UART takes out.
 *
 * A frame that does not fit is dropped whole (and counted), never truncated, so the host
 * never sees half a frame from the unit.  The size is a build setting: KF_TX_BUFFER_BYTES
 * (a power of two; 4096 by default, the host build uses 65536).
 */
#ifndef KF_TX_H
#define KF_TX_H

#include <stdint.h>

#ifndef KF_TX_BUFFER_BYTES
#define KF_TX_BUFFER_BYTES 4096u
#endif

typedef struct {
    uint8_t buf[KF_TX_BUFFER_BYTES];
    uint32_t head;     /* next byte to write (free-running, wraps at 2^32) */
    uint32_t tail;     /* next byte to send */
    uint32_t frames_dropped;
    uint32_t bytes_sent;
} kf_tx;

void kf_tx_init(kf_tx *t);

/* Queue one frame: 1 when queued, 0 when it did not fit (dropped and counted). */
int kf_tx_push(kf_tx *t, const uint8_t *frame, uint32_t len);

/* Bytes waiting. */
uint32_t kf_tx_pending(const kf_tx *t);

/* Free bytes. */
uint32_t kf_tx_room(const kf_tx *t);

/* Hand waiting bytes to kf_hal_uart_write (as many as it accepts); returns bytes sent. */
uint32_t kf_tx_flush(kf_tx *t);

#endif /* KF_TX_H */
