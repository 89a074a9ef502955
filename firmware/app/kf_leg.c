/*
 * kf_leg.c - the wearable leg EKF on a two-sensor unit (float32 builds): hip and knee torques
 * of a planar thigh-shank model (generated leg_f32, codegen/estimators/dynamics/leg.py) from
 * both sensors' calibrated gyroscope and accelerometer samples, sent as KF_EFFORTS.
 *
 * On when KF_JOINT_ID != 0 (sensor 0 on the thigh, sensor 1 on the shank) and KF_EFF_RATE_HZ
 * != 0; one EKF step per sample of sensor 0, with sensor 1's sample received since the
 * previous step (none: sensor 1 counts as lost in that step).  The model's inputs are in the
 * segment frames of the joint-angle step (X medio-lateral to the subject's left, Y proximal, Z
 * anterior; sensor-to-segment offsets q_SB = KF_JA_PROX_* / KF_JA_DIST_*, v_sensor =
 * R(q_SB) v_segment): the rate about the subject's right (-X: + hip flexion), the specific
 * force along the segment towards distal (-Y) and anterior (+Z).  Each input is one float32
 * dot product of a row of R(q_SB)^T with the calibrated sensor vector, ((a0*v0 + a1*v1) +
 * a2*v2), the rows computed in float32 from the normalised offsets whenever they change
 * (kinefuse.firmware.hostunit.leg_model repeats every operation).  A sample with the sensor's
 * clipping flag is not used (that sensor lost for the step).  The fixed-point builds have no
 * leg EKF (it is generated in float32 only); there the functions below do nothing.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "kf_app_internal.h"

#if KF_HAVE_LEG

static void leg_vector(const kf_app *app, int32_t at, float v, float *vec)
{
    for (uint16_t i = 0; i < KF_GEN_LEG_PARAM_COUNT; i++) {
        vec[i] = app->values[KF_P_LEG_FIRST + i].f;
    }
    if (at >= 0) {
        vec[at] = v;
    }
}

/* rows (gyr, acc along, acc anterior) of sensor k from its offset quaternion w x y z */
static void axes_of(const float *q, float ax[3][3])
{
    float w = q[0], x = q[1], y = q[2], z = q[3];
    float n2 = ((w * w + x * x) + y * y) + z * z;
    if (!(n2 >= 1e-12f)) {
        w = 1.0f;          /* (nearly) all zero: identity */
        x = y = z = 0.0f;
    } else {
        float k = 1.0f / sqrtf(n2);
        w = w * k;
        x = x * k;
        y = y * k;
        z = z * k;
    }
    /* R(q_SB): segment -> sensor; v_segment = R^T v_sensor */
    float r00 = 1.0f - 2.0f * (y * y + z * z), r01 = 2.0f * (x * y - w * z), r02 = 2.0f * (x * z + w * y);
    float r10 = 2.0f * (x * y + w * z), r11 = 1.0f - 2.0f * (x * x + z * z), r12 = 2.0f * (y * z - w * x);
    float r20 = 2.0f * (x * z - w * y), r21 = 2.0f * (y * z + w * x), r22 = 1.0f - 2.0f * (x * x + y * y);
    ax[0][0] = -r00;       /* rate about the subject's right: -X */
    ax[0][1] = -r10;
    ax[0][2] = -r20;
    ax[1][0] = -r01;       /* along the segment towards distal: -Y */
    ax[1][1] = -r11;
    ax[1][2] = -r21;
    ax[2][0] = r02;        /* anterior: +Z */
    ax[2][1] = r12;
    ax[2][2] = r22;
}

static float dot3(const float a[3], const float v[3])
{
    return (a[0] * v[0] + a[1] * v[1]) + a[2] * v[2];
}

void kf_leg_axes(kf_app *app)
{
    float q[4];
    for (int k = 0; k < 2; k++) {
        for (int i = 0; i < 4; i++) {   /* KF_JA_PROX_W..Z, then KF_JA_DIST_W..Z */
            q[i] = app->values[KF_P_JOINT_FIRST + KF_GEN_JOINT_P_OFFSETS + 4 * k + i].f;
        }
        axes_of(q, app->leg_axes[k]);
    }
}

void kf_leg_reset(kf_app *app)
{
    float vec[KF_GEN_LEG_PARAM_COUNT];
    app->leg_on = (uint8_t)(app->two_sensors && app->values[KF_P_EFF_RATE_HZ].u != 0u);
    app->eff_status = 0u;
    app->fresh2 = 0u;
    memset(&app->lout, 0, sizeof app->lout);
    leg_vector(app, -1, 0.0f, vec);
    (void)kf_gen_leg_init(&app->leg, vec);   /* validated when the values were accepted */
    kf_leg_axes(app);
}

uint8_t kf_leg_set_param(kf_app *app, int32_t at, float v)
{
    float vec[KF_GEN_LEG_PARAM_COUNT];
    kf_leg_state tmp;
    leg_vector(app, at, v, vec);
    if (kf_gen_leg_init(&tmp, vec) != 0) {
        return MAV_PARAM_ERROR_VALUE_OUT_OF_RANGE;   /* the generated range check */
    }
    app->leg.params = tmp.params;                    /* live: the estimate goes on */
    return 0u;
}

void kf_leg_repair(kf_app *app)
{
    float vec[KF_GEN_LEG_PARAM_COUNT];
    for (int tries = 0; tries <= (int)KF_GEN_LEG_PARAM_COUNT; tries++) {
        leg_vector(app, -1, 0.0f, vec);
        int r = kf_gen_leg_init(&app->leg, vec);
        if (r >= 0 || -r - 1 >= (int)KF_GEN_LEG_PARAM_COUNT) {
            break;
        }
        uint32_t i = KF_P_LEG_FIRST + (uint32_t)(-r - 1);
        app->values[i] = kf_param_table[i].def;
        app->cnt.stored_rejects++;
    }
}

void kf_leg_sample2(kf_app *app, const kf_imu_input *in, uint8_t flags)
{
    app->last_in2 = *in;
    app->flags2 = flags;
    app->fresh2 = 1u;
}

void kf_leg_step(kf_app *app, const kf_imu_input *in0, uint8_t flags0)
{
    kf_leg_input li;
    const kf_imu_input *src[2] = {in0, &app->last_in2};
    uint8_t fl[2] = {flags0, app->flags2};
    uint8_t fresh[2] = {1u, app->fresh2};
    uint8_t missing = 0u;
    int32_t before = app->leg.rejected;
    memset(&li, 0, sizeof li);
    for (int k = 0; k < 2; k++) {
        uint8_t g_ok = (uint8_t)(fresh[k] && (fl[k] & KF_RAW_SAMPLE_FLAGS_GYRO_CLIPPED) == 0u);
        uint8_t a_ok = (uint8_t)(fresh[k] && (fl[k] & KF_RAW_SAMPLE_FLAGS_ACC_CLIPPED) == 0u);
        float g[3], a[3];
        for (int i = 0; i < 3; i++) {
            g[i] = (float)src[k]->gyr[i];
            a[i] = (float)src[k]->acc[i];
        }
        li.gyr[k] = g_ok ? dot3(app->leg_axes[k][0], g) : 0.0f;
        li.acc[2 * k] = a_ok ? dot3(app->leg_axes[k][1], a) : 0.0f;
        li.acc[2 * k + 1] = a_ok ? dot3(app->leg_axes[k][2], a) : 0.0f;
        li.gyr_valid[k] = g_ok;
        li.acc_valid[k] = a_ok;
        missing |= (uint8_t)(!g_ok || !a_ok);
    }
    li.foot_valid = 0u;            /* no ankle force sensor on a unit */
    li.dt = in0->dt;               /* sensor 0's time step (calib_apply: float32(dt_us) * 1e-6f) */
    leg_f32_update(&app->leg, &li, &app->lout);
    app->fresh2 = 0u;
    if (missing || app->lout.imu_lost || app->lout.rejected != before) {
        app->eff_status |= KF_EFFORTS_STATUS_SENSOR_MISSING;
    }
    app->eff_status |= app->lout.skipped_now ? KF_EFFORTS_STATUS_UPDATE_SKIPPED : 0u;
    app->eff_status |= app->lout.reset_now ? KF_EFFORTS_STATUS_RESET : 0u;
}

void kf_leg_send(kf_app *app, uint64_t t, uint32_t counter)
{
    mavlink_message_t msg;
    float e[12], sd[12];
    memset(e, 0, sizeof e);
    memset(sd, 0, sizeof sd);
    for (int i = 0; i < 2; i++) {
        e[i] = app->lout.te[i];
        sd[i] = app->lout.te_std[i];
    }
    uint8_t st = (uint8_t)(app->eff_status | (app->lout.initialised ? KF_EFFORTS_STATUS_VALID : 0u));
    mavlink_msg_kf_efforts_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg, t, counter,
                                       e, sd, KF_EFFORT_MODEL_PLANAR_LEG, 2u, st);
    if (kf_send(app, &msg)) {
        app->eff_status = 0u;
    }
}

#else /* no leg EKF in this build: KF_EFF_RATE_HZ stays 0 (kf_param_in_range) */

void kf_leg_axes(kf_app *app)
{
    (void)app;
}

void kf_leg_reset(kf_app *app)
{
    app->leg_on = 0u;
    app->eff_status = 0u;
}

uint8_t kf_leg_set_param(kf_app *app, int32_t at, float v)
{
    (void)app;
    (void)at;
    (void)v;
    return 0u;                     /* the table's range is all there is to check */
}

void kf_leg_repair(kf_app *app)
{
    (void)app;
}

void kf_leg_sample2(kf_app *app, const kf_imu_input *in, uint8_t flags)
{
    (void)app;
    (void)in;
    (void)flags;
}

void kf_leg_step(kf_app *app, const kf_imu_input *in0, uint8_t flags0)
{
    (void)app;
    (void)in0;
    (void)flags0;
}

void kf_leg_send(kf_app *app, uint64_t t, uint32_t counter)
{
    (void)app;
    (void)t;
    (void)counter;
}

#endif
