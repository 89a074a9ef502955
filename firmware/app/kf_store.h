/*
 * kf_store.h - the configuration in persistent storage: two copies, each with a CRC-32.
 *
 * Storage (kf_hal_storage_*) is split into two equal slots.  A save writes the slot that does
 * NOT hold the newest valid copy, with the next sequence number, and writes the CRC last; a
 * load takes the valid copy with the highest sequence number.  A power cut at any byte of a
 * save therefore leaves the previous copy intact: the configuration reads back either as
 * before the save or as after it, never as a mixture.
 *
 * A copy:  header (kf_store_header) | count x entry (name hash, 32-bit value) | CRC-32.
 * Values are stored by the FNV-1a hash of the parameter name, so a firmware with more, fewer or
 * reordered parameters still finds the values it knows.  Integers little-endian as the CPU
 * (both supported targets are little-endian).
 */
#ifndef KF_STORE_H
#define KF_STORE_H

#include <stdint.h>

#define KF_STORE_MAGIC   0x4643464Bu   /* "KFCF" */
#define KF_STORE_VERSION 1u
#define KF_STORE_KEY_LEN 32u

typedef struct {
    uint32_t magic;
    uint16_t version;
    uint16_t count;          /* entries that follow */
    uint32_t seq;            /* save counter: the higher valid copy wins */
    uint32_t reserved;
    uint8_t key[KF_STORE_KEY_LEN];   /* MAVLink 2 signing key; all zero: signing off */
    uint64_t sign_timestamp; /* signing floor after a reset (10 us since 2015-01-01): at or
                              * above every signed timestamp accepted (kf_handle.c) */
} kf_store_header;

typedef struct {
    uint32_t name_hash;
    uint32_t value;          /* bit pattern (float bits for REAL32) */
} kf_store_entry;

typedef struct {
    uint32_t seq;            /* sequence number of the newest valid copy (0: none) */
    uint8_t slot;            /* slot holding it */
    uint8_t have;            /* 1 when a valid copy exists */
    uint32_t errors;         /* failed HAL reads/writes, storage too small */
} kf_store;

/* entry i of the configuration to save (0..count-1) */
typedef void (*kf_store_get_fn)(void *ctx, uint16_t i, kf_store_entry *e);
/* one entry read back from the newest valid copy */
typedef void (*kf_store_put_fn)(void *ctx, const kf_store_entry *e);

uint32_t kf_store_name_hash(const char *name);

/* Find the newest valid copy; fill *hdr and call put() for each entry.  Returns the number of
 * entries, or -1 when no valid copy exists (first boot, or both copies damaged). */
int32_t kf_store_load(kf_store *st, kf_store_header *hdr, kf_store_put_fn put, void *ctx);

/* Save hdr (its seq is set here) and count entries from get().  Returns 0, or -1 when the
 * storage is too small or a HAL write failed (the previous copy is then still the newest). */
int kf_store_save(kf_store *st, kf_store_header *hdr, uint16_t count, kf_store_get_fn get, void *ctx);

#endif /* KF_STORE_H */
