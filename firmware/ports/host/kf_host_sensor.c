/*
 * kf_host_sensor.c - the synthetic IMU of the host build (see kf_host_sensor.h).
 * Integer arithmetic only (C division truncates towards zero), so Python can mirror it.
 */
#include <stdint.h>

#include "kf_host_sensor.h"

/* sin(2 pi i / 256) * 1000, rounded */
static const int16_t k_sin[256] = {
    0, 25, 49, 74, 98, 122, 147, 171, 195, 219, 243, 267, 290, 314, 337, 360,
    383, 405, 428, 450, 471, 493, 514, 535, 556, 576, 596, 615, 634, 653, 672, 690,
    707, 724, 741, 757, 773, 788, 803, 818, 831, 845, 858, 870, 882, 893, 904, 914,
    924, 933, 942, 950, 957, 964, 970, 976, 981, 985, 989, 992, 995, 997, 999, 1000,
    1000, 1000, 999, 997, 995, 992, 989, 985, 981, 976, 970, 964, 957, 950, 942, 933,
    924, 914, 904, 893, 882, 870, 858, 845, 831, 818, 803, 788, 773, 757, 741, 724,
    707, 690, 672, 653, 634, 615, 596, 576, 556, 535, 514, 493, 471, 450, 428, 405,
    383, 360, 337, 314, 290, 267, 243, 219, 195, 171, 147, 122, 98, 74, 49, 25,
    0, -25, -49, -74, -98, -122, -147, -171, -195, -219, -243, -267, -290, -314, -337, -360,
    -383, -405, -428, -450, -471, -493, -514, -535, -556, -576, -596, -615, -634, -653, -672, -690,
    -707, -724, -741, -757, -773, -788, -803, -818, -831, -845, -858, -870, -882, -893, -904, -914,
    -924, -933, -942, -950, -957, -964, -970, -976, -981, -985, -989, -992, -995, -997, -999, -1000,
    -1000, -1000, -999, -997, -995, -992, -989, -985, -981, -976, -970, -964, -957, -950, -942, -933,
    -924, -914, -904, -893, -882, -870, -858, -845, -831, -818, -803, -788, -773, -757, -741, -724,
    -707, -690, -672, -653, -634, -615, -596, -576, -556, -535, -514, -493, -471, -450, -428, -405,
    -383, -360, -337, -314, -290, -267, -243, -219, -195, -171, -147, -122, -98, -74, -49, -25,
};

static int32_t isin(uint32_t phase)
{
    return k_sin[phase & 255u];
}

static int32_t icos(uint32_t phase)
{
    return k_sin[(phase + 64u) & 255u];
}

/* noise in [-3, 3] counts from a hash of (k, axis) */
static int32_t noise(uint64_t k, uint32_t axis)
{
    uint32_t x = (uint32_t)k * 2654435761u ^ (uint32_t)(k >> 32) ^ (axis * 0x9E3779B9u);
    x ^= x >> 15;
    x *= 0x2C1B3C6Du;
    x ^= x >> 12;
    return (int32_t)(x % 7u) - 3;
}

static int16_t sat16(int32_t v)
{
    return (int16_t)(v > 32767 ? 32767 : (v < -32768 ? -32768 : v));
}

void kf_host_sensor_sample(uint64_t k, uint64_t t_us, kf_raw_sample *out)
{
    /* heading: one turn (256 table steps) per 8 s of sample time */
    uint32_t ph = (uint32_t)((t_us * 32u) / 1000000u);
    out->acc[0] = sat16(noise(k, 0u));                    /* mG: +1 g on z (z up) */
    out->acc[1] = sat16(noise(k, 1u));
    out->acc[2] = sat16(1000 + noise(k, 2u));
    out->gyr[0] = sat16(noise(k, 3u));                    /* mrad/s: 0.785 rad/s about z */
    out->gyr[1] = sat16(noise(k, 4u));
    out->gyr[2] = sat16(785 + noise(k, 5u));
    /* earth field (ENU) 19 uT north, 45 uT down, seen from the turning sensor: mgauss */
    out->mag[0] = sat16((190 * isin(ph)) / 1000 + noise(k, 6u));
    out->mag[1] = sat16((190 * icos(ph)) / 1000 + noise(k, 7u));
    out->mag[2] = sat16(-450 + noise(k, 8u));
    out->mag_valid = (uint8_t)((k % 10u) == 0u);          /* magnetometer at a tenth of the rate */
}
