/*
 * kf_hal.h - the hardware abstraction the kinefuse application runs on.
 *
 * One implementation per board (firmware/boards/<board>/kf_hal_<board>.c) plus the host
 * build used for software-in-the-loop tests.  The application never touches registers.
 * All functions are non-blocking unless stated; none allocates.
 */
#ifndef KF_HAL_H
#define KF_HAL_H

#include <stdint.h>

/* One raw sensor sample as the sensor driver delivers it (counts, device time). */
typedef struct {
    uint32_t time_us;   /* device clock at sampling, microseconds (wraps at 2^32) */
    int16_t acc[3];     /* accelerometer, raw counts (scale set by parameters) */
    int16_t gyr[3];     /* gyroscope, raw counts */
    int16_t mag[3];     /* magnetometer, raw counts */
    uint8_t mag_valid;  /* 1 when mag[] holds a new magnetometer sample */
} kf_raw_sample;

/* Initialise clocks, UART and storage.  Called once at reset. */
void kf_hal_init(void);

/* Free-running microsecond clock (wraps at 2^32). */
uint32_t kf_hal_micros(void);

/* Read up to `max` received bytes; returns how many were read (0 when none is waiting). */
int32_t kf_hal_uart_read(uint8_t *buf, int32_t max);

/* Queue `len` bytes for transmission; blocks only while the transmit FIFO is full.
 * Returns the number of bytes accepted. */
int32_t kf_hal_uart_write(const uint8_t *buf, int32_t len);

/* Fetch the next sample from the on-board sensor; returns 1 if one was available.
 * Boards without a sensor (QEMU, host) return 0: samples arrive over the link instead. */
int kf_hal_sensor_read(kf_raw_sample *out);

/* Persistent storage (flash page / file / RAM).  Return 0 on success, -1 on error. */
uint32_t kf_hal_storage_size(void);
int kf_hal_storage_read(uint32_t offset, void *buf, uint32_t len);
int kf_hal_storage_write(uint32_t offset, const void *buf, uint32_t len);

/* Restart the unit (never returns on hardware; the host build may return). */
void kf_hal_reboot(void);

/* Optional functions: the application links weak defaults (firmware/app/kf_hal_optional.c)
 * that a board may override. */

/* Set the sensor output data rate; returns the rate the sensor will deliver (Hz), or -1
 * when the board has no sensor (default).  A sensor granted a rate is watched: no sample from
 * kf_hal_sensor_read for 4 periods (at least 100 ms) is KF_UNIT_STATUS SENSOR_FAULT; so is
 * the same silence of kf_hal_sensor2_read in two-sensor mode outside HIL mode. */
int32_t kf_hal_sensor_configure(uint32_t rate_hz);

/* Battery voltage in millivolts; UINT16_MAX when unknown (default). */
uint16_t kf_hal_battery_mv(void);

/* Sensor samples lost before kf_hal_sensor_read could deliver them (FIFO overrun), counted
 * since reset; 0 by default. */
uint32_t kf_hal_sensor_dropped(void);

/* Two-sensor units (KF_JOINT_ID != 0): the next sample of the second (distal) sensor, on the
 * same clock; returns 1 if one was available.  Default: no second sensor (0); HIL_SENSOR
 * with id = 1 stands in for it. */
int kf_hal_sensor2_read(kf_raw_sample *out);

/* Nothing to do in this main-loop turn (kf_app_poll returned 0): wait for the next event
 * (received byte, clock tick) if the board can; must return within about a millisecond.
 * Default: return at once (busy loop). */
void kf_hal_idle(void);

#endif /* KF_HAL_H */
