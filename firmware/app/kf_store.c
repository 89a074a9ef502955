/*
 * kf_store.c - two-copy configuration storage with CRC-32 (see kf_store.h).
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "kf_crc32.h"
#include "kf_hal.h"
#include "kf_store.h"

#define KF_STORE_SLOTS 2u
#define KF_STORE_CHUNK 64u   /* bytes gathered per HAL write */

uint32_t kf_store_name_hash(const char *name)
{
    uint32_t h = 2166136261u;   /* FNV-1a, 32 bit */
    for (uint32_t i = 0; i < 16u && name[i] != '\0'; i++) {
        h ^= (uint8_t)name[i];
        h *= 16777619u;
    }
    return h;
}

static uint32_t slot_size(void)
{
    return (kf_hal_storage_size() / KF_STORE_SLOTS) & ~7u;
}

static uint32_t copy_size(uint16_t count)
{
    return (uint32_t)sizeof(kf_store_header) + (uint32_t)count * (uint32_t)sizeof(kf_store_entry) + 4u;
}

/* 1 when slot s holds a valid copy; its header in *hdr. */
static int check_slot(kf_store *st, uint32_t s, kf_store_header *hdr)
{
    uint32_t base = s * slot_size();
    uint32_t crc, stored;
    kf_store_entry e;
    if (kf_hal_storage_read(base, hdr, (uint32_t)sizeof *hdr) != 0) {
        st->errors++;
        return 0;
    }
    if (hdr->magic != KF_STORE_MAGIC || hdr->version != KF_STORE_VERSION
        || copy_size(hdr->count) > slot_size()) {
        return 0;
    }
    crc = kf_crc32(0u, hdr, (uint32_t)sizeof *hdr);
    for (uint32_t i = 0; i < hdr->count; i++) {
        if (kf_hal_storage_read(base + (uint32_t)sizeof *hdr + i * (uint32_t)sizeof e, &e, (uint32_t)sizeof e) != 0) {
            st->errors++;
            return 0;
        }
        crc = kf_crc32(crc, &e, (uint32_t)sizeof e);
    }
    if (kf_hal_storage_read(base + copy_size(hdr->count) - 4u, &stored, 4u) != 0) {
        st->errors++;
        return 0;
    }
    return stored == crc;
}

int32_t kf_store_load(kf_store *st, kf_store_header *hdr, kf_store_put_fn put, void *ctx)
{
    kf_store_header h;
    kf_store_entry e;
    uint32_t base;
    st->have = 0u;
    st->seq = 0u;
    st->slot = 0u;
    if (slot_size() < copy_size(0u)) {
        st->errors++;
        return -1;
    }
    for (uint32_t s = 0; s < KF_STORE_SLOTS; s++) {
        if (check_slot(st, s, &h) && (!st->have || (int32_t)(h.seq - st->seq) > 0)) {
            st->have = 1u;
            st->seq = h.seq;
            st->slot = (uint8_t)s;
            *hdr = h;
        }
    }
    if (!st->have) {
        return -1;
    }
    base = st->slot * slot_size();
    for (uint32_t i = 0; i < hdr->count; i++) {
        if (kf_hal_storage_read(base + (uint32_t)sizeof h + i * (uint32_t)sizeof e, &e, (uint32_t)sizeof e) != 0) {
            st->errors++;
            return -1;
        }
        put(ctx, &e);
    }
    return (int32_t)hdr->count;
}

typedef struct {
    uint8_t buf[KF_STORE_CHUNK];
    uint32_t used;
    uint32_t offset;     /* storage offset of buf[0] */
    uint32_t crc;
    int failed;
} kf_store_writer;

static void writer_flush(kf_store_writer *w)
{
    if (w->used != 0u && !w->failed) {
        if (kf_hal_storage_write(w->offset, w->buf, w->used) != 0) {
            w->failed = 1;
        }
    }
    w->offset += w->used;
    w->used = 0u;
}

static void writer_put(kf_store_writer *w, const void *data, uint32_t len, int crc)
{
    const uint8_t *p = (const uint8_t *)data;
    if (crc) {
        w->crc = kf_crc32(w->crc, data, len);
    }
    for (uint32_t i = 0; i < len; i++) {
        if (w->used == KF_STORE_CHUNK) {
            writer_flush(w);
        }
        w->buf[w->used++] = p[i];
    }
}

int kf_store_save(kf_store *st, kf_store_header *hdr, uint16_t count, kf_store_get_fn get, void *ctx)
{
    kf_store_writer w;
    kf_store_entry e;
    uint32_t slot = st->have ? (st->slot + 1u) % KF_STORE_SLOTS : 0u;
    uint32_t crc;
    if (copy_size(count) > slot_size()) {
        st->errors++;
        return -1;
    }
    hdr->magic = KF_STORE_MAGIC;
    hdr->version = KF_STORE_VERSION;
    hdr->count = count;
    hdr->seq = st->seq + 1u;
    hdr->reserved = 0u;
    memset(&w, 0, sizeof w);
    w.offset = slot * slot_size();
    writer_put(&w, hdr, (uint32_t)sizeof *hdr, 1);
    for (uint16_t i = 0; i < count; i++) {
        get(ctx, i, &e);
        writer_put(&w, &e, (uint32_t)sizeof e, 1);
    }
    writer_flush(&w);
    crc = w.crc;
    writer_put(&w, &crc, 4u, 0);   /* the CRC last: until it is written the copy is invalid */
    writer_flush(&w);
    if (w.failed) {
        st->errors++;
        return -1;
    }
    st->have = 1u;
    st->seq = hdr->seq;
    st->slot = (uint8_t)slot;
    return 0;
}
