/*
 * kf_crc32.h - CRC-32 (IEEE 802.3, reflected, as zlib.crc32) for the stored configuration.
 */
#ifndef KF_CRC32_H
#define KF_CRC32_H

#include <stdint.h>

/* Continue a CRC: start with crc = 0; the result equals zlib.crc32(data, crc). */
uint32_t kf_crc32(uint32_t crc, const void *data, uint32_t len);

#endif /* KF_CRC32_H */
