/*
 * kf_params.h - the unit's parameters: one table of descriptors (name <= 16 characters,
 * MAVLink type, default, range) for the application settings, the calibration and every
 * wired filter; values as 32-bit patterns (float bits for REAL32, integers bytewise).
 *
 * Order: application parameters (kf_app_param), calibration (KF_ACC_*, KF_GYR_*, KF_MAG_*,
 * generated), then each filter's parameters (KF_<tag>_*, generated) in kf_filter_list.h order,
 * then the joint-angle step's (KF_JA_*, generated; used in two-sensor mode, KF_JOINT_ID != 0),
 * then the leg EKF's (KF_LEG_*, generated; two-sensor mode with KF_EFF_RATE_HZ != 0, float32
 * builds only: in the others the rows exist, with their ranges, but nothing uses them), then
 * sensor 1's own calibration map (KF_ACC2_*, KF_GYR2_*, KF_MAG2_*, generated: the calibration
 * rows again, same order; used in two-sensor mode).  New groups go at the end: the indices of
 * the older rows stay (storage finds values by name hash, kf_store.h).
 */
#ifndef KF_PARAMS_H
#define KF_PARAMS_H

#include <stdint.h>

#include "kf_filters.h"

/* MAV_PARAM_TYPE values used (common.xml) */
#define KF_PT_UINT8  1u
#define KF_PT_UINT16 3u
#define KF_PT_UINT32 5u
#define KF_PT_REAL32 9u

/* parameter groups */
#define KF_PG_APP    0u
#define KF_PG_CALIB  1u
#define KF_PG_FILTER 2u
#define KF_PG_JOINT  3u   /* joint-angle step (two-sensor mode) */
#define KF_PG_LEG    4u   /* leg EKF (two-sensor mode, KF_EFFORTS) */
#define KF_PG_CALIB2 5u   /* sensor 1's calibration map (two-sensor mode) */

/* flags */
#define KF_PF_READONLY 1u
#define KF_PF_CHOICE   2u   /* REAL32 choice (Param.choices): only the whole numbers lo..hi */

typedef union {
    float f;
    int32_t i;
    uint32_t u;
} kf_pvalue;

typedef struct {
    const char *name;      /* NUL-terminated, at most 16 characters */
    uint8_t type;          /* KF_PT_* */
    uint8_t group;         /* KF_PG_* */
    uint8_t filter;        /* group FILTER: index in kf_gen_filters */
    uint8_t index;         /* index within the group's value vector */
    uint8_t flags;
    kf_pvalue def, lo, hi; /* integers: lo/hi inclusive (uint32); REAL32: float bounds */
} kf_param_desc;

/* Application parameters (indices into the table). */
enum {
    KF_P_UNIT_ID,          /* MAVLink system id and unit id, 1..254 */
    KF_P_RATE_HZ,          /* sensor sample rate = KF_RAW_SAMPLE rate, Hz */
    KF_P_ORI_RATE_HZ,      /* KF_ORIENTATION rate, Hz (0: off) */
    KF_P_HRIMU_RATE,       /* HIGHRES_IMU rate, Hz (0: off) */
    KF_P_ATTQ_RATE,        /* ATTITUDE_QUATERNION rate, Hz (0: off) */
    KF_P_FILTER,           /* KF_FILTER id of the running filter (0: none) */
    KF_P_MAG_ENABLE,       /* 0: never pass magnetometer readings to the filter (6D) */
    KF_P_STREAM_BOOT,      /* 1: stream from power-up (else wait for MAV_CMD_KF_STREAM) */
    KF_P_HIL_MODE,         /* HIL_SENSOR input, bits: KF_HIL_MODE_DIRECT (else counts +
                            * calibration), KF_HIL_MODE_Q_RAW (q builds: also the raw quaternion) */
    KF_P_SERIAL_NO,        /* unit serial number */
    KF_P_SIGNING,          /* read-only: 1 when a signing key is set */
    KF_P_JOINT_ID,         /* KF_JOINT of a two-sensor unit (0: one sensor, no KF_JOINT_ANGLE) */
    KF_P_EFF_RATE_HZ,      /* KF_EFFORTS rate, Hz; 0 (default): the leg EKF does not run.  Two-sensor
                            * mode only; values other than 0 are refused where it is not built */
    KF_P_BATT_LOW_MV,      /* battery warning threshold, mV: KF_UNIT_STATUS LOW_BATTERY while the
                            * 1 Hz reading is below it, cleared 100 mV above it (0: off; default:
                            * a single Li-ion/LiPo cell near empty under load) */
    KF_P_APP_COUNT
};

/* KF_HIL_MODE bits */
#define KF_HIL_MODE_DIRECT 1u   /* HIL_SENSOR values go to the filter as float32, no calibration */
#define KF_HIL_MODE_Q_RAW  2u   /* fixed-point builds: after each HIL KF_ORIENTATION, a MEMORY_VECT
                                 * with the filter's raw Q-format quaternion (kf_sample.c) */
/* that MEMORY_VECT: ver and type (address = low 16 bits of sample_counter) */
#define KF_QRAW_VER        0x4Bu  /* 'K': kinefuse's own layout, not common.xml's ver 1 types */
#define KF_QRAW_TYPE_Q     1u     /* value = int32[4] little-endian: q_raw w, x, y, z */

#define KF_P_CALIB_FIRST  KF_P_APP_COUNT
#define KF_P_FILTER_FIRST (KF_P_CALIB_FIRST + KF_GEN_CALIB_PARAM_COUNT)
#define KF_P_JOINT_FIRST  (KF_P_FILTER_FIRST + KF_GEN_FILTER_PARAM_COUNT)
#define KF_P_LEG_FIRST    (KF_P_JOINT_FIRST + KF_GEN_JOINT_PARAM_COUNT)
#define KF_P_CALIB2_FIRST (KF_P_LEG_FIRST + KF_GEN_LEG_PARAM_COUNT)
#define KF_PARAM_COUNT    (KF_P_CALIB2_FIRST + KF_GEN_CALIB2_PARAM_COUNT)

extern const kf_param_desc kf_param_table[KF_PARAM_COUNT];

/* Index of the parameter named `name` (a 16-byte MAVLink field, NUL-terminated or not), or -1. */
int32_t kf_param_find(const char *name);

/* 1 when v (a bit pattern of the parameter's type) is within the descriptor's range. */
int kf_param_in_range(const kf_param_desc *d, kf_pvalue v);

/* Index of the filter with KF_FILTER id `id` in kf_gen_filters, or -1 (0 = none, unknown, or
 * left out of this build). */
int32_t kf_filter_index(uint32_t id);

#endif /* KF_PARAMS_H */
