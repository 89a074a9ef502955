/*
 * selftest_quat_norm.c - quaternion normalisation written one operation per statement, in
 * the order a float32 model can reproduce bit for bit: ((w*w + x*x) + y*y) + z*z, sqrtf,
 * 1/n, four products.  Records: 4 float32 in, 4 float32 out.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#if FLT_EVAL_METHOD != 0
#error "float expressions must be evaluated in float (FLT_EVAL_METHOD 0)"
#endif
#ifdef __FAST_MATH__
#error "-ffast-math breaks bit-exactness"
#endif

void kf_selftest_quat_normalise(const void *in, void *out);

void kf_selftest_quat_normalise(const void *in, void *out)
{
    float q[4];
    float o[4];
    memcpy(q, in, sizeof q);
    float ww = q[0] * q[0];
    float xx = q[1] * q[1];
    float yy = q[2] * q[2];
    float zz = q[3] * q[3];
    float s1 = ww + xx;
    float s2 = s1 + yy;
    float s3 = s2 + zz;
    float norm = sqrtf(s3);
    float inv = 1.0f / norm;
    o[0] = q[0] * inv;
    o[1] = q[1] * inv;
    o[2] = q[2] * inv;
    o[3] = q[3] * inv;
    memcpy(out, o, sizeof o);
}
