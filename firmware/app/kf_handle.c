/*
 * kf_handle.c - what the unit does with each received frame: signing policy, parameter
 * protocol, commands, time sync, HIL sensor input (HIL_SENSOR.id 0: the unit's sensor;
 * id 1: the second, distal sensor of a two-sensor unit), signing setup.  Anything else is counted
 * as an unknown message and otherwise ignored.
 *
 * Signing: with a key set (SETUP_SIGNING), a signed frame must verify (signature, and a
 * timestamp newer than the last one of its stream and than the floor stored before the last
 * reset, see reserve_timestamp), else it is dropped and counted.  Unsigned frames are then
 * accepted only for reading: HEARTBEAT, TIMESYNC, PARAM_REQUEST_LIST/READ.  PARAM_SET is
 * answered with PARAM_ERROR (permission denied) and the unchanged value, COMMAND_LONG with
 * MAV_RESULT_DENIED; HIL_SENSOR and SETUP_SIGNING are dropped; all are counted.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "kf_app_internal.h"

#define KF_SCALE_ACC 9.80665e-3   /* KF_RAW_SAMPLE units (kinefuse.xml) */
#define KF_SCALE_GYR 1e-3
#define KF_SCALE_MAG 0.1
#define KF_SCALE_TEMP 0.01
#define KF_UT_PER_GAUSS 100.0

static int for_me(const kf_app *app, uint8_t target_system, uint8_t target_component)
{
    return (target_system == 0u || target_system == kf_sysid(app))
           && (target_component == 0u || target_component == KF_COMPONENT_ID);
}

/* --- signing ---------------------------------------------------------------------------- */

static int stream_known(const kf_app *app, const mavlink_message_t *msg)
{
    for (uint16_t i = 0; i < app->sign_streams.num_signing_streams && i < MAVLINK_MAX_SIGNING_STREAMS; i++) {
        const struct __mavlink_signing_stream *s = &app->sign_streams.stream[i];
        if (s->sysid == msg->sysid && s->compid == msg->compid && s->link_id == msg->signature[0]) {
            return 1;
        }
    }
    return 0;
}

static uint64_t signature_timestamp(const mavlink_message_t *msg)
{
    uint64_t ts = 0u;
    for (int i = 5; i >= 0; i--) {
        ts = (ts << 8) | msg->signature[1 + i];
    }
    return ts;
}

static int signature_ok(kf_app *app, const mavlink_message_t *msg)
{
    if (!stream_known(app, msg) && signature_timestamp(msg) <= app->sign_floor) {
        return 0;   /* older than what was accepted before the last reset: a replay */
    }
    return mavlink_signature_check(&app->signing, &app->sign_streams, msg) ? 1 : 0;
}

/* MAVLink signing: the newest accepted timestamp must survive a restart, and the unit has no
 * clock of that epoch.  Storing every frame's would wear the flash at the sample rate, so the
 * stored copy holds a reservation (sign_reserved, the boot floor) at or above every timestamp
 * accepted: a verified frame beyond it first moves it KF_SIGN_RESERVE_TICKS ahead in storage,
 * then is handled.  A power cut at any moment therefore leaves a floor that refuses every frame
 * handled before it (a frame cut during its own save was not handled).  A host on the MAVLink
 * clock (10 us ticks of real time) causes one such save per 60 s of signed traffic; one whose
 * timestamps run faster is refused until KF_SIGN_SAVE_MIN_US has passed since the previous
 * save (at most 6 saves a minute whatever the host sends).  1: handle it, 0: drop it. */
#define KF_SIGN_RESERVE_TICKS 6000000u      /* 60 s of 10 us ticks */
#define KF_SIGN_SAVE_MIN_US 10000000u       /* 10 s of device time */

static int reserve_timestamp(kf_app *app, uint64_t ts)
{
    uint64_t now;
    if (ts <= app->sign_reserved) {
        return 1;
    }
    now = kf_app_time(app);
    if (app->sign_saved && now - app->sign_saved_us < KF_SIGN_SAVE_MIN_US) {
        return 0;
    }
    app->sign_saved = 1u;
    app->sign_saved_us = now;
    app->sign_reserved = app->signing.timestamp + KF_SIGN_RESERVE_TICKS;   /* >= ts */
    /* a HAL failure is counted (STORAGE_ERROR); the frame is still handled, as a parameter
     * write is when its save fails */
    (void)kf_config_save(app);
    return 1;
}

void kf_app_sign_shutdown(kf_app *app)
{
    /* a commanded restart: store the newest accepted timestamp itself rather than the
     * reservation, so that the host's next frames (its clock has not passed the reservation
     * yet) are not refused after the reboot; a power cut during it leaves the reservation */
    if (app->key_set && app->sign_reserved > app->signing.timestamp) {
        app->sign_reserved = app->signing.timestamp;
        (void)kf_config_save(app);
    }
}

void kf_app_set_key(kf_app *app, const uint8_t key[32], uint64_t timestamp)
{
    /* the streams are cleared below: keep the newest timestamp accepted so far as the floor,
     * or frames accepted since the last save could be replayed (same key set again) */
    if (app->signing.timestamp > app->sign_floor) {
        app->sign_floor = app->signing.timestamp;
    }
    memcpy(app->key, key, KF_STORE_KEY_LEN);
    app->key_set = 0u;
    for (uint32_t i = 0; i < KF_STORE_KEY_LEN; i++) {
        app->key_set |= (uint8_t)(key[i] != 0u);
    }
    memset(&app->signing, 0, sizeof app->signing);
    memcpy(app->signing.secret_key, key, sizeof app->signing.secret_key);
    memset(&app->sign_streams, 0, sizeof app->sign_streams);
    if (timestamp > app->sign_floor) {
        app->sign_floor = timestamp;
    }
    app->signing.timestamp = app->sign_floor;
    if (app->sign_reserved < app->sign_floor) {
        app->sign_reserved = app->sign_floor;   /* stored with the key (the caller saves) */
    }
    app->values[KF_P_SIGNING].u = app->key_set;
}

static void handle_setup_signing(kf_app *app, const mavlink_message_t *msg, int trusted)
{
    mavlink_setup_signing_t m;
    mavlink_msg_setup_signing_decode(msg, &m);
    if (!for_me(app, m.target_system, m.target_component)) {
        return;
    }
    if (!trusted) {
        app->cnt.unsigned_refused++;
        return;
    }
    kf_app_set_key(app, m.secret_key, m.initial_timestamp);
    if (app->sign_reserved < app->sign_floor + KF_SIGN_RESERVE_TICKS) {
        app->sign_reserved = app->sign_floor + KF_SIGN_RESERVE_TICKS;   /* this save reserves too */
    }
    (void)kf_config_save(app);
}

/* --- parameters ------------------------------------------------------------------------- */

static void handle_param_read(kf_app *app, const mavlink_message_t *msg)
{
    mavlink_param_request_read_t m;
    mavlink_msg_param_request_read_decode(msg, &m);
    if (!for_me(app, m.target_system, m.target_component)) {
        return;
    }
    int32_t idx = m.param_index >= 0 ? (int32_t)m.param_index : kf_param_find(m.param_id);
    if (idx >= 0 && idx < (int32_t)KF_PARAM_COUNT) {
        (void)kf_send_param_value(app, idx);
    } else {
        (void)kf_send_param_error(app, m.param_id, m.param_index, MAV_PARAM_ERROR_DOES_NOT_EXIST,
                                  msg->sysid, msg->compid);
    }
}

static void handle_param_set(kf_app *app, const mavlink_message_t *msg, int trusted)
{
    mavlink_param_set_t m;
    kf_pvalue v;
    mavlink_msg_param_set_decode(msg, &m);
    if (!for_me(app, m.target_system, m.target_component)) {
        return;
    }
    int32_t idx = kf_param_find(m.param_id);
    uint8_t err = 0u;
    if (idx < 0) {
        err = MAV_PARAM_ERROR_DOES_NOT_EXIST;
    } else if (!trusted) {
        err = MAV_PARAM_ERROR_PERMISSION_DENIED;
        app->cnt.unsigned_refused++;
    } else if (m.param_type != kf_param_table[idx].type) {
        err = MAV_PARAM_ERROR_VALUE_OUT_OF_RANGE;   /* wrong type (as the host tools expect) */
    } else {
        memcpy(&v.u, &m.param_value, sizeof v.u);   /* integers arrive bytewise */
        err = kf_config_set(app, idx, v);
    }
    if (err != 0u) {
        app->cnt.param_rejects++;
        (void)kf_send_param_error(app, m.param_id, idx, err, msg->sysid, msg->compid);
        if (idx >= 0) {
            (void)kf_send_param_value(app, idx);    /* the value that stays */
        }
        return;
    }
    (void)kf_send_param_value(app, idx);
}

/* --- commands --------------------------------------------------------------------------- */

static uint8_t set_interval(kf_app *app, float msgid_f, float interval_us)
{
    int32_t idx;
    uint32_t msgid = (msgid_f >= 0.0f && msgid_f < 16777216.0f) ? (uint32_t)msgid_f : 0xFFFFFFFFu;
    switch (msgid) {
    case MAVLINK_MSG_ID_KF_RAW_SAMPLE:
        idx = KF_P_RATE_HZ;
        break;
    case MAVLINK_MSG_ID_KF_ORIENTATION:
        idx = KF_P_ORI_RATE_HZ;
        break;
    case MAVLINK_MSG_ID_HIGHRES_IMU:
        idx = KF_P_HRIMU_RATE;
        break;
    case MAVLINK_MSG_ID_ATTITUDE_QUATERNION:
        idx = KF_P_ATTQ_RATE;
        break;
    case MAVLINK_MSG_ID_KF_EFFORTS:
        idx = KF_P_EFF_RATE_HZ;                          /* 0 (the default) turns the leg EKF off */
        break;
    default:
        return MAV_RESULT_UNSUPPORTED;
    }
    kf_pvalue v;
    if (!(interval_us == interval_us)) {
        return MAV_RESULT_DENIED;
    }
    if (interval_us < 0.0f) {
        v.u = 0u;                                        /* -1: off */
    } else if (interval_us == 0.0f) {
        v = kf_param_table[idx].def;                     /* 0: default rate */
    } else if (interval_us < 100.0f) {
        return MAV_RESULT_DENIED;                        /* faster than 10 kHz */
    } else {
        v.u = (uint32_t)(1e6f / interval_us + 0.5f);     /* whole Hz */
        if (v.u == 0u) {
            return MAV_RESULT_DENIED;                    /* slower than 0.5 Hz: not "off" */
        }
    }
    return kf_config_set(app, idx, v) == 0u ? MAV_RESULT_ACCEPTED : MAV_RESULT_DENIED;
}

static uint8_t request_message(float msgid_f)
{
    uint32_t msgid = (msgid_f >= 0.0f && msgid_f < 16777216.0f) ? (uint32_t)msgid_f : 0xFFFFFFFFu;
    switch (msgid) {
    case MAVLINK_MSG_ID_KF_UNIT_STATUS:
    case MAVLINK_MSG_ID_HEARTBEAT:
    case MAVLINK_MSG_ID_SYS_STATUS:
    case MAVLINK_MSG_ID_AUTOPILOT_VERSION:
        return MAV_RESULT_ACCEPTED;
    default:
        return MAV_RESULT_UNSUPPORTED;
    }
}

static void send_requested(kf_app *app, float msgid_f)
{
    uint32_t msgid = (uint32_t)msgid_f;   /* checked by request_message */
    if (msgid == MAVLINK_MSG_ID_KF_UNIT_STATUS) {
        (void)kf_send_unit_status(app);
    } else if (msgid == MAVLINK_MSG_ID_HEARTBEAT) {
        (void)kf_send_heartbeat(app);
    } else if (msgid == MAVLINK_MSG_ID_SYS_STATUS) {
        (void)kf_send_sys_status(app);
    } else {
        (void)kf_send_autopilot_version(app);
    }
}

static void handle_command(kf_app *app, const mavlink_message_t *msg, int trusted)
{
    mavlink_command_long_t c;
    uint8_t result = MAV_RESULT_UNSUPPORTED;
    mavlink_msg_command_long_decode(msg, &c);
    if (!for_me(app, c.target_system, c.target_component)) {
        return;
    }
    if (!trusted) {
        app->cnt.unsigned_refused++;
        (void)kf_send_ack(app, c.command, MAV_RESULT_DENIED, msg->sysid, msg->compid);
        return;
    }
    switch (c.command) {
    case MAV_CMD_KF_STREAM:
        app->streaming = (uint8_t)(c.param1 >= 0.5f);
        if (app->streaming && c.param2 >= 0.5f) {
            app->sample_counter = 0u;
            app->cnt_ori = app->cnt_hr = app->cnt_aq = app->cnt_eff = 0u;
        }
        result = MAV_RESULT_ACCEPTED;
        break;
    case MAV_CMD_KF_HEADING_TARE: {
        float t[4];
        if (app->filter < 0 || !app->initialised) {
            result = MAV_RESULT_TEMPORARILY_REJECTED;   /* no orientation yet */
        } else if (kf_quat_heading_tare(app->out.q, c.param1, t) != 0) {
            result = MAV_RESULT_FAILED;                 /* x axis vertical, or NaN heading */
        } else {
            memcpy(app->tare, t, sizeof t);
            app->tared = 1u;
            result = MAV_RESULT_ACCEPTED;
        }
        break;
    }
    case MAV_CMD_KF_FILTER_RESET:
        kf_config_reset_filter(app);    /* param1 (keep bias) is not supported: full reset */
        result = MAV_RESULT_ACCEPTED;
        break;
    case MAV_CMD_SET_MESSAGE_INTERVAL:
        result = set_interval(app, c.param1, c.param2);
        break;
    case MAV_CMD_REQUEST_MESSAGE:
        result = request_message(c.param1);
        break;
    case MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES:
        result = MAV_RESULT_ACCEPTED;
        break;
    case MAV_CMD_PREFLIGHT_REBOOT_SHUTDOWN:
        if (c.param1 >= 0.5f && c.param1 < 1.5f) {
            result = MAV_RESULT_ACCEPTED;
            app->reboot = 1u;           /* kf_app_poll sends the ACK, then resets */
        }
        break;
    default:
        break;
    }
    (void)kf_send_ack(app, c.command, result, msg->sysid, msg->compid);
    if (result == MAV_RESULT_ACCEPTED && c.command == MAV_CMD_REQUEST_MESSAGE) {
        send_requested(app, c.param1);
    } else if (result == MAV_RESULT_ACCEPTED && c.command == MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES) {
        (void)kf_send_autopilot_version(app);
    }
}

/* --- HIL sensor input ------------------------------------------------------------------- */

/* SI value -> int16 counts as kinefuse.host.link.hil.raw_counts: float64 division, round half
 * to even, saturate; *clip set when |rounded| > 32767 */
static int16_t to_counts(double x, double scale, uint8_t *clip)
{
    double r = nearbyint(x / scale);
    if (r > 32767.0) {
        *clip = 1u;
        return 32767;
    }
    if (r < -32767.0) {
        *clip = 1u;
        return r < -32768.0 ? -32768 : (int16_t)r;
    }
    return (int16_t)r;
}

#define KF_GYRO_SHIFT_MAX 3u

/* gyro rad/s -> KF_RAW_SAMPLE gyro fields as kinefuse.host.link.hil.raw_gyro_counts: the
 * smallest shift 0..3 for which all three nearbyint((x / 1e-3) * 2^-shift) (float64 division,
 * exact power-of-two scaling, round half to even) are within +-32767; beyond 2^3 * 32.767 rad/s
 * shift 3 saturated and *clip set.  gyr_cal: the shift-0 counts (to_counts) for the calibration
 * map, whose input is int16 counts. */
static uint8_t gyro_counts(const float g[3], int16_t gyr[3], int16_t gyr_cal[3], uint8_t *clip)
{
    static const double pow2_neg[KF_GYRO_SHIFT_MAX + 1u] = {1.0, 0.5, 0.25, 0.125};   /* exact */
    double r0[3];
    uint8_t shift = 0u, c0 = 0u;
    for (int i = 0; i < 3; i++) {
        r0[i] = (double)g[i] / KF_SCALE_GYR;
        gyr_cal[i] = to_counts((double)g[i], KF_SCALE_GYR, &c0);
    }
    for (; shift < KF_GYRO_SHIFT_MAX; shift++) {
        int fits = 1;
        for (int i = 0; i < 3; i++) {
            double r = nearbyint(r0[i] * pow2_neg[shift]);
            fits &= (r <= 32767.0 && r >= -32767.0);
        }
        if (fits) {
            break;
        }
    }
    for (int i = 0; i < 3; i++) {
        /* to_counts of the scaled quotient: the same rounding and saturation */
        gyr[i] = to_counts(r0[i] * pow2_neg[shift], 1.0, clip);
    }
    return shift;
}

static void handle_hil(kf_app *app, const mavlink_message_t *msg)
{
    mavlink_hil_sensor_t m;
    kf_sample s;
    uint8_t ca = 0u, cg = 0u, cm = 0u, ct = 0u;
    mavlink_msg_hil_sensor_decode(msg, &m);
    if (m.id > 1u || (m.id == 1u && app->values[KF_P_JOINT_ID].u == 0u)) {
        app->cnt.hil_invalid++;        /* sensor 1 exists in two-sensor mode only */
        return;
    }
    float a[3] = {m.xacc, m.yacc, m.zacc};
    float g[3] = {m.xgyro, m.ygyro, m.zgyro};
    float b[3] = {m.xmag, m.ymag, m.zmag};
    for (int i = 0; i < 3; i++) {
        if (isnan(a[i]) || isnan(g[i]) || isnan(b[i])) {
            app->cnt.hil_invalid++;    /* no count represents NaN: the sample is not used */
            return;
        }
    }
    if (isnan(m.temperature)) {
        m.temperature = 0.0f;
        m.fields_updated &= ~0x1000u;  /* no measurement: 0 must not be flagged valid */
    }
    memset(&s, 0, sizeof s);
    s.time_us = m.time_usec;
    for (int i = 0; i < 3; i++) {
        s.acc[i] = to_counts((double)a[i], KF_SCALE_ACC, &ca);
        s.mag[i] = to_counts((double)b[i] * KF_UT_PER_GAUSS, KF_SCALE_MAG, &cm);
        s.f_acc[i] = a[i];
        s.f_gyr[i] = g[i];
        s.f_mag[i] = b[i] * 100.0f;     /* gauss -> uT, one float32 rounding */
    }
    s.gyro_shift = gyro_counts(g, s.gyr, s.gyr_cal, &cg);
    s.temperature = to_counts((double)m.temperature, KF_SCALE_TEMP, &ct);
    s.mag_valid = (uint8_t)((m.fields_updated & 0x1C0u) != 0u);
    s.flags = (uint8_t)(KF_RAW_SAMPLE_FLAGS_SIMULATED | (ca ? KF_RAW_SAMPLE_FLAGS_ACC_CLIPPED : 0u)
                        | (cg ? KF_RAW_SAMPLE_FLAGS_GYRO_CLIPPED : 0u)
                        | (cm ? KF_RAW_SAMPLE_FLAGS_MAG_CLIPPED : 0u)
                        | ((m.fields_updated & 0x1000u) ? KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID : 0u));
    s.direct = (uint8_t)((app->values[KF_P_HIL_MODE].u & KF_HIL_MODE_DIRECT) != 0u);
    if (!app->hil) {
        app->hil = 1u;         /* from now on the sensor is ignored (until reset) */
        kf_config_reset_filter(app);   /* no estimate mixing sensor and simulated motion; the
                                        * first HIL sample gets the nominal time step */
    }
    if (m.id == 1u) {
        kf_app_sample2(app, &s);       /* the distal sensor: no answer of its own */
    } else {
        kf_app_sample(app, &s);
    }
}

/* --- dispatch --------------------------------------------------------------------------- */

void kf_handle_frame(kf_app *app, const mavlink_message_t *msg)
{
    int is_signed = (msg->incompat_flags & MAVLINK_IFLAG_SIGNED) != 0u;
    if (is_signed && app->key_set
        && (!signature_ok(app, msg) || !reserve_timestamp(app, signature_timestamp(msg)))) {
        app->cnt.signature_failures++;
        return;
    }
    int trusted = !app->key_set || is_signed;
    switch (msg->msgid) {
    case MAVLINK_MSG_ID_HEARTBEAT:
        return;
    case MAVLINK_MSG_ID_TIMESYNC: {
        mavlink_timesync_t t;
        mavlink_message_t out;
        mavlink_msg_timesync_decode(msg, &t);
        if (t.tc1 == 0) {
            mavlink_msg_timesync_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &out,
                                             (int64_t)(kf_app_time(app) * 1000u), t.ts1);
            (void)kf_send(app, &out);
        }
        return;
    }
    case MAVLINK_MSG_ID_PARAM_REQUEST_LIST: {
        mavlink_param_request_list_t m;
        mavlink_msg_param_request_list_decode(msg, &m);
        if (for_me(app, m.target_system, m.target_component)) {
            app->list_next = 0;
        }
        return;
    }
    case MAVLINK_MSG_ID_PARAM_REQUEST_READ:
        handle_param_read(app, msg);
        return;
    case MAVLINK_MSG_ID_PARAM_SET:
        handle_param_set(app, msg, trusted);
        return;
    case MAVLINK_MSG_ID_COMMAND_LONG:
        handle_command(app, msg, trusted);
        return;
    case MAVLINK_MSG_ID_HIL_SENSOR:
        if (!trusted) {
            app->cnt.unsigned_refused++;
            return;
        }
        handle_hil(app, msg);
        return;
    case MAVLINK_MSG_ID_SETUP_SIGNING:
        handle_setup_signing(app, msg, trusted);
        return;
    default:
        app->cnt.unknown_messages++;
        return;
    }
}
