/*
 * kf_status.c - once per second: HEARTBEAT, KF_UNIT_STATUS and SYS_STATUS, with the rates
 * achieved and the processor load measured over the second that ended (flags TX_OVERFLOW,
 * STORAGE_ERROR and SENSOR_FAULT: since the previous status; LOW_BATTERY from this second's
 * reading); a STATUSTEXT when the parameter storage failed, or a stored value was refused at
 * load, since the previous one, and when the battery went low.
 */
#include <stdint.h>

#include "kf_app_internal.h"

#define KF_STATUS_PERIOD_US 1000000u
/* LOW_BATTERY clears only this far above KF_BATT_LOW_MV: a cell's voltage sags and recovers
 * with the load (radio bursts), which would otherwise toggle the flag near the threshold */
#define KF_BATT_HYSTERESIS_MV 100u

static void battery_check(kf_app *app)
{
    uint32_t mv = kf_hal_battery_mv();
    uint32_t low_mv = app->values[KF_P_BATT_LOW_MV].u;
    if (mv == UINT16_MAX || low_mv == 0u) {
        app->low_battery = 0u;             /* not measured, or the warning is off */
    } else if (mv < low_mv) {
        app->low_battery = 1u;
    } else if (mv >= low_mv + KF_BATT_HYSTERESIS_MV) {
        app->low_battery = 0u;
    }
    if (!app->low_battery) {
        app->low_battery_told = 0u;        /* the next fall is told again */
    }
}

void kf_status_tick(kf_app *app, uint64_t now)
{
    kf_rates *r = &app->rates;
    uint64_t span = now - r->t0;
    if (span > 0u) {
        float s = (float)span * 1e-6f;
        r->sensor_hz = (float)r->samples / s;
        r->raw_hz = (float)r->raw / s;
        r->ori_hz = (float)r->ori / s;
        uint64_t load = r->busy_us * 1000u / span;
        r->load = (uint16_t)(load > 1000u ? 1000u : load);
    }
    r->samples = r->raw = r->ori = 0u;
    r->busy_us = 0u;
    r->t0 = now;
    app->cnt.samples_dropped = kf_hal_sensor_dropped();
    battery_check(app);
    (void)kf_send_heartbeat(app);
    (void)kf_send_unit_status(app);
    (void)kf_send_sys_status(app);
    r->frames_dropped0 = app->tx.frames_dropped;
    r->store_errors_st0 = app->store.errors;
    app->sensor_fault_seen = app->sensor_fault;   /* SENSOR_FAULT: since this status */
    if (app->store.errors != r->store_errors0) {
        /* a failed load or save since the previous status (at boot: since reset): besides
         * KF_UNIT_STATUS_FLAGS_STORAGE_ERROR, in words (it is not a sensor fault) */
        if (kf_send_statustext(app, MAV_SEVERITY_ERROR, "parameter storage error: settings may be lost")) {
            r->store_errors0 = app->store.errors;
        }
    }
    if (app->cnt.stored_rejects != r->stored_rejects0) {
        /* stored values the firmware refused at load (e.g. a range narrowed by an update):
         * the defaults run instead, which the user must know */
        if (kf_send_statustext(app, MAV_SEVERITY_WARNING, "stored parameter out of range: default used")) {
            r->stored_rejects0 = app->cnt.stored_rejects;
        }
    }
    if (app->low_battery && !app->low_battery_told) {
        /* once per fall below the threshold (retried while the link is full): a recording
         * stops when the cell is empty */
        if (kf_send_statustext(app, MAV_SEVERITY_WARNING, "battery low: recharge the unit")) {
            app->low_battery_told = 1u;
        }
    }
    /* next second on the device clock; after a stall, skip what was missed */
    app->next_status_us += KF_STATUS_PERIOD_US;
    if (app->next_status_us <= now) {
        app->next_status_us = now + KF_STATUS_PERIOD_US;
    }
}
