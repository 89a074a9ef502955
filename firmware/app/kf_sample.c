/*
 * kf_sample.c - one sample through the pipeline: time step, calibration (generated
 * calib_apply) or the direct HIL conversion, the selected filter, then the messages that are
 * due for it (KF_RAW_SAMPLE, KF_ORIENTATION, HIGHRES_IMU, ATTITUDE_QUATERNION, and in
 * two-sensor mode KF_JOINT_ANGLE).
 *
 * Two-sensor mode (KF_JOINT_ID != 0): sensor 1 (distal) runs through its own calibration map
 * (KF_ACC2/GYR2/MAG2_*: the same generated calib_apply with sensor 1's parameters) and its own
 * instance of the selected filter (kf_app_sample2); whenever KF_ORIENTATION of
 * sensor 0 (proximal) goes out, the generated joint step combines the two filters' latest
 * outputs and KF_JOINT_ANGLE goes out with sensor 0's time and sample counter.  With the leg
 * EKF on (KF_EFF_RATE_HZ != 0, float32 builds; kf_leg.c) every sample of sensor 0 steps it with
 * both sensors' calibrated samples, and KF_EFFORTS goes out at KF_EFF_RATE_HZ (in HIL after
 * every sample), after KF_JOINT_ANGLE when both are due.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "kf_app_internal.h"

#define KF_DT_US_MAX 1000000u

#if KF_NUMERIC_Q
/* raw Q value -> float: one rounding (int -> float), then an exact power-of-two scaling */
static float q_to_f(int32_t raw, int frac)
{
    return (float)raw * (1.0f / (float)(1ul << frac));
}
#endif

/* the filter input record as float32 SI values (f32 builds: the values themselves) */
static void input_to_float(const kf_imu_input *in, float gyr[3], float acc[3], float mag[3])
{
    for (int i = 0; i < 3; i++) {
#if KF_NUMERIC_Q
        gyr[i] = q_to_f(in->gyr[i], KF_GEN_FRAC_GYR);
        acc[i] = q_to_f(in->acc[i], KF_GEN_FRAC_ACC);
        mag[i] = q_to_f(in->mag[i], KF_GEN_FRAC_MAG);
#else
        gyr[i] = in->gyr[i];
        acc[i] = in->acc[i];
        mag[i] = in->mag[i];
#endif
    }
}

static uint32_t time_step_us(const kf_app *app, uint64_t t, uint64_t *t_prev, uint8_t *have_prev)
{
    uint32_t dt;
    if (!*have_prev) {
        uint32_t rate = app->values[KF_P_RATE_HZ].u;   /* first sample: the nominal period */
        dt = (1000000u + rate / 2u) / rate;
    } else if (t <= *t_prev) {
        dt = 0u;                                       /* the filter rejects a zero step */
    } else {
        uint64_t d = t - *t_prev;
        dt = d > KF_DT_US_MAX ? KF_DT_US_MAX : (uint32_t)d;
    }
    *t_prev = t;
    *have_prev = 1u;
    return dt;
}

/* counts + the sensor's calibration map, or the direct HIL values, -> the filter input record */
static void filter_input(const kf_app *app, kf_calib_state *calib, const kf_sample *s, uint32_t dt_us,
                         kf_imu_input *in)
{
    if (s->direct) {
        float dt = (float)dt_us * 1e-6f;   /* the same single rounding as calib_apply's dt */
        kf_gen_imu_from_f32(s->f_gyr, s->f_acc, s->f_mag, dt, in);
    } else {
        kf_gen_calib_apply(calib, s->acc, s->gyr_cal, s->mag, dt_us, in);   /* int16 counts */
    }
    in->mag_valid = (uint8_t)(s->mag_valid != 0u && app->values[KF_P_MAG_ENABLE].u != 0u);
}

/* the sample's clipping flags as they apply to the filter input: in HIL mode 0 a gyro_shift
 * above 0 means the calibration map's int16 gyro input (1 mrad/s counts) saturated, so the leg
 * EKF must not use that gyro (as before the shift existed); HIL direct mode takes the float32
 * values themselves and the sensor path always has shift 0 */
static uint8_t input_flags(const kf_sample *s)
{
    return (uint8_t)(s->flags | ((s->gyro_shift != 0u && !s->direct) ? KF_RAW_SAMPLE_FLAGS_GYRO_CLIPPED : 0u));
}

static void output_quat(const kf_app *app, float q[4])
{
    if (app->tared) {
        kf_quat_mul(app->tare, app->out.q, q);
    } else {
        memcpy(q, app->out.q, sizeof app->out.q);
    }
}

static void send_raw(kf_app *app, const kf_sample *s, uint32_t counter, uint8_t mag_valid)
{
    mavlink_message_t msg;
    uint8_t flags = (uint8_t)(s->flags | (mag_valid ? KF_RAW_SAMPLE_FLAGS_MAG_UPDATED : 0u));
    mavlink_msg_kf_raw_sample_pack_status(
        kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg, s->time_us, counter,
        s->acc[0], s->acc[1], s->acc[2], s->gyr[0], s->gyr[1], s->gyr[2], s->mag[0], s->mag[1],
        s->mag[2], s->temperature, kf_sysid(app), flags, s->gyro_shift);
    if (kf_send(app, &msg)) {
        app->rates.raw++;
    }
}

/* the attitude error covariance in the (tared) earth frame: C' = Rz C Rz^T for the tare's
 * rotation about z; all zero (= not provided, no bytes on the wire) without one */
static void output_cov(const kf_app *app, float cov[6])
{
    const float *c = app->out.cov;
    if (!app->out.has_cov) {
        memset(cov, 0, 6 * sizeof cov[0]);
        return;
    }
    if (!app->tared) {
        memcpy(cov, c, 6 * sizeof cov[0]);
        return;
    }
    float w = app->tare[0], z = app->tare[3];
    float co = w * w - z * z;            /* cos and sin of the tare angle */
    float si = 2.0f * w * z;
    float xx = c[0], xy = c[1], xz = c[2], yy = c[3], yz = c[4], zz = c[5];
    cov[0] = co * co * xx - 2.0f * co * si * xy + si * si * yy;
    cov[1] = co * si * (xx - yy) + (co * co - si * si) * xy;
    cov[2] = co * xz - si * yz;
    cov[3] = si * si * xx + 2.0f * co * si * xy + co * co * yy;
    cov[4] = si * xz + co * yz;
    cov[5] = zz;
}

/* 1 when the active filter runs 6D: its `mode` switch at 0 ignores the magnetometer, so
 * KF_ORIENTATION must not say MAG_USED */
static int filter_6d(const kf_app *app)
{
    return app->mode_param >= 0 && app->values[app->mode_param].f < 0.5f;
}

static void send_orientation(kf_app *app, uint64_t t, uint32_t counter)
{
    mavlink_message_t msg;
    float q[4];
    float cov[6];
    uint16_t st = 0u;
    output_quat(app, q);
    output_cov(app, cov);
    st |= app->initialised ? KF_ORIENTATION_STATUS_INITIALISED : 0u;
    st |= app->out.rest ? KF_ORIENTATION_STATUS_AT_REST : 0u;
    st |= app->out.mag_disturbed ? KF_ORIENTATION_STATUS_MAG_DISTURBED : 0u;
    st |= (app->mag_seen && !app->out.mag_disturbed && !filter_6d(app)) ? KF_ORIENTATION_STATUS_MAG_USED : 0u;
    st |= app->tared ? KF_ORIENTATION_STATUS_HEADING_TARED : 0u;
    st |= app->clipped ? KF_ORIENTATION_STATUS_INPUT_CLIPPED : 0u;
    st |= app->numeric_reset ? KF_ORIENTATION_STATUS_NUMERIC_RESET : 0u;
    mavlink_msg_kf_orientation_pack_status(
        kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg, t, counter, q[0], q[1], q[2], q[3],
        app->cnt.rejected_base + (uint32_t)app->out.rejected, st, KF_EARTH_FRAME_ENU,
        kf_gen_filters[app->filter].id, kf_sysid(app), cov);
    if (kf_send(app, &msg)) {
        app->rates.ori++;
        app->clipped = 0u;
        app->numeric_reset = 0u;
        app->mag_seen = 0u;
    }
}

#if KF_NUMERIC_Q
/* HIL with KF_HIL_MODE bit 1 (q builds): the filter's raw Q-format quaternion, all 32 bits of
 * each component (KF_ORIENTATION's float32 keeps 24), right after KF_ORIENTATION, as MEMORY_VECT:
 * address = low 16 bits of sample_counter, ver = KF_QRAW_VER, type = KF_QRAW_TYPE_Q, value =
 * q_raw[0..3] (w, x, y, z) as little-endian int32; the filter's output, before any tare. */
static void send_q_raw(kf_app *app, uint32_t counter)
{
    mavlink_message_t msg;
    int8_t v[32];
    memset(v, 0, sizeof v);
    for (int i = 0; i < 4; i++) {
        uint32_t u = (uint32_t)app->out.q_raw[i];
        for (int b = 0; b < 4; b++) {
            v[4 * i + b] = (int8_t)(uint8_t)(u >> (8 * b));
        }
    }
    mavlink_msg_memory_vect_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                        (uint16_t)(counter & 0xFFFFu), KF_QRAW_VER, KF_QRAW_TYPE_Q, v);
    (void)kf_send(app, &msg);
}
#endif

static void send_highres(kf_app *app, const kf_sample *s, uint8_t mag_valid)
{
    mavlink_message_t msg;
    float g[3], a[3], m[3];
    input_to_float(&app->last_in, g, a, m);
    uint16_t upd = 0x3Fu | (mag_valid ? 0x1C0u : 0u)
                   | ((s->flags & KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID) ? 0x1000u : 0u);
    /* HIGHRES_IMU: calibrated values, magnetometer in gauss (1 gauss = 100 uT) */
    mavlink_msg_highres_imu_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                        s->time_us, a[0], a[1], a[2], g[0], g[1], g[2],
                                        m[0] * 0.01f, m[1] * 0.01f, m[2] * 0.01f, 0.0f, 0.0f, 0.0f,
                                        (float)s->temperature * 0.01f, upd, 0u);
    (void)kf_send(app, &msg);
}

static void send_attitude_quaternion(kf_app *app, uint64_t t)
{
    static const float no_offset[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    mavlink_message_t msg;
    float q[4], ned[4], g[3], a[3], m[3];
    output_quat(app, q);
    kf_quat_enu_to_ned(q, ned);    /* MAVLink's earth frame is NED; body = the sensor frame */
    input_to_float(&app->last_in, g, a, m);
    mavlink_msg_attitude_quaternion_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status,
                                                &msg, (uint32_t)(t / 1000u), ned[0], ned[1], ned[2],
                                                ned[3], g[0], g[1], g[2], no_offset);
    (void)kf_send(app, &msg);
}

/* KF_ANGLE_SEQUENCE of the joint step's `sequence` parameter (0 X-Z'-Y'', 1 X-Y'-Z'', 2 Z-Y'-X'') */
static uint8_t joint_sequence(const kf_app *app)
{
    float v = app->values[KF_P_JOINT_FIRST + KF_GEN_JOINT_P_SEQUENCE].f;
    if (v < 0.5f) {
        return KF_ANGLE_SEQUENCE_XZY;
    }
    return v < 1.5f ? KF_ANGLE_SEQUENCE_XYZ : KF_ANGLE_SEQUENCE_ZYX;
}

#define KF_NEAR_LOCK_RAD 1.3962634f   /* 80 deg: |angle_2| within 10 deg of the singularity */

static void send_joint_angle(kf_app *app, uint64_t t, uint32_t counter)
{
    mavlink_message_t msg;
    uint8_t st = 0u;
    const float *a = app->jout.angles;
    kf_gen_joint_update(&app->joint, &app->out, &app->out2, &app->jout);
    st |= (app->initialised && app->initialised2 && app->jout.valid) ? KF_JOINT_ANGLE_STATUS_VALID : 0u;
    st |= (a[1] > KF_NEAR_LOCK_RAD || a[1] < -KF_NEAR_LOCK_RAD) ? KF_JOINT_ANGLE_STATUS_NEAR_SINGULARITY : 0u;
    st |= (app->values[KF_P_MAG_ENABLE].u == 0u || filter_6d(app) || app->out.mag_disturbed
           || app->out2.mag_disturbed)
              ? KF_JOINT_ANGLE_STATUS_HEADING_UNRELIABLE : 0u;
    st |= app->joint_reset ? KF_JOINT_ANGLE_STATUS_NUMERIC_RESET : 0u;
    mavlink_msg_kf_joint_angle_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg, t,
                                           counter, a[0], a[1], a[2],
                                           (uint8_t)app->values[KF_P_JOINT_ID].u, joint_sequence(app),
                                           st, kf_sysid(app), kf_sysid(app));
    if (kf_send(app, &msg)) {
        app->joint_reset = 0u;            /* told once; a dropped frame keeps it for the next */
    }
}

void kf_app_sample2(kf_app *app, const kf_sample *s)
{
    kf_imu_input in;
    if (!app->two_sensors) {
        return;
    }
    uint32_t dt_us = time_step_us(app, s->time_us, &app->t_prev2, &app->have_prev2);
    filter_input(app, &app->calib2, s, dt_us, &in);   /* sensor 1's own map */
    if (app->leg_on) {
        kf_leg_sample2(app, &in, input_flags(s));
    }
    if (app->filter < 0) {
        return;
    }
    int32_t before = app->out2.rejected;
    kf_gen_filters[app->filter].update(&app->filt2, &in, &app->out2);
    if (!isfinite(app->out2.q[0]) || !isfinite(app->out2.q[1]) || !isfinite(app->out2.q[2])
        || !isfinite(app->out2.q[3])) {
        kf_config_reset_filter2(app);
        app->joint_reset = 1u;            /* sensor 1 has no KF_ORIENTATION: not sensor 0's flag */
        app->cnt.numeric_resets++;
    } else if (app->out2.rejected == before) {
        app->initialised2 = 1u;
    }
}

static int due(uint16_t div, uint16_t *cnt)
{
    if (div == 0u) {
        return 0;
    }
    if (++*cnt >= div) {
        *cnt = 0u;
        return 1;
    }
    return 0;
}

static int quat_finite(const float q[4])
{
    return isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]) && isfinite(q[3]);
}

void kf_app_sample(kf_app *app, const kf_sample *s)
{
    uint32_t counter = app->sample_counter++;
    uint32_t dt_us = time_step_us(app, s->time_us, &app->t_prev, &app->have_prev);
    uint8_t mag_valid = (uint8_t)(s->mag_valid != 0u);
    uint8_t hil = (uint8_t)((s->flags & KF_RAW_SAMPLE_FLAGS_SIMULATED) != 0u);
    kf_imu_input in;

    app->cnt.samples++;
    app->rates.samples++;
    filter_input(app, &app->calib, s, dt_us, &in);
    app->last_in = in;
    app->mag_seen |= in.mag_valid;
    app->mag_present |= mag_valid;            /* a reading arrived, whether KF_MAG_ENABLE uses it or not */
    if ((input_flags(s) & (KF_RAW_SAMPLE_FLAGS_ACC_CLIPPED | KF_RAW_SAMPLE_FLAGS_GYRO_CLIPPED
                           | KF_RAW_SAMPLE_FLAGS_MAG_CLIPPED)) != 0u) {
        app->clipped = 1u;
    }
    if (app->filter >= 0) {
        int32_t before = app->out.rejected;
        kf_gen_filters[app->filter].update(&app->filt, &in, &app->out);
        if (!quat_finite(app->out.q)) {
            kf_config_reset_filter(app);      /* never stream NaN: start again from the next sample */
            app->numeric_reset = 1u;
            app->joint_reset = 1u;            /* the joint angle uses this filter too */
            app->cnt.numeric_resets++;
        } else if (app->out.rejected == before) {
            app->initialised = 1u;
        }
    }
    if (app->leg_on) {
        kf_leg_step(app, &in, input_flags(s));
    }

    if (app->streaming || hil) {
        send_raw(app, s, counter, mag_valid);
    }
    if (app->filter >= 0 && (hil || (app->streaming && due(app->div_ori, &app->cnt_ori)))) {
        send_orientation(app, s->time_us, counter);
#if KF_NUMERIC_Q
        if (hil && (app->values[KF_P_HIL_MODE].u & KF_HIL_MODE_Q_RAW) != 0u) {
            send_q_raw(app, counter);
        }
#endif
        if (app->two_sensors) {
            send_joint_angle(app, s->time_us, counter);   /* at the orientation rate */
        }
    }
    /* the KF_EFFORTS decimation runs like KF_ORIENTATION's, also while the leg EKF is off or
     * restarts, so that at the same rate both go out with the same samples */
    int eff_due = !hil && app->streaming && due(app->div_eff, &app->cnt_eff);
    if (app->leg_on && (hil || eff_due)) {
        kf_leg_send(app, s->time_us, counter);
    }
    if (app->streaming && due(app->div_hr, &app->cnt_hr)) {
        send_highres(app, s, mag_valid);
    }
    if (app->streaming && app->filter >= 0 && due(app->div_aq, &app->cnt_aq)) {
        send_attitude_quaternion(app, s->time_us);
    }
}
