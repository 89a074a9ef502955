/*
 * kf_link.h - receive side of the link: finds MAVLink 2 frames in the UART byte stream.
 *
 * A candidate starts at 0xFD.  It is dropped, and the search resumes ONE byte later, when its
 * incompatibility flags are unknown, its message id is not in the dialect, its length exceeds
 * the message's, or its CRC fails; so a stray 0xFD never hides the good frames after it.  A
 * good frame is consumed whole.  Memory: one fixed buffer of two maximal frames.
 */
#ifndef KF_LINK_H
#define KF_LINK_H

#include <stdint.h>

#include "kf_mavlink.h"

#define KF_LINK_BUF (2u * KF_FRAME_MAX)

typedef struct {
    uint8_t buf[KF_LINK_BUF];
    uint16_t len;
    uint32_t frames_ok;
    uint32_t crc_errors;      /* known message id and plausible length, bad CRC */
    uint32_t unknown_ids;     /* candidates whose message id is not in the dialect */
    uint32_t bad_frames;      /* unknown incompatibility flags, or longer than the message */
    uint32_t bytes_skipped;   /* bytes not part of an accepted frame */
} kf_link;

void kf_link_init(kf_link *l);

/* Where received bytes go: *room bytes free at the returned pointer. */
uint8_t *kf_link_space(kf_link *l, uint16_t *room);

/* n bytes were written at kf_link_space(). */
void kf_link_commit(kf_link *l, uint16_t n);

/* Next complete frame: 1 and *msg filled (payload zero-extended to the message's full length,
 * signature block copied), or 0 when more bytes are needed. */
int kf_link_next(kf_link *l, mavlink_message_t *msg);

#endif /* KF_LINK_H */
