/*
 * kf_quat.c - the little quaternion algebra the application needs on a filter's output
 * (heading tare, ENU -> NED for ATTITUDE_QUATERNION).  Hamilton, scalar first, sensor -> earth.
 * float32; this is presentation after the filter, outside the bit-exact path.
 */
#include <math.h>
#include <stdint.h>

#include "kf_app_internal.h"

void kf_quat_mul(const float a[4], const float b[4], float out[4])
{
    float w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    float x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    float y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    float z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    out[0] = w;
    out[1] = x;
    out[2] = y;
    out[3] = z;
}

int kf_quat_heading_tare(const float q[4], float heading, float tare[4])
{
    /* sensor x axis in the earth frame: first column of R(q) */
    float hx = 1.0f - 2.0f * (q[2] * q[2] + q[3] * q[3]);
    float hy = 2.0f * (q[1] * q[2] + q[0] * q[3]);
    float n2 = hx * hx + hy * hy;
    if (!(n2 > 1e-4f) || !isfinite(heading)) {
        return -1;    /* x axis within ~0.6 deg of vertical: no heading to tare */
    }
    float n = sqrtf(n2);
    hx /= n;
    hy /= n;
    /* rotation about z taking (hx, hy) onto (cos h, sin h): half-angle form, no atan2 */
    float dx = cosf(heading);
    float dy = sinf(heading);
    float c = hx * dx + hy * dy;          /* cos of the angle */
    float s = hx * dy - hy * dx;          /* sin of the angle */
    float w = 1.0f + c;
    float z = s;
    float m2 = w * w + z * z;
    if (m2 < 1e-12f) {
        w = 0.0f;                         /* 180 degrees */
        z = 1.0f;
        m2 = 1.0f;
    }
    float m = sqrtf(m2);
    tare[0] = w / m;
    tare[1] = 0.0f;
    tare[2] = 0.0f;
    tare[3] = z / m;
    return 0;
}

void kf_quat_enu_to_ned(const float q_enu[4], float q_ned[4])
{
    /* NED from ENU: swap x/y and negate z = rotation by pi about (1, 1, 0)/sqrt(2) */
    static const float r[4] = {0.0f, 0.70710678f, 0.70710678f, 0.0f};
    kf_quat_mul(r, q_enu, q_ned);
}
