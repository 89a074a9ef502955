/*
 * kf_link.c - MAVLink 2 frame scanner with resume-at-next-byte on every failure.
 */
#include <stdint.h>
#include <string.h>

#include "kf_link.h"

#define KF_HDR MAVLINK_CORE_HEADER_LEN   /* bytes after the magic: len..msgid (9) */

void kf_link_init(kf_link *l)
{
    memset(l, 0, sizeof *l);
}

uint8_t *kf_link_space(kf_link *l, uint16_t *room)
{
    *room = (uint16_t)(KF_LINK_BUF - l->len);
    return &l->buf[l->len];
}

void kf_link_commit(kf_link *l, uint16_t n)
{
    if (n > KF_LINK_BUF - l->len) {
        n = (uint16_t)(KF_LINK_BUF - l->len);   /* never trust a caller past the buffer */
    }
    l->len = (uint16_t)(l->len + n);
}

static void drop(kf_link *l, uint16_t n)
{
    memmove(l->buf, &l->buf[n], (size_t)(l->len - n));
    l->len = (uint16_t)(l->len - n);
}

int kf_link_next(kf_link *l, mavlink_message_t *msg)
{
    for (;;) {
        uint16_t start = 0;
        while (start < l->len && l->buf[start] != MAVLINK_STX) {
            start++;
        }
        if (start > 0) {
            l->bytes_skipped += start;
            drop(l, start);
        }
        if (l->len < 1u + KF_HDR) {
            return 0;
        }
        const uint8_t *b = l->buf;
        uint8_t plen = b[1];
        uint8_t incompat = b[2];
        uint32_t msgid = (uint32_t)b[7] | ((uint32_t)b[8] << 8) | ((uint32_t)b[9] << 16);
        if ((incompat & (uint8_t)~MAVLINK_IFLAG_SIGNED) != 0u) {
            l->bad_frames++;
            l->bytes_skipped++;
            drop(l, 1u);
            continue;
        }
        const mavlink_msg_entry_t *e = mavlink_get_msg_entry(msgid);
        if (e == NULL) {
            l->unknown_ids++;
            l->bytes_skipped++;
            drop(l, 1u);
            continue;
        }
        if (plen > e->max_msg_len) {
            l->bad_frames++;
            l->bytes_skipped++;
            drop(l, 1u);
            continue;
        }
        uint16_t sig = (incompat & MAVLINK_IFLAG_SIGNED) ? MAVLINK_SIGNATURE_BLOCK_LEN : 0u;
        uint16_t total = (uint16_t)(1u + KF_HDR + plen + 2u + sig);
        if (l->len < total) {
            return 0;
        }
        uint16_t crc = crc_calculate(&b[1], (uint16_t)(KF_HDR + plen));
        crc_accumulate(e->crc_extra, &crc);
        uint16_t got = (uint16_t)(b[1u + KF_HDR + plen] | ((uint16_t)b[2u + KF_HDR + plen] << 8));
        if (crc != got) {
            l->crc_errors++;
            l->bytes_skipped++;
            drop(l, 1u);
            continue;
        }
        memset(msg, 0, sizeof *msg);
        msg->magic = b[0];
        msg->len = plen;
        msg->incompat_flags = incompat;
        msg->compat_flags = b[3];
        msg->seq = b[4];
        msg->sysid = b[5];
        msg->compid = b[6];
        msg->msgid = msgid & 0xFFFFFFu;   /* 24 bits by construction */
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &b[1u + KF_HDR], plen);   /* rest stays zero */
        msg->checksum = crc;
        msg->ck[0] = (uint8_t)(crc & 0xFFu);
        msg->ck[1] = (uint8_t)(crc >> 8);
        if (sig != 0u) {
            memcpy(msg->signature, &b[3u + KF_HDR + plen], MAVLINK_SIGNATURE_BLOCK_LEN);
        }
        l->frames_ok++;
        drop(l, total);
        return 1;
    }
}
