/* MAVLink 2 frame scanner for the host decoder (kinefuse.host.link.decoder), loaded with cffi.
 *
 * Finds every frame that passes its CRC, with the rules of the pure-Python decoder: a failed
 * candidate (unknown incompat flag, unknown id, empty payload, bad CRC) resumes the search
 * ONE byte later; a good frame continues the search after it.  Payload unpacking and signature
 * checks stay in Python.  C99, no allocation, no globals. */
#include <stdint.h>
#include <string.h>

#define KF_MAGIC 0xFDu
#define KF_EMPTY 0xFFFFFFFFu

/* counters[]: 0 CRC errors, 1 unknown ids, 2 bad incompat flags, 3 empty payloads, 4 bytes skipped */
enum { C_CRC = 0, C_UNKNOWN = 1, C_INCOMPAT = 2, C_LENGTH = 3, C_SKIPPED = 4 };

static uint16_t crc_byte(uint16_t crc, uint8_t b)
{
    uint8_t t = (uint8_t)(b ^ (uint8_t)(crc & 0xFFu));
    t = (uint8_t)(t ^ (uint8_t)(t << 4));
    return (uint16_t)((crc >> 8) ^ ((uint16_t)t << 8) ^ ((uint16_t)t << 3) ^ (uint16_t)(t >> 4));
}

/* keys/vals: open-addressing table (size mask + 1, a power of two) of message ids;
   vals = CRC_EXTRA | payload length << 8 (the length is not needed: any non-empty payload
   is accepted, see below).  starts must hold n / 13 + 1 entries (the most
   frames n bytes can contain).  *keep = first byte not decided (an incomplete candidate when
   final == 0), else n.  Returns the number of frames written to starts. */
int32_t kf_scan(const uint8_t *buf, int32_t n, int32_t final,
                const uint32_t *keys, const uint16_t *vals, uint32_t mask,
                int32_t *starts, uint64_t *counters, int32_t *keep)
{
    int32_t i = 0;
    int32_t found = 0;
    *keep = n;
    while (i < n) {
        if (buf[i] != KF_MAGIC) {
            const uint8_t *p = (const uint8_t *)memchr(buf + i, (int)KF_MAGIC, (size_t)(n - i));
            if (p == NULL) {
                counters[C_SKIPPED] += (uint64_t)(n - i);
                break;
            }
            counters[C_SKIPPED] += (uint64_t)((int32_t)(p - buf) - i);
            i = (int32_t)(p - buf);
        }
        if (n - i < 10) {
            if (final) {
                counters[C_SKIPPED] += (uint64_t)(n - i);
            } else {
                *keep = i;
            }
            break;
        }
        {
            const uint8_t plen = buf[i + 1];
            const uint8_t inc = buf[i + 2];
            uint32_t msgid, h;
            int32_t end, stop, k;
            uint16_t crc, extra;
            if (inc & 0xFEu) {
                counters[C_INCOMPAT]++;
                counters[C_SKIPPED]++;
                i++;
                continue;
            }
            msgid = (uint32_t)buf[i + 7] | ((uint32_t)buf[i + 8] << 8) | ((uint32_t)buf[i + 9] << 16);
            h = (msgid * 2654435761u) & mask;  /* Knuth multiplicative hash */
            while (keys[h] != KF_EMPTY && keys[h] != msgid) {
                h = (h + 1u) & mask;
            }
            if (keys[h] == KF_EMPTY) {
                counters[C_UNKNOWN]++;
                counters[C_SKIPPED]++;
                i++;
                continue;
            }
            extra = (uint16_t)(vals[h] & 0xFFu);
            /* a longer payload (a newer firmware's extension fields) is accepted: MAVLink 2
               truncates it to the known fields, the CRC covers it as received */
            if (plen == 0u) {
                counters[C_LENGTH]++;
                counters[C_SKIPPED]++;
                i++;
                continue;
            }
            end = i + 12 + (int32_t)plen;
            stop = end + (inc ? 13 : 0);
            if (stop > n) {
                if (final) {  /* the stream ended inside this candidate: it fails */
                    counters[C_SKIPPED]++;
                    i++;
                    continue;
                }
                *keep = i;
                break;
            }
            crc = 0xFFFFu;
            for (k = i + 1; k < end - 2; k++) {
                crc = crc_byte(crc, buf[k]);
            }
            crc = crc_byte(crc, (uint8_t)extra);
            if (crc != (uint16_t)(buf[end - 2] | (buf[end - 1] << 8))) {
                counters[C_CRC]++;
                counters[C_SKIPPED]++;
                i++;
                continue;
            }
            starts[found++] = i;
            i = stop;
        }
    }
    return found;
}
