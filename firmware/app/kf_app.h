/*
 * kf_app.h - the kinefuse unit application: sensor samples in, calibration, the selected
 * filter, MAVLink 2 out; parameters, commands, time sync, signing and HIL input over the link.
 *
 * All state lives in one kf_app object (no globals): a port allocates it statically, calls
 * kf_app_init() at reset and kf_app_poll() from its main loop.  Nothing allocates; every
 * buffer has a fixed size; every length and value received is checked before use.
 *
 * Clock: time_boot_us is the HAL's microsecond clock extended to 64 bits (never reset while
 * running).  Samples: sample_counter counts every sample processed since boot (or since
 * MAV_CMD_KF_STREAM with reset); the first sample has counter 0.
 */
#ifndef KF_APP_H
#define KF_APP_H

#include <stdint.h>

#include "kf_filters.h"
#include "kf_hal.h"
#include "kf_link.h"
#include "kf_mavlink.h"
#include "kf_params.h"
#include "kf_store.h"
#include "kf_tx.h"

/* One sample entering the pipeline (from the sensor or from HIL_SENSOR). */
typedef struct {
    uint64_t time_us;      /* device clock, us since boot */
    int16_t acc[3];        /* counts (KF_RAW_SAMPLE units unless the calibration scale says otherwise) */
    int16_t gyr[3];        /* KF_RAW_SAMPLE gyro fields: units of 2^gyro_shift counts */
    int16_t gyr_cal[3];    /* the calibration map's gyro input: 1-count units, saturated (= gyr
                            * when gyro_shift is 0) */
    int16_t mag[3];
    int16_t temperature;   /* cdegC */
    uint8_t mag_valid;
    uint8_t flags;         /* KF_RAW_SAMPLE_FLAGS_* known at input (clipped, simulated, temperature) */
    uint8_t direct;        /* 1: use f_* below instead of counts + calibration (HIL direct mode) */
    uint8_t gyro_shift;    /* KF_RAW_SAMPLE.gyro_shift: 0 (sensor samples), 0..3 (HIL) */
    float f_gyr[3];        /* rad/s */
    float f_acc[3];        /* m/s^2 */
    float f_mag[3];        /* uT */
} kf_sample;

typedef struct {
    uint32_t samples;            /* samples processed */
    uint32_t samples_dropped;    /* sensor samples lost before processing (HAL FIFO overrun) */
    uint32_t rejected_base;      /* rejections of previous filter instances (sensor 0: reported) */
    uint32_t rejected2_base;     /* the same for sensor 1's instance (two-sensor mode) */
    uint32_t unknown_messages;   /* valid frames not handled + candidates with unknown ids */
    uint32_t param_rejects;
    uint32_t unsigned_refused;   /* unsigned configuration/commands refused (key set) */
    uint32_t signature_failures; /* signed frames whose signature or timestamp failed */
    uint32_t hil_invalid;        /* HIL_SENSOR samples with NaN values or an unknown sensor id (not processed) */
    uint32_t numeric_resets;     /* a filter (either sensor's) re-initialised after a non-finite output */
    uint32_t stored_rejects;     /* stored values out of range at load (defaults used) */
} kf_counters;

typedef struct {
    uint32_t samples, raw, ori;  /* counted since the previous status */
    uint64_t t0;                 /* start of the interval */
    uint64_t busy_us;            /* time spent working in kf_app_poll */
    float sensor_hz, raw_hz, ori_hz;
    uint16_t load;               /* d% */
    uint32_t frames_dropped0;    /* tx.frames_dropped at the previous status (TX_OVERFLOW) */
    uint32_t store_errors0;      /* store.errors when the last storage STATUSTEXT was queued */
    uint32_t store_errors_st0;   /* store.errors at the previous status (STORAGE_ERROR) */
    uint32_t stored_rejects0;    /* cnt.stored_rejects at the previous status (STATUSTEXT) */
} kf_rates;

typedef struct kf_app {
    /* configuration */
    kf_pvalue values[KF_PARAM_COUNT];
    kf_store store;
    uint8_t key[KF_STORE_KEY_LEN];
    uint8_t key_set;
    uint8_t sign_saved;            /* a save moved sign_reserved ahead since reset */
    uint64_t sign_floor;           /* new signing streams must be newer than this */
    uint64_t sign_reserved;        /* signing timestamp of the newest stored copy: no accepted
                                    * signed frame is newer (kf_handle.c reserve_timestamp) */
    uint64_t sign_saved_us;        /* device time of the last such save */

    /* link */
    kf_link rx;
    kf_tx tx;
    mavlink_status_t tx_status;    /* sequence numbers of what we send */
    mavlink_signing_t signing;
    mavlink_signing_streams_t sign_streams;
    int32_t list_next;             /* next PARAM_VALUE of a PARAM_REQUEST_LIST, -1: none */

    /* clock */
    uint32_t clock_last32;
    uint64_t clock_now;

    /* estimation */
    kf_calib_state calib;
    kf_filter_state_u filt;
    kf_filter_state_u scratch;     /* parameter validation without touching the running filter */
    kf_filter_params_u fparams;
    int32_t filter;                /* index in kf_gen_filters, -1: none */
    int32_t mode_param;            /* the active filter's 6D/9D `mode` switch in values, -1: none */
    kf_filter_out out;
    kf_imu_input last_in;          /* last filter input (HIGHRES_IMU) */
    uint8_t initialised;
    uint8_t numeric_reset;         /* sensor 0's filter reset: reported once in KF_ORIENTATION.status */
    uint8_t joint_reset;           /* either sensor's filter reset: once in KF_JOINT_ANGLE.status */
    uint8_t mag_present;           /* a magnetometer reading of sensor 0 arrived since boot */
    uint8_t clipped;               /* a clipped sample since the previous KF_ORIENTATION */
    uint8_t mag_seen;              /* a magnetometer reading reached the filter since then */
    uint8_t calibrated;            /* calibration differs from the defaults */
    float tare[4];                 /* applied to the output: q_out = tare * q */
    uint8_t tared;

    /* two-sensor mode (KF_JOINT_ID != 0): sensor 1 (distal) has its own calibration map
     * (KF_ACC2/GYR2/MAG2_*, the same generated calib_apply) and its own instance of the selected
     * filter (same parameters); the joint step combines both */
    kf_calib_state calib2;
    kf_filter_state_u filt2;
    kf_filter_out out2;
    kf_joint_state joint;
    kf_joint_out jout;
    uint64_t t_prev2;
    uint8_t have_prev2;
    uint8_t initialised2;
    uint8_t two_sensors;

    /* leg EKF (two-sensor mode with KF_EFF_RATE_HZ != 0; float32 builds, see kf_leg.c): hip and
     * knee torques from both sensors' calibrated gyroscope and accelerometer, KF_EFFORTS */
#if KF_HAVE_LEG
    kf_leg_state leg;
    kf_leg_output lout;
    float leg_axes[2][3][3];       /* per sensor: rows giving the leg inputs (gyr, acc along, acc
                                    * anterior) from the sensor-frame vectors (KF_JA_* offsets) */
    kf_imu_input last_in2;         /* sensor 1's last calibrated sample */
    uint8_t flags2;                /* ... its KF_RAW_SAMPLE_FLAGS (clipping) */
    uint8_t fresh2;                /* 1: it arrived after the previous leg step */
    int32_t leg_rejected;          /* lout.rejected before the last step */
#endif
    uint8_t leg_on;                /* the leg EKF runs (two sensors, KF_EFF_RATE_HZ != 0, built) */
    uint8_t eff_status;            /* KF_EFFORTS_STATUS bits gathered since the last KF_EFFORTS */

    /* samples and streams */
    uint32_t sample_counter;
    uint64_t t_prev;
    uint8_t have_prev;
    uint8_t hil;
    uint8_t streaming;
    uint16_t div_ori, div_hr, div_aq, div_eff;   /* every n-th sample (0: off) */
    uint16_t cnt_ori, cnt_hr, cnt_aq, cnt_eff;

    /* health */
    uint64_t sensor_last_us;       /* device time of sensor 0's last sample (or of its rate setting) */
    uint64_t sensor2_last_us;      /* sensor 1's (or of the rate setting, or of two-sensor mode's start) */
    uint32_t sensor_timeout_us;    /* SENSOR_FAULT after this long without a sample (0: no sensor) */
    uint8_t sensor_fault;          /* a watched sensor is silent now (kf_app.c) */
    uint8_t sensor_fault_seen;     /* ... or was at some time since the previous 1 Hz status */
    uint8_t low_battery;           /* the 1 Hz battery reading fell below KF_BATT_LOW_MV (kf_status.c) */
    uint8_t low_battery_told;      /* ... and its STATUSTEXT went out */
    kf_counters cnt;
    kf_rates rates;
    uint64_t next_status_us;
    uint8_t reboot;                /* a reboot was requested: the port restarts after the flush */
} kf_app;

/* Reset: load the stored configuration (or defaults), set up filter, calibration and link. */
void kf_app_init(kf_app *app);

/* One turn of the main loop: receive and handle frames, take sensor samples, send what is
 * due.  Returns 1 when it did something (the port may sleep otherwise). */
int kf_app_poll(kf_app *app);

/* Process one sample (the sensor path and HIL_SENSOR both end here). */
void kf_app_sample(kf_app *app, const kf_sample *s);

/* Two-sensor mode: one sample of sensor 1 (the distal segment; kf_hal_sensor2_read or
 * HIL_SENSOR id 1): its own calibration map (KF_ACC2/GYR2/MAG2_*), then its own filter instance.  Nothing is sent for it; the
 * next sample of sensor 0 sends KF_JOINT_ANGLE with both filters' latest orientations (and,
 * with the leg EKF on, steps it with both sensors' samples and sends KF_EFFORTS). */
void kf_app_sample2(kf_app *app, const kf_sample *s);

/* Current device time, us since boot (64 bits). */
uint64_t kf_app_time(kf_app *app);

#endif /* KF_APP_H */
