/*
 * kf_hal_test.h - control functions of the test HAL (kf_hal_test.c); the application is
 * passed as void * so the cffi declarations need no struct layout.
 */
#ifndef KF_HAL_TEST_H
#define KF_HAL_TEST_H

#include <stdint.h>

uint32_t kft_app_size(void);
void kft_reset(uint32_t storage_size);
uint32_t kft_feed(const uint8_t *data, uint32_t len);
uint32_t kft_rx_left(void);
uint32_t kft_take(uint8_t *out, uint32_t max);
void kft_tx_limit(uint32_t bytes_per_call);
void kft_set_time(uint32_t us);
void kft_budget(int64_t bytes);
uint32_t kft_written(void);
uint8_t *kft_storage(void);
int kft_sensor_push(const kf_raw_sample *s);
int kft_sensor2_push(const kf_raw_sample *s);
int kft_reboots(void);
void kft_sensor_grant(int32_t hz);
void kft_set_battery_mv(uint16_t mv);
uint32_t kft_sensor_asked(void);
void kft_rejected(const void *app, uint32_t out[4]);
void kft_reset_filter2(void *app);
void kft_poison_filter(void *app, int sensor);
void kft_counters(const void *app, uint32_t out[12]);
uint32_t kft_param_count(void);
const char *kft_param_name(uint32_t i);
uint32_t kft_param_get(const void *app, uint32_t i);
uint8_t kft_param_type(uint32_t i);
void kft_output(const void *app, float q[4], int32_t q_raw[4]);
void kft_app_init(void *app);
int kft_app_poll(void *app);

#endif /* KF_HAL_TEST_H */
