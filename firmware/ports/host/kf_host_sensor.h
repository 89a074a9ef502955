/*
 * kf_host_sensor.h - a synthetic IMU for the host build: deterministic counts, exact sample
 * times (sample k at k * 1e6 / rate us after the sensor started), paced by the host clock.
 *
 * Motion: rotation about the vertical sensor z axis (+1 g on z) at 0.785 rad/s (one turn in
 * 8 s), the earth field turning with it in the sensor frame, plus pseudo-random noise of a
 * few counts on every axis.  Every value is an integer function of the sample index k, so a test
 * can recompute exactly what was sent (kinefuse.firmware.hostunit.synthetic_samples).
 */
#ifndef KF_HOST_SENSOR_H
#define KF_HOST_SENSOR_H

#include <stdint.h>

#include "kf_hal.h"

/* sample k, taken t_us after the sensor started (counts in KF_RAW_SAMPLE units); the
 * caller sets out->time_us */
void kf_host_sensor_sample(uint64_t k, uint64_t t_us, kf_raw_sample *out);

#endif /* KF_HOST_SENSOR_H */
