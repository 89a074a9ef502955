/*
 * kf_fixed.h - fixed-point helpers of kinefuse generated code.  Copied verbatim from
 * codegen/runtime/kf_fixed.h by `kinefuse codegen`; its Python mirror is codegen/runtime/q.py
 * (one function there for each function the generated code calls; the building blocks below them,
 * kf_smull, kf_bitlen32, kf_isqrt_floor..., are exact integer functions with no mirror).
 *
 * Number format: every real value is an int32 "raw" with a per-variable number of fractional
 * bits f chosen by range analysis (value = raw * 2^-f; f may be negative or exceed 31).
 * Intermediates are int64 and are proven (by integer interval analysis in the generator) not to
 * overflow.  Raw values stay within +-(2^31 - 1).
 * Rounding: right shifts round half up (add half an LSB, then shift); division rounds half away
 * from zero; square roots round to nearest.  Saturation is explicit (kf_sat) and only emitted
 * where a bound cannot be proven.
 */
#ifndef KF_FIXED_H
#define KF_FIXED_H

#include <stdint.h>

/* The generated code relies on GCC/Clang's documented arithmetic right shift of negative values. */
typedef char kf_requires_arithmetic_shift[((-1) >> 1) == -1 ? 1 : -1];
typedef char kf_requires_arithmetic_shift64[(((int64_t)-1) >> 1) == -1 ? 1 : -1];

/* A positive value with a dynamic binary point: value = m * 2^-e, m in [2^30, 2^31).
 * Used for reciprocal square roots, whose range is too wide for one static format. */
typedef struct {
    int32_t m;
    int32_t e;
} kf_dyn;

/* 32 x 32 -> 64-bit products.  ARMv6-M / ARMv8-M Baseline (Cortex-M0/M0+/M23) have no long
 * multiply and GCC calls the 64 x 64 __aeabi_lmul (about 45 instructions with the call); four
 * 16 x 16 products and one 32-bit product give the same bits in about 20 (Hacker's Delight 8-2).
 * KF_PORTABLE_LONG_MUL selects that path, the 32-bit division loop of kf_udiv64_32 (in C; the
 * Thumb-1 assembly form runs only on those cores) and the digit-by-digit square root on any
 * target (the host tests compare both paths). */
#if defined(__ARM_ARCH_6M__) || defined(__ARM_ARCH_8M_BASE__) || defined(KF_PORTABLE_LONG_MUL)
#define KF_NO_LONG_MUL 1   /* these cores have no CLZ and (v6-M) no divider either */
#endif

/* Cores with a 32-bit divider and CLZ but 64-bit division only in libgcc (ARMv7-M: M3, M4, M7;
 * ARMv8-M Mainline) divide 64 by 32 bits in two 16-bit digits; KF_PORTABLE_DIVLU selects this
 * path on the host for its tests. */
#if !defined(KF_NO_LONG_MUL) && \
    ((defined(__arm__) && defined(__ARM_FEATURE_IDIV) && defined(__ARM_FEATURE_CLZ)) || \
     defined(KF_PORTABLE_DIVLU))
#define KF_DIV_BY_DIGITS 1
#endif

#ifdef KF_NO_LONG_MUL
static inline uint64_t kf_umull(uint32_t a, uint32_t b)
{
    const uint32_t a0 = a & 0xFFFFu, a1 = a >> 16, b0 = b & 0xFFFFu, b1 = b >> 16;
    const uint32_t t = a1 * b0 + ((a0 * b0) >> 16);    /* < 2^32 */
    const uint32_t w = a0 * b1 + (t & 0xFFFFu);        /* < 2^32 */
    const uint32_t hi = a1 * b1 + (t >> 16) + (w >> 16);
    return ((uint64_t)hi << 32) | (uint64_t)(a * b);
}

static inline int64_t kf_smull(int32_t a, int32_t b)
{
    const uint32_t a0 = (uint32_t)a & 0xFFFFu, b0 = (uint32_t)b & 0xFFFFu;
    const int32_t a1 = a >> 16, b1 = b >> 16;
    const int32_t t = a1 * (int32_t)b0 + (int32_t)((a0 * b0) >> 16);   /* |t| < 2^31 */
    const int32_t w = (int32_t)a0 * b1 + (t & 0xFFFF);                 /* |w| < 2^31 */
    const int32_t hi = a1 * b1 + (t >> 16) + (w >> 16);
    return (int64_t)(((uint64_t)(uint32_t)hi << 32) | (uint64_t)((uint32_t)a * (uint32_t)b));
}
#else
static inline uint64_t kf_umull(uint32_t a, uint32_t b)
{
    return (uint64_t)a * b;
}

static inline int64_t kf_smull(int32_t a, int32_t b)
{
    return (int64_t)a * b;
}
#endif

/* Number of significant bits of v (0 for 0): CLZ where the core has it, else five steps (the
 * M0 has no CLZ; GCC's __clzsi2 call costs more). */
static inline int32_t kf_bitlen32(uint32_t v)
{
#if defined(__GNUC__) && !defined(KF_NO_LONG_MUL)
    return (v == 0u) ? 0 : 32 - __builtin_clz(v);
#else
    int32_t n = 0;
    if ((v >> 16) != 0u) {
        v >>= 16;
        n += 16;
    }
    if ((v >> 8) != 0u) {
        v >>= 8;
        n += 8;
    }
    if ((v >> 4) != 0u) {
        v >>= 4;
        n += 4;
    }
    if ((v >> 2) != 0u) {
        v >>= 2;
        n += 2;
    }
    if ((v >> 1) != 0u) {
        v >>= 1;
        n += 1;
    }
    return n + (int32_t)v;
#endif
}

static inline int32_t kf_bitlen64(uint64_t v)
{
    return ((v >> 32) != 0u) ? 32 + kf_bitlen32((uint32_t)(v >> 32)) : kf_bitlen32((uint32_t)v);
}

/* Clamp an int64 to [lo, hi]. */
static inline int32_t kf_sat(int64_t v, int32_t lo, int32_t hi)
{
    return (v < lo) ? lo : ((v > hi) ? hi : (int32_t)v);
}

/* v * 2^k clamped to [lo, hi], for k >= 0, without overflow. */
static inline int32_t kf_lsh_sat(int64_t v, int32_t k, int32_t lo, int32_t hi)
{
    if (k >= 62) {
        return (v > 0) ? hi : ((v < 0) ? lo : kf_sat(0, lo, hi));
    }
    if (v > (((int64_t)hi) >> k)) {
        return hi;
    }
    if (v < -((-(int64_t)lo) >> k)) {
        return lo;
    }
    return (int32_t)(v * ((int64_t)1 << k));
}

#ifdef KF_DIV_BY_DIGITS
/* floor((u * 2^16 + next) / d) for a normalised d (top bit set), u < d and next < 2^16: one
 * 32/16-bit hardware division by d's top half, then at most two corrections. */
static inline __attribute__((always_inline)) uint32_t kf_div_digit16(uint32_t u, uint32_t next,
                                                                     uint32_t d)
{
    const uint32_t dh = d >> 16, dl = d & 0xFFFFu;
    uint32_t q = u / dh, rhat = u - q * dh;
    while ((q > 0xFFFFu) || (q * dl > ((rhat << 16) | next))) {
        q--;
        rhat += dh;
        if (rhat > 0xFFFFu) {      /* rhat * 2^16 >= 2^32 > q * dl: no further correction */
            break;
        }
    }
    return q;
}
#endif

/* floor(n / d) and the remainder, for 0 < d <= 2^31 and n < d * 2^32 (the quotient fits 32 bits);
 * where there is long multiplication (every path but the shift-subtract loop) d may be any
 * nonzero 32-bit value.
 * Where there is no divider (ARMv6-M, ARMv8-M Baseline) GCC would call libgcc's 64-bit
 * __udivmoddi4 (about 360 instructions on a Cortex-M0); 32 restoring shift-subtract steps on
 * the 32-bit halves take about 240 (the remainder stays below d <= 2^31, so doubling it keeps it
 * in 32 bits).  On Thumb-1 the step is written in assembly: the 64-bit shift is one adds/adcs
 * pair, which GCC does not produce from C. */
static inline uint32_t kf_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem)
{
#ifdef KF_NO_LONG_MUL
    uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n;
#if defined(__GNUC__) && defined(__thumb__) && !defined(__thumb2__) && !defined(KF_PORTABLE_LONG_MUL)
    uint32_t i = 32u;
    __asm__(".syntax unified\n"   /* GCC hands Thumb-1 inline assembly over in divided syntax */
            "1:\n\t"
            "adds %[lo], %[lo], %[lo]\n\t"   /* hi:lo <<= 1 */
            "adcs %[hi], %[hi], %[hi]\n\t"
            "cmp %[hi], %[d]\n\t"
            "bcc 2f\n\t"
            "subs %[hi], %[hi], %[d]\n\t"    /* quotient bit 1 into the vacated low bit */
            "adds %[lo], %[lo], #1\n"
            "2:\n\t"
            "subs %[i], %[i], #1\n\t"
            "bne 1b"
            : [lo] "+l"(lo), [hi] "+l"(hi), [i] "+l"(i)
            : [d] "l"(d)
            : "cc");
#else
    int32_t i;
    for (i = 0; i < 32; i++) {
        hi = (hi << 1) | (lo >> 31);
        lo <<= 1;
        if (hi >= d) {
            hi -= d;
            lo |= 1u;
        }
    }
#endif
    *rem = hi;
    return lo;
#elif defined(KF_DIV_BY_DIGITS)
    /* Two 16-bit quotient digits (Knuth's algorithm D as Hacker's Delight 9-3 divlu writes it):
     * about 40 instructions where libgcc's 64-bit __aeabi_uldivmod takes about 55. */
    uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n, q1, q0, mid;
    const int32_t s = __builtin_clz(d);            /* normalise: top bit of d set */
    d <<= s;
    hi = (hi << s) | ((lo >> 1) >> (31 - s));      /* (lo >> 32) would be undefined for s = 0 */
    lo <<= s;
    q1 = kf_div_digit16(hi, lo >> 16, d);
    mid = (hi << 16) + (lo >> 16) - q1 * d;        /* exact mod 2^32: the true value is < d */
    q0 = kf_div_digit16(mid, lo & 0xFFFFu, d);
    *rem = ((mid << 16) + (lo & 0xFFFFu) - q0 * d) >> s;
    return (q1 << 16) | q0;
#else
    const uint64_t q = n / d;
    *rem = (uint32_t)(n - q * d);
    return (uint32_t)q;
#endif
}

/* n / d rounded half away from zero, clamped to [lo, hi]; d == 0 saturates by the sign of n. */
static inline int32_t kf_div_rnd(int64_t n, int64_t d, int32_t lo, int32_t hi)
{
    uint64_t un, ud, q, r;
    int64_t v;
    if (d == 0) {
        return (n > 0) ? hi : ((n < 0) ? lo : kf_sat(0, lo, hi));
    }
    un = (n < 0) ? ((uint64_t)0 - (uint64_t)n) : (uint64_t)n;
    ud = (d < 0) ? ((uint64_t)0 - (uint64_t)d) : (uint64_t)d;
    if ((ud <= ((uint64_t)1 << 31)) && ((un >> 32) < ud)) {    /* the generated code's usual case */
        uint32_t r32;
        q = kf_udiv64_32(un, (uint32_t)ud, &r32);
        r = r32;
    } else {
        q = un / ud;
        r = un - q * ud;
    }
    if (r >= ud - r) {
        q += 1u;
    }
    v = ((n < 0) != (d < 0)) ? -(int64_t)q : (int64_t)q;
    return kf_sat(v, lo, hi);
}

/* `groups` digit-by-digit square-root steps, each taking the two top bits of *w into root *r and
 * remainder *m (m <= 2r holds after each step).  32-bit while the root stays below 2^29, which
 * keeps m * 4 + 3 below 2^32 (64-bit compares and subtractions cost 2-4 instructions each on a
 * Cortex-M). */
static inline void kf_isqrt_digits32(uint32_t *w, int32_t groups, uint32_t *r, uint32_t *m)
{
    uint32_t ww = *w, rr = *r, mm = *m;
    for (; groups > 0; groups--) {
        mm = (mm << 2) | (ww >> 30);
        ww <<= 2;
        rr <<= 1;
        if (mm >= ((rr << 1) | 1u)) {
            mm -= (rr << 1) | 1u;
            rr |= 1u;
        }
    }
    *w = ww;
    *r = rr;
    *m = mm;
}

/* Where a hardware float square root exists (and 64-bit products are cheap), kf_isqrt_floor
 * starts from it; elsewhere (the M0, an M3/M4 without FPU) it goes digit by digit.  Either way
 * the result is the exact floor: the float value is only a first guess. */
#if !defined(KF_NO_LONG_MUL) && !defined(KF_PORTABLE_ISQRT) && \
    (defined(__ARM_FP) || defined(__x86_64__) || defined(__i386__) || defined(__aarch64__))
#define KF_ISQRT_BY_FLOAT 1
#endif

/* floor(sqrt(n)) for any n < 2^64, and the remainder n - r^2. */
static inline uint64_t kf_isqrt_floor(uint64_t n, uint64_t *rem)
{
#ifdef KF_ISQRT_BY_FLOAT
    /* float guess (relative error below 2^-22), one Newton step (the guess is then within a few
     * units, from above), then exact settling with 64-bit products (r < 2^32: no overflow) */
    const float x = (float)(uint32_t)(n >> 32) * 4294967296.0f + (float)(uint32_t)n;
    const float g = __builtin_sqrtf(x);
    uint64_t r;
    if (n < 2u) {
        *rem = 0u;
        return n;
    }
    r = (g >= 4294967040.0f) ? 0xFFFFFFFFu : (uint64_t)(uint32_t)g;   /* r >= 1 */
    if ((n >> 32) < r) {      /* the quotient fits 32 bits: always but for n near 2^64 */
        uint32_t unused;
        r = (r + kf_udiv64_32(n, (uint32_t)r, &unused)) >> 1;
    } else {
        r = (r + n / r) >> 1;
    }
    if (r > 0xFFFFFFFFu) {
        r = 0xFFFFFFFFu;
    }
    while (r * r > n) {
        r--;
    }
    while ((r < 0xFFFFFFFFu) && ((r + 1u) * (r + 1u) <= n)) {
        r++;
    }
    *rem = n - r * r;
    return r;
#else
    uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n, r = 0, m = 0;
    uint64_t r64, m64;
    int32_t i;
    if (hi == 0) {
        kf_isqrt_digits32(&lo, 16, &r, &m);
        *rem = m;
        return r;
    }
    kf_isqrt_digits32(&hi, 16, &r, &m);     /* r < 2^16 */
    kf_isqrt_digits32(&lo, 13, &r, &m);     /* r < 2^29; lo keeps its last 6 bits on top */
    r64 = r;
    m64 = m;
    for (i = 0; i < 3; i++) {
        m64 = (m64 << 2) | (lo >> 30);
        lo <<= 2;
        r64 <<= 1;
        if (m64 >= ((r64 << 1) | 1u)) {
            m64 -= (r64 << 1) | 1u;
            r64 |= 1u;
        }
    }
    *rem = m64;
    return r64;
#endif
}

/* sqrt(n) rounded to nearest; 0 for n <= 0. */
static inline int64_t kf_isqrt_rnd(int64_t n)
{
    uint64_t r, rem;
    if (n <= 0) {
        return 0;
    }
    r = kf_isqrt_floor((uint64_t)n, &rem);
    if (rem > r) {   /* n > (r + 1/2)^2 */
        r += 1u;
    }
    return (int64_t)r;
}

/* 1 / sqrt(y * 2^-fy) as a dynamic value, for y < 2^62; y <= 0 is treated as 1. */
static inline kf_dyn kf_rsqrt_dyn64(int64_t y, int32_t fy)
{
    kf_dyn out;
    uint64_t n, r, rem, m;
    int32_t s = 0;
    n = (y <= 0) ? 1u : (uint64_t)y;
    if ((fy & 1) != 0) {            /* make fy + s even so the square root is exact in exponent */
        if (n >= ((uint64_t)1 << 61)) {
            n = (n + 1u) >> 1;
            s = -1;
        } else {
            n <<= 1;
            s = 1;
        }
    }
    if (n < ((uint64_t)1 << 60)) {      /* normalise n to [2^60, 2^62) by an even shift */
        const int32_t k = (62 - kf_bitlen64(n)) & ~1;
        n <<= k;
        s += k;
    }
    r = kf_isqrt_floor(n, &rem);        /* r in [2^30, 2^31) */
    {   /* 2^61 / r rounded, in (2^30, 2^31]: (2^61 + r/2) / r, whose high word 2^29 is below r */
        uint32_t unused;
        m = kf_udiv64_32(((uint64_t)1 << 61) + (r >> 1), (uint32_t)r, &unused);
    }
    out.e = 61 - (fy + s) / 2;
    if (m >= ((uint64_t)1 << 31)) {
        m >>= 1;
        out.e -= 1;
    }
    out.m = (int32_t)m;
    return out;
}

/* 1 / sqrt(y * 2^-fy) for an int32 y (see kf_rsqrt_dyn64). */
static inline kf_dyn kf_rsqrt_dyn(int32_t y, int32_t fy)
{
    return kf_rsqrt_dyn64((int64_t)y, fy);
}

/* 1 / sqrt(max(a^2 + b^2 + c^2 + d^2, eps)) for components in one format f (value = raw * 2^-f);
 * 1/sqrt(eps) is passed as the dyn constant (eps_m, eps_e).  The components are first scaled so
 * the largest has 30 significant bits (block scaling): a vector of any length keeps full
 * relative precision. */
static inline kf_dyn kf_rnorm_dyn(int32_t a, int32_t b, int32_t c, int32_t d, int32_t f,
                                  int32_t eps_m, int32_t eps_e)
{
    kf_dyn r, eps;
    /* |raw| <= 2^31 - 1: magnitudes fit uint32 (values as the int64 form computed them) */
    uint32_t x0 = (a < 0) ? 0u - (uint32_t)a : (uint32_t)a;
    uint32_t x1 = (b < 0) ? 0u - (uint32_t)b : (uint32_t)b;
    uint32_t x2 = (c < 0) ? 0u - (uint32_t)c : (uint32_t)c;
    uint32_t x3 = (d < 0) ? 0u - (uint32_t)d : (uint32_t)d;
    uint32_t big;
    int32_t s = 0;
    eps.m = eps_m;
    eps.e = eps_e;
    big = (x0 > x1) ? x0 : x1;
    big = (big > x2) ? big : x2;
    big = (big > x3) ? big : x3;
    if (big == 0u) {
        return eps;
    }
    if (big >= ((uint32_t)1 << 30)) {   /* halve (rounded) so four squares fit below 2^62 */
        x0 = (x0 + 1u) >> 1;
        x1 = (x1 + 1u) >> 1;
        x2 = (x2 + 1u) >> 1;
        x3 = (x3 + 1u) >> 1;
        s = -1;
    } else {                           /* shift so the largest is in [2^29, 2^30) */
        s = 30 - kf_bitlen32(big);
        x0 <<= s;
        x1 <<= s;
        x2 <<= s;
        x3 <<= s;
    }
    /* each x <= 2^30 here */
    r = kf_rsqrt_dyn64((int64_t)(kf_umull(x0, x0) + kf_umull(x1, x1) + kf_umull(x2, x2)
                                 + kf_umull(x3, x3)), 2 * (f + s));
    /* max(n2, eps) in the denominator is min(r, 1/sqrt(eps)): compare m * 2^-e values */
    if ((r.e < eps.e) || ((r.e == eps.e) && (r.m > eps.m))) {
        return eps;
    }
    return r;
}

/* r * c * 2^-fc for c >= 0 as a dyn value, the mantissa rounded to nearest (ties up) back into
 * [2^30, 2^31); c <= 0 gives the value 0 (m = 0, which kf_mul_dyn turns into 0). */
static inline kf_dyn kf_dyn_scale(kf_dyn r, int32_t c, int32_t fc)
{
    kf_dyn out;
    uint64_t p, m;
    int32_t sh;
    if ((c <= 0) || (r.m <= 0)) {
        out.m = 0;
        out.e = 0;
        return out;
    }
    p = kf_umull((uint32_t)r.m, (uint32_t)c);     /* below 2^62 */
    sh = kf_bitlen32((uint32_t)(p >> 31));   /* p >> 31 < 2^31 */
    if (sh > 0) {
        m = (p + ((uint64_t)1 << (sh - 1))) >> sh;
        if (m >= ((uint64_t)1 << 31)) {    /* rounded up to 2^31 */
            m >>= 1;
            sh++;
        }
    } else {
        m = p;
        while (m < ((uint64_t)1 << 30)) {
            m <<= 1;
            sh--;
        }
    }
    out.m = (int32_t)m;
    out.e = r.e + fc - sh;
    return out;
}

/* a * r rescaled: raw result = a * r.m * 2^-(kbase + r.e), rounded, clamped to [lo, hi]. */
static inline int32_t kf_mul_dyn(int32_t a, kf_dyn r, int32_t kbase, int32_t lo, int32_t hi)
{
    int64_t p = kf_smull(a, r.m);
    int32_t k = kbase + r.e;
    if (k >= 63) {
        return kf_sat(0, lo, hi);     /* |p| < 2^62: the exact result rounds to 0 */
    }
    if (k > 0) {
        return kf_sat((p + ((int64_t)1 << (k - 1))) >> k, lo, hi);
    }
    return kf_lsh_sat(p, -k, lo, hi);
}

/* Saturating counter step. */
static inline int32_t kf_inc_if(int32_t c, int cond)
{
    return (cond && (c < INT32_MAX)) ? (c + 1) : c;
}

/* A binary32 value to raw with f fractional bits, rounded half away from zero and clamped to
 * [lo, hi] (NaN gives lo).  Pure integer code: no floating-point unit or library needed. */
static inline int32_t kf_q_from_f32(float x, int32_t f, int32_t lo, int32_t hi)
{
    union { float f; uint32_t u; } b;
    uint32_t mant;
    int32_t exp2, sh;
    uint64_t mag;
    int neg;
    b.f = x;
    neg = (int)(b.u >> 31);
    exp2 = (int32_t)((b.u >> 23) & 0xFFu);
    mant = b.u & 0x7FFFFFu;
    if (exp2 == 0xFF) {
        return (mant != 0u) ? lo : (neg ? lo : hi);   /* NaN, -inf, +inf */
    }
    if (exp2 == 0) {
        exp2 = 1;                      /* subnormal */
    } else {
        mant |= 0x800000u;
    }
    /* |x| = mant * 2^(exp2 - 150); raw = |x| * 2^f = mant * 2^(exp2 - 150 + f) */
    sh = exp2 - 150 + f;
    if (sh >= 39) {
        mag = (uint64_t)1 << 62;       /* far beyond any int32 raw: saturates below */
    } else if (sh >= 0) {
        mag = (uint64_t)mant << sh;
    } else if (sh > -26) {
        mag = (((uint64_t)mant) + ((uint64_t)1 << (-sh - 1))) >> (-sh);
    } else {
        mag = 0u;
    }
    return kf_sat(neg ? -(int64_t)mag : (int64_t)mag, lo, hi);
}

#endif /* KF_FIXED_H */
