/*
 * kf_host.h - settings of the host (software-in-the-loop) port, filled by its main before
 * kf_hal_init().  POSIX only.
 */
#ifndef KF_HOST_H
#define KF_HOST_H

#include <stdint.h>

typedef struct {
    int uart_in;              /* fd the UART reads (non-blocking) */
    int uart_out;             /* fd the UART writes (non-blocking) */
    const char *storage_path; /* file backing kf_hal_storage_* (created, 0xFF-filled) */
    uint32_t storage_size;
    int64_t storage_fail_after; /* >= 0: power cut (process exit 75) after this many bytes */
    int sensor;               /* 1: synthetic sensor (kf_host_sensor.c), 0: none */
    uint64_t max_samples;     /* synthetic sensor stops after this many samples (0: never) */
    uint64_t gap_after;       /* after this many samples the sensor is silent for gap_us, */
    uint32_t gap_us;          /* then resumes (once; 0: no gap) - a stalled sensor */
} kf_host_config;

extern kf_host_config kf_host;

/* 1 once after kf_hal_reboot() was called (the main loop then re-initialises the app). */
int kf_host_take_reboot(void);

/* Microseconds until the synthetic sensor's next sample is due (for the main loop's wait). */
uint32_t kf_host_sensor_wait_us(void);

#endif /* KF_HOST_H */
