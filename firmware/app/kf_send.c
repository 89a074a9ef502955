/*
 * kf_send.c - outgoing messages: pack with the generated *_pack_status() functions, serialise
 * and queue whole frames (a full queue drops the frame and counts it).
 */
#include <stdint.h>
#include <string.h>

#include "kf_app_internal.h"
#include "kf_version.h"

uint8_t kf_sysid(const kf_app *app)
{
    return (uint8_t)app->values[KF_P_UNIT_ID].u;
}

int kf_send(kf_app *app, mavlink_message_t *msg)
{
    uint8_t buf[KF_FRAME_MAX];
    uint16_t n = mavlink_msg_to_send_buffer(buf, msg);
    return kf_tx_push(&app->tx, buf, n);
}

int kf_send_param_value(kf_app *app, int32_t index)
{
    mavlink_message_t msg;
    const kf_param_desc *d = &kf_param_table[index];
    char name[16];                                       /* the packer copies 16 bytes */
    float wire;
    memset(name, 0, sizeof name);
    for (uint32_t i = 0; i < sizeof name && d->name[i] != '\0'; i++) {
        name[i] = d->name[i];
    }
    memcpy(&wire, &app->values[index].u, sizeof wire);   /* bytewise: exact for integers */
    mavlink_msg_param_value_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                        name, wire, d->type, (uint16_t)KF_PARAM_COUNT,
                                        (uint16_t)index);
    return kf_send(app, &msg);
}

int kf_send_param_error(kf_app *app, const char *name16, int32_t index, uint8_t error,
                        uint8_t to_sys, uint8_t to_comp)
{
    mavlink_message_t msg;
    char name[17];
    memcpy(name, name16, 16);
    name[16] = '\0';
    mavlink_msg_param_error_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                        to_sys, to_comp, name, (int16_t)index, error);
    return kf_send(app, &msg);
}

int kf_send_ack(kf_app *app, uint16_t command, uint8_t result, uint8_t to_sys, uint8_t to_comp)
{
    mavlink_message_t msg;
    mavlink_msg_command_ack_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                        command, result, 0u, 0, to_sys, to_comp);
    return kf_send(app, &msg);
}

int kf_send_statustext(kf_app *app, uint8_t severity, const char *text)
{
    mavlink_message_t msg;
    char buf[MAVLINK_MSG_STATUSTEXT_FIELD_TEXT_LEN];   /* the packer copies all 50 bytes */
    memset(buf, 0, sizeof buf);
    for (uint32_t i = 0; i < sizeof buf && text[i] != '\0'; i++) {
        buf[i] = text[i];
    }
    mavlink_msg_statustext_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                       severity, buf, 0u, 0u);
    return kf_send(app, &msg);
}

int kf_send_heartbeat(kf_app *app)
{
    mavlink_message_t msg;
    mavlink_msg_heartbeat_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                      MAV_TYPE_GENERIC, MAV_AUTOPILOT_INVALID, 0u, 0u,
                                      app->streaming ? MAV_STATE_ACTIVE : MAV_STATE_STANDBY);
    return kf_send(app, &msg);
}

static uint32_t status_flags(const kf_app *app)
{
    uint32_t f = 0u;
    f |= app->streaming ? KF_UNIT_STATUS_FLAGS_STREAMING : 0u;
    f |= app->hil ? KF_UNIT_STATUS_FLAGS_HIL : 0u;
    f |= app->calibrated ? KF_UNIT_STATUS_FLAGS_CALIBRATED : 0u;
    f |= app->mag_present ? KF_UNIT_STATUS_FLAGS_MAG_PRESENT : 0u;
    /* this second's battery reading below KF_BATT_LOW_MV (kf_status.c; battery_voltage is sent) */
    f |= app->low_battery ? KF_UNIT_STATUS_FLAGS_LOW_BATTERY : 0u;
    /* "since the previous status": frames_dropped itself counts since boot */
    f |= app->tx.frames_dropped != app->rates.frames_dropped0 ? KF_UNIT_STATUS_FLAGS_TX_OVERFLOW : 0u;
    /* storage errors are not a sensor fault: their own flag (and a STATUSTEXT, kf_status.c) */
    f |= app->store.errors != app->rates.store_errors_st0 ? KF_UNIT_STATUS_FLAGS_STORAGE_ERROR : 0u;
    /* sensor 0 silent at some time since the previous status (kf_app.c); clear once a whole
     * interval had samples */
    f |= app->sensor_fault_seen ? KF_UNIT_STATUS_FLAGS_SENSOR_FAULT : 0u;
    return f;
}

int kf_send_unit_status(kf_app *app)
{
    mavlink_message_t msg;
    uint32_t rate = app->values[KF_P_RATE_HZ].u;
    uint32_t ori = app->values[KF_P_ORI_RATE_HZ].u;
    const kf_counters *c = &app->cnt;
    uint16_t mv = kf_hal_battery_mv();
    uint32_t unknown = c->unknown_messages + app->rx.unknown_ids;
    uint32_t rejected = c->rejected_base + (uint32_t)app->out.rejected;
    /* sensor 1's filter (two-sensor mode): its own count, kept across its restarts */
    uint32_t rejected2 = c->rejected2_base + (uint32_t)app->out2.rejected;
    mavlink_msg_kf_unit_status_pack_status(
        kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg, kf_app_time(app), KF_FW_VERSION,
        KF_GIT_HASH, KF_DIALECT_HASH, c->samples, c->samples_dropped, app->tx.frames_dropped,
        rejected, app->rx.crc_errors + app->rx.bad_frames, unknown, c->param_rejects,
        (float)rate, app->rates.sensor_hz, app->streaming ? (float)rate : 0.0f, app->rates.raw_hz,
        /* KF_FILTER 0 (none): no KF_ORIENTATION goes out, so none is requested */
        (app->streaming && app->filter >= 0) ? (float)ori : 0.0f, app->rates.ori_hz, mv, app->rates.load,
        (uint16_t)status_flags(app), -1, kf_sysid(app),
        app->filter >= 0 ? kf_gen_filters[app->filter].id : 0u,
        KF_NUMERIC_Q ? KF_NUMERIC_FORMAT_FIXED_POINT : KF_NUMERIC_FORMAT_FLOAT32, KF_EARTH_FRAME_ENU,
        c->numeric_resets, c->hil_invalid, rejected2);
    return kf_send(app, &msg);
}

int kf_send_sys_status(kf_app *app)
{
    /* for generic ground stations: load, battery and the error counters
     * (errors_comm: CRC/framing, count1: unknown messages, count2: refused unsigned,
     *  count3: bad signatures, count4: parameter rejects), saturated to 16 bits */
    mavlink_message_t msg;
    const kf_counters *c = &app->cnt;
    uint32_t v[5] = {app->rx.crc_errors + app->rx.bad_frames, c->unknown_messages + app->rx.unknown_ids,
                     c->unsigned_refused, c->signature_failures, c->param_rejects};
    uint16_t s[5];
    for (int i = 0; i < 5; i++) {
        s[i] = (uint16_t)(v[i] > 0xFFFFu ? 0xFFFFu : v[i]);
    }
    uint32_t sensors = MAV_SYS_STATUS_SENSOR_3D_GYRO | MAV_SYS_STATUS_SENSOR_3D_ACCEL
                       | MAV_SYS_STATUS_SENSOR_3D_MAG;
    /* KF_MAG_ENABLE 0: the magnetometer is not used (present, not enabled) */
    uint32_t enabled = app->values[KF_P_MAG_ENABLE].u != 0u
                       ? sensors : sensors & ~(uint32_t)MAV_SYS_STATUS_SENSOR_3D_MAG;
    /* health: a silent sensor (SENSOR_FAULT in the KF_UNIT_STATUS of the same second) takes
     * all three of its sensors out (one chip delivers them) */
    uint32_t health = app->sensor_fault_seen ? 0u : sensors;
    /* the battery where the board measures it: unhealthy while LOW_BATTERY */
    uint16_t mv = kf_hal_battery_mv();
    if (mv != UINT16_MAX) {
        sensors |= MAV_SYS_STATUS_SENSOR_BATTERY;
        enabled |= MAV_SYS_STATUS_SENSOR_BATTERY;
        health |= app->low_battery ? 0u : (uint32_t)MAV_SYS_STATUS_SENSOR_BATTERY;
    }
    mavlink_msg_sys_status_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                       sensors, enabled, health, app->rates.load, mv,
                                       -1, -1, 0u, s[0], s[1], s[2], s[3], s[4], 0u, 0u, 0u);
    return kf_send(app, &msg);
}

int kf_send_autopilot_version(kf_app *app)
{
    mavlink_message_t msg;
    uint8_t custom[8];
    uint32_t git = KF_GIT_HASH;
    uint8_t zero[18];
    memset(custom, 0, sizeof custom);
    memset(zero, 0, sizeof zero);
    memcpy(custom, &git, sizeof git);
    uint64_t caps = MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_BYTEWISE | MAV_PROTOCOL_CAPABILITY_MAVLINK2;
    mavlink_msg_autopilot_version_pack_status(kf_sysid(app), KF_COMPONENT_ID, &app->tx_status, &msg,
                                              caps, KF_FW_VERSION, 0u, 0u, 0u, custom, custom, custom,
                                              0u, 0u, app->values[KF_P_SERIAL_NO].u, zero);
    return kf_send(app, &msg);
}
