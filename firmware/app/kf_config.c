/*
 * kf_config.c - parameter values: defaults, load/save through kf_store, validation and the
 * side effects of a change (filter switch, stream rates, unit id, the two sensors' calibration).
 */
#include <stdint.h>
#include <string.h>

#include "kf_app_internal.h"

#define KF_SENSOR_TIMEOUT_MIN_US 100000u

static const kf_filter_ops *active_ops(const kf_app *app)
{
    return app->filter >= 0 ? &kf_gen_filters[app->filter] : NULL;
}

/* float32 parameter vector of filter k, with value v at position `at` (-1: none replaced) */
static void filter_vector(const kf_app *app, int32_t k, int32_t at, float v, float *vec)
{
    const kf_filter_ops *f = &kf_gen_filters[k];
    for (uint16_t i = 0; i < f->param_count; i++) {
        vec[i] = app->values[KF_P_FILTER_FIRST + f->first_param + i].f;
    }
    if (at >= 0) {
        vec[at] = v;
    }
}

/* float32 calibration vector of sensor 0 (first = KF_P_CALIB_FIRST) or sensor 1
 * (KF_P_CALIB2_FIRST): the same generated map, the same order */
static void calib_vector(const kf_app *app, uint32_t first, int32_t at, float v, float *vec)
{
    for (uint16_t i = 0; i < KF_GEN_CALIB_PARAM_COUNT; i++) {
        vec[i] = app->values[first + i].f;
    }
    if (at >= 0) {
        vec[at] = v;
    }
}

static void joint_vector(const kf_app *app, int32_t at, float v, float *vec)
{
    for (uint16_t i = 0; i < KF_GEN_JOINT_PARAM_COUNT; i++) {
        vec[i] = app->values[KF_P_JOINT_FIRST + i].f;
    }
    if (at >= 0) {
        vec[at] = v;
    }
}

static int filter_check(kf_app *app, int32_t k, const float *vec)
{
    const kf_filter_ops *f = &kf_gen_filters[k];
    if (f->build == NULL) {
        return 0;    /* left out of this build: the values' own ranges are all we can check */
    }
    f->build(vec, &app->fparams);
    return f->init(&app->scratch, &app->fparams);
}

/* KF_UNIT_STATUS_FLAGS_CALIBRATED: sensor 0's map, or in two-sensor mode sensor 1's, is not
 * the default.  Compared as float values (never NaN: range-checked), so -0.0 is the default 0. */
static void update_calibrated_flag(kf_app *app)
{
    app->calibrated = 0u;
    for (uint32_t i = KF_P_CALIB_FIRST; i < KF_P_FILTER_FIRST; i++) {
        if (app->values[i].f != kf_param_table[i].def.f) {
            app->calibrated = 1u;
        }
    }
    if (app->values[KF_P_JOINT_ID].u != 0u) {
        for (uint32_t i = KF_P_CALIB2_FIRST; i < KF_P_CALIB2_FIRST + KF_GEN_CALIB2_PARAM_COUNT; i++) {
            if (app->values[i].f != kf_param_table[i].def.f) {
                app->calibrated = 1u;
            }
        }
    }
}

static void reset_two_sensors(kf_app *app);

/* (Re)start the selected filter from its parameters; clears tare and status.  The next
 * sample gets the nominal time step (as after a reset), whatever time preceded it. */
void kf_config_reset_filter(kf_app *app)
{
    float vec[KF_GEN_FILTER_PARAM_MAX + 1];
    const kf_filter_ops *f = active_ops(app);
    reset_two_sensors(app);
    app->cnt.rejected_base += (uint32_t)app->out.rejected;
    memset(&app->out, 0, sizeof app->out);
    app->out.q[0] = 1.0f;
    app->initialised = 0u;
    app->tared = 0u;
    app->have_prev = 0u;
    if (f == NULL) {
        return;
    }
    filter_vector(app, app->filter, -1, 0.0f, vec);
    f->build(vec, &app->fparams);
    (void)f->init(&app->filt, &app->fparams);   /* validated when the values were accepted */
    if (app->two_sensors) {
        (void)f->init(&app->filt2, &app->fparams);
    }
}

/* Two-sensor mode on or off (KF_JOINT_ID), the second filter instance and the joint step
 * restarted; called by kf_config_reset_filter. */
static void reset_two_sensors(kf_app *app)
{
    float jv[KF_GEN_JOINT_PARAM_COUNT];
    app->cnt.rejected2_base += (uint32_t)app->out2.rejected;
    uint8_t was_two = app->two_sensors;
    app->two_sensors = (uint8_t)(app->values[KF_P_JOINT_ID].u != 0u);
    if (app->two_sensors && !was_two) {
        app->sensor2_last_us = kf_app_time(app);   /* sensor 1's watch starts now */
    }
    memset(&app->out2, 0, sizeof app->out2);
    app->out2.q[0] = 1.0f;
    memset(&app->jout, 0, sizeof app->jout);
    app->initialised2 = 0u;
    app->have_prev2 = 0u;
    joint_vector(app, -1, 0.0f, jv);
    (void)kf_gen_joint_init(&app->joint, jv);   /* validated when the values were accepted */
    kf_leg_reset(app);                          /* the leg EKF restarts with the filters */
}

/* Restart only sensor 1's filter instance (after a non-finite output). */
void kf_config_reset_filter2(kf_app *app)
{
    float vec[KF_GEN_FILTER_PARAM_MAX + 1];
    const kf_filter_ops *f = active_ops(app);
    app->cnt.rejected2_base += (uint32_t)app->out2.rejected;   /* sensor 1's own count, not sensor 0's */
    memset(&app->out2, 0, sizeof app->out2);
    app->out2.q[0] = 1.0f;
    app->initialised2 = 0u;
    app->have_prev2 = 0u;
    if (f == NULL) {
        return;
    }
    filter_vector(app, app->filter, -1, 0.0f, vec);
    f->build(vec, &app->fparams);
    (void)f->init(&app->filt2, &app->fparams);
}

void kf_config_select_filter(kf_app *app)
{
    app->filter = kf_filter_index(app->values[KF_P_FILTER].u);
    /* the filter's `mode` choice (KF_FL_MODE, KF_EK_MODE: 0 ignores the magnetometer), found
     * once here rather than by name for every KF_ORIENTATION */
    app->mode_param = -1;
    if (app->filter >= 0) {
        const kf_filter_ops *f = &kf_gen_filters[app->filter];
        for (uint16_t i = 0; i < f->param_count; i++) {
            uint32_t k = KF_P_FILTER_FIRST + f->first_param + i;
            const char *n = kf_param_table[k].name;
            size_t len = strlen(n);
            if ((kf_param_table[k].flags & KF_PF_CHOICE) != 0u && len > 5u
                && strcmp(n + len - 5u, "_MODE") == 0) {
                app->mode_param = (int32_t)k;
            }
        }
    }
    kf_config_reset_filter(app);
}

static uint16_t divider(uint32_t rate, uint32_t hz)
{
    if (hz == 0u || rate == 0u) {
        return 0u;
    }
    uint32_t d = (rate + hz / 2u) / hz;
    return (uint16_t)(d == 0u ? 1u : d);
}

/* The sensor is configured first: when it delivers another rate than KF_RATE_HZ asks for, that
 * rate becomes KF_RATE_HZ (time steps, dividers, PARAM_VALUE and KF_UNIT_STATUS tell what the
 * unit really does).  Returns -1 when the rate it delivers is outside KF_RATE_HZ's range (the
 * parameter is then left as it was asked). */
int kf_config_apply_rates(kf_app *app)
{
    int r = 0;
    int32_t granted = kf_hal_sensor_configure(app->values[KF_P_RATE_HZ].u);
    /* SENSOR_FAULT watch (kf_app.c): a sensor that delivers `granted` Hz is silent when nothing
     * came for 4 periods, and never before 100 ms (start-up, FIFO batches); a fault stays until
     * the next sample.  The timeout counts from now: a new rate may take a moment to start. */
    app->sensor_last_us = kf_app_time(app);
    app->sensor2_last_us = app->sensor_last_us;
    if (granted > 0) {                 /* -1: no sensor (samples over the link): as asked */
        kf_pvalue g;
        uint32_t four = 4000000u / (uint32_t)granted;
        app->sensor_timeout_us = four > KF_SENSOR_TIMEOUT_MIN_US ? four : KF_SENSOR_TIMEOUT_MIN_US;
        g.u = (uint32_t)granted;
        if (kf_param_in_range(&kf_param_table[KF_P_RATE_HZ], g)) {
            app->values[KF_P_RATE_HZ] = g;
        } else {
            r = -1;
        }
    } else {
        app->sensor_timeout_us = 0u;   /* no sensor: nothing to watch */
        app->sensor_fault = 0u;
    }
    uint32_t rate = app->values[KF_P_RATE_HZ].u;
    app->div_ori = divider(rate, app->values[KF_P_ORI_RATE_HZ].u);
    app->div_hr = divider(rate, app->values[KF_P_HRIMU_RATE].u);
    app->div_aq = divider(rate, app->values[KF_P_ATTQ_RATE].u);
    app->div_eff = divider(rate, app->values[KF_P_EFF_RATE_HZ].u);
    app->cnt_ori = app->cnt_hr = app->cnt_aq = app->cnt_eff = 0u;
    return r;
}

/* --- persistence ------------------------------------------------------------------------ */

static void put_entry(void *ctx, const kf_store_entry *e)
{
    kf_app *app = (kf_app *)ctx;
    for (int32_t i = 0; i < (int32_t)KF_PARAM_COUNT; i++) {
        const kf_param_desc *d = &kf_param_table[i];
        if ((d->flags & KF_PF_READONLY) == 0u && kf_store_name_hash(d->name) == e->name_hash) {
            kf_pvalue v;
            v.u = e->value;
            if (kf_param_in_range(d, v)) {
                app->values[i] = v;
            } else {
                app->cnt.stored_rejects++;   /* e.g. a range narrowed by a firmware update */
            }
            return;
        }
    }
}

static void get_entry(void *ctx, uint16_t i, kf_store_entry *e)
{
    const kf_app *app = (const kf_app *)ctx;
    /* the table without its read-only rows, in table order */
    uint16_t k = 0;
    for (int32_t j = 0; j < (int32_t)KF_PARAM_COUNT; j++) {
        if ((kf_param_table[j].flags & KF_PF_READONLY) != 0u) {
            continue;
        }
        if (k == i) {
            e->name_hash = kf_store_name_hash(kf_param_table[j].name);
            e->value = app->values[j].u;
            return;
        }
        k++;
    }
    e->name_hash = 0u;
    e->value = 0u;
}

static uint16_t stored_count(void)
{
    uint16_t n = 0;
    for (int32_t j = 0; j < (int32_t)KF_PARAM_COUNT; j++) {
        if ((kf_param_table[j].flags & KF_PF_READONLY) == 0u) {
            n++;
        }
    }
    return n;
}

int kf_config_save(kf_app *app)
{
    kf_store_header h;
    memset(&h, 0, sizeof h);
    memcpy(h.key, app->key, sizeof h.key);
    h.sign_timestamp = app->sign_reserved;   /* the reservation, not the newest timestamp itself */
    return kf_store_save(&app->store, &h, stored_count(), get_entry, app);
}

/* Values that pass their own range but not the filter's/calibration's joint check go back
 * to their defaults, one at a time (the generated init names the first bad one). */
static void repair_calib(kf_app *app, uint32_t first, kf_calib_state *calib)
{
    float vec[KF_GEN_CALIB_PARAM_COUNT];
    for (int tries = 0; tries <= (int)KF_GEN_CALIB_PARAM_COUNT; tries++) {
        calib_vector(app, first, -1, 0.0f, vec);
        int r = kf_gen_calib_init(calib, vec);
        if (r >= 0 || -r - 1 >= (int)KF_GEN_CALIB_PARAM_COUNT) {
            break;
        }
        uint32_t i = first + (uint32_t)(-r - 1);
        app->values[i] = kf_param_table[i].def;
        app->cnt.stored_rejects++;
    }
}

static void repair_groups(kf_app *app)
{
    float vec[KF_GEN_CALIB_PARAM_COUNT + KF_GEN_FILTER_PARAM_MAX];
    repair_calib(app, KF_P_CALIB_FIRST, &app->calib);
    repair_calib(app, KF_P_CALIB2_FIRST, &app->calib2);   /* sensor 1's map (absent from an older image: defaults) */
    for (int32_t k = 0; k < (int32_t)KF_GEN_FILTER_COUNT; k++) {
        for (int tries = 0; tries <= (int)KF_GEN_FILTER_PARAM_MAX; tries++) {
            filter_vector(app, k, -1, 0.0f, vec);
            int r = filter_check(app, k, vec);
            if (r >= 0 || -r - 1 >= (int)kf_gen_filters[k].param_count) {
                break;
            }
            uint32_t i = KF_P_FILTER_FIRST + kf_gen_filters[k].first_param + (uint32_t)(-r - 1);
            app->values[i] = kf_param_table[i].def;
            app->cnt.stored_rejects++;
        }
    }
    for (int tries = 0; tries <= (int)KF_GEN_JOINT_PARAM_COUNT; tries++) {
        joint_vector(app, -1, 0.0f, vec);
        int r = kf_gen_joint_init(&app->joint, vec);
        if (r >= 0 || -r - 1 >= (int)KF_GEN_JOINT_PARAM_COUNT) {
            break;
        }
        uint32_t i = KF_P_JOINT_FIRST + (uint32_t)(-r - 1);
        app->values[i] = kf_param_table[i].def;
        app->cnt.stored_rejects++;
    }
    kf_leg_repair(app);
}

void kf_config_load(kf_app *app)
{
    kf_store_header h;
    for (int32_t i = 0; i < (int32_t)KF_PARAM_COUNT; i++) {
        app->values[i] = kf_param_table[i].def;
    }
    memset(app->key, 0, sizeof app->key);
    app->key_set = 0u;
    app->sign_floor = 0u;
    app->sign_reserved = 0u;
    if (kf_store_load(&app->store, &h, put_entry, app) >= 0) {
        memcpy(app->key, h.key, sizeof app->key);
        for (uint32_t i = 0; i < KF_STORE_KEY_LEN; i++) {
            app->key_set |= (uint8_t)(app->key[i] != 0u);
        }
        app->sign_floor = h.sign_timestamp;
        app->sign_reserved = h.sign_timestamp;   /* at or above every frame accepted before */
    }
    app->values[KF_P_SIGNING].u = app->key_set;
    if (!kf_param_in_range(&kf_param_table[KF_P_FILTER], app->values[KF_P_FILTER])) {
        /* the default filter is not in this build: take the first that is */
        app->values[KF_P_FILTER].u = 0u;
        for (int32_t k = KF_GEN_FILTER_COUNT - 1; k >= 0; k--) {
            if (kf_gen_filters[k].update != NULL) {
                app->values[KF_P_FILTER].u = kf_gen_filters[k].id;
            }
        }
    }
    repair_groups(app);
    update_calibrated_flag(app);
}

/* --- one parameter ---------------------------------------------------------------------- */

uint8_t kf_config_set(kf_app *app, int32_t index, kf_pvalue v)
{
    float vec[KF_GEN_CALIB_PARAM_COUNT + KF_GEN_FILTER_PARAM_MAX];
    const kf_param_desc *d;
    if (index < 0 || index >= (int32_t)KF_PARAM_COUNT) {
        return MAV_PARAM_ERROR_DOES_NOT_EXIST;
    }
    d = &kf_param_table[index];
    if ((d->flags & KF_PF_READONLY) != 0u) {
        return MAV_PARAM_ERROR_READ_ONLY;
    }
    if (!kf_param_in_range(d, v)) {
        return MAV_PARAM_ERROR_VALUE_OUT_OF_RANGE;
    }
    if (d->group == KF_PG_CALIB || d->group == KF_PG_CALIB2) {
        kf_calib_state tmp;
        uint8_t second = (uint8_t)(d->group == KF_PG_CALIB2);
        calib_vector(app, second ? KF_P_CALIB2_FIRST : KF_P_CALIB_FIRST, d->index, v.f, vec);
        if (kf_gen_calib_init(&tmp, vec) != 0) {
            return MAV_PARAM_ERROR_VALUE_OUT_OF_RANGE;   /* the generated range check */
        }
        if (second) {
            app->calib2 = tmp;
        } else {
            app->calib = tmp;
        }
    } else if (d->group == KF_PG_FILTER) {
        const kf_filter_ops *f = &kf_gen_filters[d->filter];
        filter_vector(app, d->filter, d->index, v.f, vec);
        if (filter_check(app, d->filter, vec) != 0) {
            return MAV_PARAM_ERROR_VALUE_OUT_OF_RANGE;   /* the generated range check */
        }
        if ((int32_t)d->filter == app->filter && f->set != NULL) {
            f->set(&app->filt, &app->fparams);           /* live: no reset of the estimate */
            if (app->two_sensors) {
                f->set(&app->filt2, &app->fparams);
            }
        }
    } else if (d->group == KF_PG_JOINT) {
        kf_joint_state tmp;
        joint_vector(app, d->index, v.f, vec);
        if (kf_gen_joint_init(&tmp, vec) != 0) {
            return MAV_PARAM_ERROR_VALUE_OUT_OF_RANGE;   /* the generated range check */
        }
        app->joint = tmp;                                /* the step holds no estimate: restart */
    } else if (d->group == KF_PG_LEG) {
        uint8_t err = kf_leg_set_param(app, d->index, v.f);   /* live, as a filter's */
        if (err != 0u) {
            return err;
        }
    }
    uint32_t old = app->values[index].u;
    app->values[index] = v;
    if (old != v.u) {
        if (d->group == KF_PG_JOINT) {
            kf_leg_axes(app);                  /* the sensor-to-segment offsets feed the leg EKF too */
        }
        switch (index) {
        case KF_P_FILTER:
            kf_config_select_filter(app);
            break;
        case KF_P_JOINT_ID:
            if ((old != 0u) != (v.u != 0u)) {
                kf_config_reset_filter(app);   /* into or out of two-sensor mode */
            }
            break;
        case KF_P_EFF_RATE_HZ:
            (void)kf_config_apply_rates(app);
            if ((old != 0u) != (v.u != 0u)) {
                kf_leg_reset(app);             /* the leg EKF on (from its start) or off */
            }
            break;
        case KF_P_RATE_HZ:
            if (kf_config_apply_rates(app) != 0) {
                app->values[index].u = old;    /* the sensor cannot deliver it: keep the old rate */
                (void)kf_config_apply_rates(app);
                return MAV_PARAM_ERROR_VALUE_OUT_OF_RANGE;
            }
            break;
        case KF_P_ORI_RATE_HZ:
        case KF_P_HRIMU_RATE:
        case KF_P_ATTQ_RATE:
            (void)kf_config_apply_rates(app);
            break;
        default:
            break;
        }
        update_calibrated_flag(app);
        (void)kf_config_save(app);   /* a failure is counted in store.errors */
    }
    return 0u;
}
