/*
 * kf_crc32.c - bitwise CRC-32: no table, because it runs only when the configuration is
 * loaded or saved (a few hundred bytes), and flash matters more than speed there.
 */
#include "kf_crc32.h"

uint32_t kf_crc32(uint32_t crc, const void *data, uint32_t len)
{
    const uint8_t *p = (const uint8_t *)data;
    crc = ~crc;
    for (uint32_t i = 0; i < len; i++) {
        crc ^= p[i];
        for (int b = 0; b < 8; b++) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
    return ~crc;
}
