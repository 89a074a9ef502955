/*
 * kf_app_internal.h - functions shared by the application's source files (not an API).
 */
#ifndef KF_APP_INTERNAL_H
#define KF_APP_INTERNAL_H

#include <stdint.h>

#include "kf_app.h"

/* kf_config.c */
void kf_config_load(kf_app *app);
int kf_config_save(kf_app *app);
/* validate, apply and persist one parameter value: 0 or a MAV_PARAM_ERROR code */
uint8_t kf_config_set(kf_app *app, int32_t index, kf_pvalue value);
/* configure the sensor (its granted rate becomes KF_RATE_HZ) and the dividers: 0, or -1 when
 * the sensor delivers a rate outside KF_RATE_HZ's range */
int kf_config_apply_rates(kf_app *app);
void kf_config_select_filter(kf_app *app);
void kf_config_reset_filter(kf_app *app);
void kf_config_reset_filter2(kf_app *app);

/* kf_leg.c: the leg EKF of a two-sensor unit (float32 builds; no-ops in the others) */
void kf_leg_reset(kf_app *app);        /* leg_on from the parameters, restart, offsets */
void kf_leg_axes(kf_app *app);         /* recompute the input rows from the KF_JA_* offsets */
uint8_t kf_leg_set_param(kf_app *app, int32_t at, float v);   /* KF_LEG_* value at `at`: 0 or a MAV_PARAM_ERROR */
void kf_leg_repair(kf_app *app);       /* stored KF_LEG_* values the generated init refuses -> defaults */
void kf_leg_sample2(kf_app *app, const kf_imu_input *in, uint8_t flags);   /* sensor 1's sample */
void kf_leg_step(kf_app *app, const kf_imu_input *in0, uint8_t flags0);    /* one step at sensor 0's sample */
void kf_leg_send(kf_app *app, uint64_t t, uint32_t counter);              /* KF_EFFORTS */

/* kf_send.c: pack one message and queue it (1: queued, 0: dropped) */
int kf_send(kf_app *app, mavlink_message_t *msg);
uint8_t kf_sysid(const kf_app *app);
int kf_send_param_value(kf_app *app, int32_t index);
int kf_send_param_error(kf_app *app, const char *name16, int32_t index, uint8_t error,
                        uint8_t to_sys, uint8_t to_comp);
int kf_send_ack(kf_app *app, uint16_t command, uint8_t result, uint8_t to_sys, uint8_t to_comp);
/* STATUSTEXT (text: at most 50 characters, not chunked) */
int kf_send_statustext(kf_app *app, uint8_t severity, const char *text);
int kf_send_heartbeat(kf_app *app);
int kf_send_unit_status(kf_app *app);
int kf_send_sys_status(kf_app *app);
int kf_send_autopilot_version(kf_app *app);

/* kf_handle.c */
void kf_handle_frame(kf_app *app, const mavlink_message_t *msg);
/* install a signing key (all zero: signing off); timestamp: lowest accepted from now on */
void kf_app_set_key(kf_app *app, const uint8_t key[32], uint64_t timestamp);
/* before a commanded reboot: store the newest accepted signing timestamp itself */
void kf_app_sign_shutdown(kf_app *app);

/* kf_status.c */
void kf_status_tick(kf_app *app, uint64_t now);

/* kf_quat.c */
void kf_quat_mul(const float a[4], const float b[4], float out[4]);
/* tare quaternion (rotation about earth z) making the heading of the sensor x axis `heading`
 * rad; returns 0, or -1 when the x axis is (nearly) vertical */
int kf_quat_heading_tare(const float q[4], float heading, float tare[4]);
/* ENU earth frame -> NED earth frame (body frame unchanged) */
void kf_quat_enu_to_ned(const float q_enu[4], float q_ned[4]);

#endif /* KF_APP_INTERNAL_H */
