/*
 * kf_filters.h - the application's view of the generated filters and calibration map.
 *
 * Every wired filter (kf_filter_list.h) is reached through one kf_filter_ops row generated in
 * kf_filters_gen.c.  The build's number system (KF_NUMERIC_Q = 0: float32 C, 1: fixed-point
 * C) selects which generated code those rows call; the interface here is the same for both.
 * Parameter values enter as float32 (what MAVLink carries); the q build converts them with
 * kf_q_from_f32, and the generated <filter>_init checks their ranges.
 */
#ifndef KF_FILTERS_H
#define KF_FILTERS_H

#include <stdint.h>

#ifndef KF_NUMERIC_Q
#define KF_NUMERIC_Q 0
#endif

#include "kf_filters_gen.h"

/* What the application needs from one filter update. */
typedef struct {
    float q[4];          /* orientation sensor -> ENU (w, x, y, z); q builds: raw * 2^-frac */
    int32_t q_raw[4];    /* q builds: the filter's raw Q-format quaternion (0 in f32 builds) */
    int32_t rejected;    /* the filter's running count of rejected samples (since its init) */
    uint8_t rest;        /* 1 while the filter reports rest (0 if it has no such output) */
    uint8_t mag_disturbed;  /* 1 while it rejects the magnetometer (0 if no such output) */
    uint8_t has_cov;     /* 1 when the filter outputs cov (else cov is not written) */
    float cov[6];        /* attitude error covariance, rad^2, earth frame: xx xy xz yy yz zz */
} kf_filter_out;

typedef struct {
    const char *name;         /* registry name, e.g. "madgwick" */
    uint8_t id;               /* KF_FILTER value */
    uint16_t first_param;     /* index of its first value in the filter parameter vector */
    uint16_t param_count;
    /* fill a <filter>_params struct from float32 values v[0..param_count) */
    void (*build)(const float *v, void *params);
    /* generated init: reset the state; 0, or -(i+1) when parameter i is out of range */
    int (*init)(void *state, const void *params);
    /* replace the parameters of a running filter (no reset) */
    void (*set)(void *state, const void *params);
    void (*update)(void *state, const kf_imu_input *in, kf_filter_out *out);
} kf_filter_ops;

extern const kf_filter_ops kf_gen_filters[KF_GEN_FILTER_COUNT];

/* Calibration map (calib_apply): set parameters from float32 values in parameter-table order;
 * 0, or -(i+1) when value i is out of its range (the defaults are then in use). */
int kf_gen_calib_init(kf_calib_state *s, const float *v);

/* counts (+ microseconds since the previous sample) -> the filters' input record */
void kf_gen_calib_apply(kf_calib_state *s, const int16_t acc[3], const int16_t gyr[3],
                        const int16_t mag[3], uint32_t dt_us, kf_imu_input *out);

/* SI float32 values (gyr rad/s, acc m/s^2, mag uT, dt s) -> the input record, without
 * calibration (HIL direct mode). */
void kf_gen_imu_from_f32(const float gyr[3], const float acc[3], const float mag[3], float dt,
                         kf_imu_input *out);

/* Two-sensor mode: the generated joint-angle step (joint_angle_f32 / joint_angle_q). */
typedef struct {
    float angles[3];     /* rad: intrinsic angles of the sequence (q builds: raw * 2^-frac) */
    float q[4];          /* joint quaternion (distal segment in the proximal segment frame) */
    uint8_t valid;       /* 1 once a sample gave angles */
    int32_t rejected;    /* the step's running count of rejected samples */
} kf_joint_out;

/* Joint-angle parameters from float32 values in parameter-table order (KF_JA_*); 0, or
 * -(i+1) when value i is out of its range (the defaults are then in use). */
int kf_gen_joint_init(kf_joint_state *s, const float *v);

/* One joint step from the two filters' outputs (proximal = sensor 0, distal = sensor 1):
 * f32 builds pass the float32 quaternions, q builds the raw outputs requantised to the step's
 * input format (KF_GEN_FRAC_QOUT -> KF_GEN_FRAC_JOINT_Q, round half up). */
void kf_gen_joint_update(kf_joint_state *s, const kf_filter_out *prox, const kf_filter_out *dist,
                         kf_joint_out *out);

#if KF_HAVE_LEG
/* Two-sensor mode: the generated leg EKF (leg_f32; float32 builds only).  Parameters from
 * float32 values in parameter-table order (KF_LEG_*); 0, or -(i+1) when value i is out of its
 * range (the defaults are then in use). */
int kf_gen_leg_init(kf_leg_state *s, const float *v);
#endif

#endif /* KF_FILTERS_H */
