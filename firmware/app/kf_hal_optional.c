/*
 * kf_hal_optional.c - defaults for the optional HAL functions (kf_hal.h).  Weak, so a board
 * port overrides them by simply defining the function.
 */
#include <stdint.h>

#include "kf_hal.h"

__attribute__((weak)) int32_t kf_hal_sensor_configure(uint32_t rate_hz)
{
    (void)rate_hz;
    return -1;   /* no sensor: samples arrive over the link (HIL_SENSOR) */
}

__attribute__((weak)) uint16_t kf_hal_battery_mv(void)
{
    return UINT16_MAX;
}

__attribute__((weak)) uint32_t kf_hal_sensor_dropped(void)
{
    return 0u;
}

__attribute__((weak)) int kf_hal_sensor2_read(kf_raw_sample *out)
{
    (void)out;
    return 0;    /* no second sensor on this board */
}

__attribute__((weak)) void kf_hal_idle(void)
{
}
