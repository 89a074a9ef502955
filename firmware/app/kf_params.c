/*
 * kf_params.c - the parameter table (application rows here, generated rows included).
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "kf_params.h"

#define KF_U(v) {.u = (uint32_t)(v)}
#define KF_F(v) {.f = (v)}
#define KF_APP_ROW(name, type, def, lo, hi, flags) \
    {name, type, KF_PG_APP, 0u, 0u, flags, KF_U(def), KF_U(lo), KF_U(hi)}
#define KF_PARAM_ROW(name, group, filter, index, def, lo, hi) \
    {name, KF_PT_REAL32, group, filter, index, 0u, KF_F(def), KF_F(lo), KF_F(hi)},
#define KF_CHOICE_ROW(name, group, filter, index, def, lo, hi) \
    {name, KF_PT_REAL32, group, filter, index, KF_PF_CHOICE, KF_F(def), KF_F(lo), KF_F(hi)},

const kf_param_desc kf_param_table[KF_PARAM_COUNT] = {
    KF_APP_ROW("KF_UNIT_ID", KF_PT_UINT8, 1u, 1u, 254u, 0u),
    KF_APP_ROW("KF_RATE_HZ", KF_PT_UINT16, 1000u, 1u, 2000u, 0u),
    KF_APP_ROW("KF_ORI_RATE_HZ", KF_PT_UINT16, 100u, 0u, 1000u, 0u),
    KF_APP_ROW("KF_HRIMU_RATE", KF_PT_UINT16, 10u, 0u, 1000u, 0u),
    KF_APP_ROW("KF_ATTQ_RATE", KF_PT_UINT16, 10u, 0u, 1000u, 0u),
    KF_APP_ROW("KF_FILTER", KF_PT_UINT8, 5u, 0u, 255u, 0u),
    KF_APP_ROW("KF_MAG_ENABLE", KF_PT_UINT8, 1u, 0u, 1u, 0u),
    KF_APP_ROW("KF_STREAM_BOOT", KF_PT_UINT8, 1u, 0u, 1u, 0u),
    KF_APP_ROW("KF_HIL_MODE", KF_PT_UINT8, 0u, 0u, 3u, 0u),
    KF_APP_ROW("KF_SERIAL_NO", KF_PT_UINT32, 0x4B460001u, 0u, 0xFFFFFFFFu, 0u),
    KF_APP_ROW("KF_SIGNING", KF_PT_UINT8, 0u, 0u, 1u, KF_PF_READONLY),
    KF_APP_ROW("KF_JOINT_ID", KF_PT_UINT8, 0u, 0u, 14u, 0u),
    KF_APP_ROW("KF_EFF_RATE_HZ", KF_PT_UINT16, 0u, 0u, 1000u, 0u),
    KF_APP_ROW("KF_BATT_LOW_MV", KF_PT_UINT16, 3400u, 0u, 5000u, 0u),
#include "kf_params_gen.inc"
};

int32_t kf_param_find(const char *name)
{
    char key[17];
    memcpy(key, name, 16);
    key[16] = '\0';
    for (int32_t i = 0; i < (int32_t)KF_PARAM_COUNT; i++) {
        if (strncmp(kf_param_table[i].name, key, 16) == 0) {
            return i;
        }
    }
    return -1;
}

int kf_param_in_range(const kf_param_desc *d, kf_pvalue v)
{
    if (d->type == KF_PT_REAL32) {
        if (!(v.f >= d->lo.f && v.f <= d->hi.f)) {
            return 0;                              /* also NaN */
        }
        /* a choice (a switch such as KF_FL_MODE, 0 = 6D / 1 = 9D): only the whole numbers
         * lo..hi, never a value the filter would read one way or the other arbitrarily */
        return (d->flags & KF_PF_CHOICE) == 0u || v.f == (float)(int32_t)v.f;
    }
    if (d->type == KF_PT_UINT8 && v.u > 0xFFu) {
        return 0;
    }
    if (d->type == KF_PT_UINT16 && v.u > 0xFFFFu) {
        return 0;
    }
    if (v.u < d->lo.u || v.u > d->hi.u) {
        return 0;
    }
    if (d == &kf_param_table[KF_P_FILTER]) {
        return v.u == 0u || kf_filter_index(v.u) >= 0;   /* none or a wired filter */
    }
    if (d == &kf_param_table[KF_P_EFF_RATE_HZ]) {
        return v.u == 0u || KF_HAVE_LEG;                   /* the leg EKF is in this build */
    }
    if (d == &kf_param_table[KF_P_HIL_MODE]) {
        /* the raw Q quaternion exists in fixed-point builds only: elsewhere the bit would do nothing */
        return (v.u & KF_HIL_MODE_Q_RAW) == 0u || KF_NUMERIC_Q;
    }
    return 1;
}

int32_t kf_filter_index(uint32_t id)
{
    for (int32_t k = 0; k < (int32_t)KF_GEN_FILTER_COUNT; k++) {
        if (kf_gen_filters[k].id == id && id != 0u && kf_gen_filters[k].update != NULL) {
            return k;
        }
    }
    return -1;
}
