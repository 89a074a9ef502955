/*
 * kf_app.c - reset and main-loop turn of the application (see kf_app.h).
 */
#include <stdint.h>
#include <string.h>

#include "kf_app_internal.h"

#define KF_SENSOR_BATCH 64          /* samples taken per turn at most */
#define KF_REBOOT_FLUSH_TURNS 100000 /* how long a reboot waits for the UART to drain */

uint64_t kf_app_time(kf_app *app)
{
    uint32_t t = kf_hal_micros();
    app->clock_now += (uint32_t)(t - app->clock_last32);   /* modulo 2^32: wraps are fine */
    app->clock_last32 = t;
    return app->clock_now;
}

void kf_app_init(kf_app *app)
{
    memset(app, 0, sizeof *app);
    kf_link_init(&app->rx);
    kf_tx_init(&app->tx);
    app->list_next = -1;
    app->clock_last32 = kf_hal_micros();
    app->clock_now = app->clock_last32;
    kf_config_load(app);
    kf_app_set_key(app, app->key, app->sign_floor);
    kf_config_select_filter(app);
    (void)kf_config_apply_rates(app);   /* a grant outside KF_RATE_HZ's range: the stored rate stays */
    app->streaming = (uint8_t)(app->values[KF_P_STREAM_BOOT].u != 0u);
    app->next_status_us = app->clock_now;   /* announce ourselves at once */
    app->rates.t0 = app->clock_now;
}

/* sensor counts at the int16 limits: the sensor (or its range) clipped */
static uint8_t clip_flags(const kf_raw_sample *r)
{
    uint8_t f = 0u;
    for (int i = 0; i < 3; i++) {
        f |= (r->acc[i] == INT16_MAX || r->acc[i] == INT16_MIN) ? KF_RAW_SAMPLE_FLAGS_ACC_CLIPPED : 0u;
        f |= (r->gyr[i] == INT16_MAX || r->gyr[i] == INT16_MIN) ? KF_RAW_SAMPLE_FLAGS_GYRO_CLIPPED : 0u;
        f |= (r->mag[i] == INT16_MAX || r->mag[i] == INT16_MIN) ? KF_RAW_SAMPLE_FLAGS_MAG_CLIPPED : 0u;
    }
    return f;
}

static void take_sensor_sample(kf_app *app, const kf_raw_sample *r, int sensor)
{
    kf_sample s;
    uint64_t now = kf_app_time(app);
    uint32_t ahead = r->time_us - app->clock_last32;   /* modulo 2^32 */
    memset(&s, 0, sizeof s);
    /* 32-bit sample time -> 64-bit device time: within 2^31 us of now, before or after */
    if ((int32_t)ahead >= 0) {
        s.time_us = now + ahead;
    } else {
        uint32_t age = app->clock_last32 - r->time_us;
        s.time_us = (uint64_t)age <= now ? now - age : 0u;
    }
    memcpy(s.acc, r->acc, sizeof s.acc);
    memcpy(s.gyr, r->gyr, sizeof s.gyr);
    memcpy(s.gyr_cal, r->gyr, sizeof s.gyr_cal);   /* the sensor's own counts: gyro_shift 0 */
    memcpy(s.mag, r->mag, sizeof s.mag);
    s.mag_valid = (uint8_t)(r->mag_valid != 0u);
    s.flags = clip_flags(r);
    if (sensor == 0) {
        kf_app_sample(app, &s);
    } else {
        kf_app_sample2(app, &s);
    }
}

int kf_app_poll(kf_app *app)
{
    mavlink_message_t msg;
    kf_raw_sample raw;
    uint64_t t_start = kf_app_time(app);
    int work = 0;
    uint16_t room;
    uint8_t *p = kf_link_space(&app->rx, &room);
    int32_t n = room != 0u ? kf_hal_uart_read(p, (int32_t)room) : 0;
    if (n > 0) {
        kf_link_commit(&app->rx, (uint16_t)(n > (int32_t)room ? (int32_t)room : n));
        work = 1;
    }
    while (kf_link_next(&app->rx, &msg)) {
        kf_handle_frame(app, &msg);
        work = 1;
    }
    /* two-sensor mode: the two sensors' samples in pairs, sensor 1 first, so that a sensor-0
     * sample sees the sensor-1 sample of the same instant (joint angle, leg EKF) even when
     * several of each wait in the FIFOs */
    int got0 = 0, got1 = 0;
    for (int k = 0; k < KF_SENSOR_BATCH; k++) {
        int got = 0;
        if (app->two_sensors && kf_hal_sensor2_read(&raw)) {
            got = 1;
            got1 = 1;
            if (!app->hil) {
                take_sensor_sample(app, &raw, 1);
            }
        }
        if (kf_hal_sensor_read(&raw)) {
            got = 1;
            got0 = 1;
            if (!app->hil) {      /* in HIL mode the samples come from HIL_SENSOR only */
                take_sensor_sample(app, &raw, 0);
            }
        }
        if (!got) {
            break;
        }
        work = 1;
    }
    /* SENSOR_FAULT: kf_hal_sensor_read has no error return, so the one failure the unit can
     * see is a configured sensor that stops delivering (timeout: kf_config_apply_rates).  The
     * FIFOs are read just above, so a late turn of this loop is not taken for a silent sensor.
     * Sensor 0 is watched in HIL mode too (it is still read there); sensor 1, in two-sensor
     * mode, only outside it: there HIL_SENSOR id 1 stands in for it, and a board may have
     * none (a two-sensor unit without a second sensor outside HIL mode is a fault). */
    uint64_t t_now = kf_app_time(app);
    if (got0) {
        app->sensor_last_us = t_now;
    }
    if (got1) {
        app->sensor2_last_us = t_now;
    }
    uint8_t silent = 0u;
    if (app->sensor_timeout_us != 0u) {
        silent = (uint8_t)(t_now - app->sensor_last_us > app->sensor_timeout_us);
        if (app->two_sensors && !app->hil
                && t_now - app->sensor2_last_us > app->sensor_timeout_us) {
            silent = 1u;
        }
    }
    app->sensor_fault = silent;
    app->sensor_fault_seen |= silent;
    /* a parameter list goes out while the queue is at most half full: streams keep priority */
    while (app->list_next >= 0 && kf_tx_pending(&app->tx) < KF_TX_BUFFER_BYTES / 2u) {
        (void)kf_send_param_value(app, app->list_next);
        app->list_next++;
        if (app->list_next >= (int32_t)KF_PARAM_COUNT) {
            app->list_next = -1;
        }
        work = 1;
    }
    uint64_t now = kf_app_time(app);
    if (now >= app->next_status_us) {
        kf_status_tick(app, now);
        work = 1;
    }
    if (kf_tx_flush(&app->tx) != 0u) {
        work = 1;
    }
    if (app->reboot) {
        for (int i = 0; i < KF_REBOOT_FLUSH_TURNS && kf_tx_pending(&app->tx) != 0u; i++) {
            (void)kf_tx_flush(&app->tx);
        }
        app->reboot = 0u;
        kf_app_sign_shutdown(app);
        kf_hal_reboot();          /* returns only on the host build, whose main re-inits */
        return 1;
    }
    if (work) {
        app->rates.busy_us += kf_app_time(app) - t_start;
    }
    return work;
}
