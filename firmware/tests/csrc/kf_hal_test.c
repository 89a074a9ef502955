/*
 * kf_hal_test.c - kf_hal.h for in-process tests (cffi): UART = two byte buffers, clock set by
 * the test, storage = RAM with a write budget (a simulated power cut stops every write after
 * the budget, mid-call if need be), sensor = a queue the test fills.
 */
#include <stdint.h>
#include <string.h>

#include "kf_app_internal.h"
#include "kf_hal_test.h"

#define T_UART 65536u
#define T_STORAGE 8192u
#define T_SENSOR 256u

static uint8_t g_rx[T_UART];
static uint32_t g_rx_len, g_rx_pos;
static uint8_t g_tx[T_UART];
static uint32_t g_tx_len;
static uint32_t g_tx_limit = T_UART;   /* bytes the UART accepts per call */
static uint32_t g_now;
static uint8_t g_storage[T_STORAGE];
static uint32_t g_storage_size = 4096u;
static int64_t g_budget = -1;           /* bytes that may still be written (-1: unlimited) */
static uint32_t g_written;
/* the sensors' FIFOs: [0] kf_hal_sensor_read, [1] kf_hal_sensor2_read */
typedef struct {
    kf_raw_sample s[T_SENSOR];
    uint32_t head, tail;
} sensor_fifo;
static sensor_fifo g_sensor[2];
static int g_reboots;
static int32_t g_grant = -1;            /* kf_hal_sensor_configure: -1 no sensor, 0 as asked, else this */
static uint32_t g_asked;                /* the rate last asked for */
static uint16_t g_battery_mv = UINT16_MAX;   /* kf_hal_battery_mv (UINT16_MAX: not measured) */

void kf_hal_init(void) {}

uint32_t kf_hal_micros(void)
{
    return g_now;
}

int32_t kf_hal_uart_read(uint8_t *buf, int32_t max)
{
    int32_t n = 0;
    while (n < max && g_rx_pos < g_rx_len) {
        buf[n++] = g_rx[g_rx_pos++];
    }
    return n;
}

int32_t kf_hal_uart_write(const uint8_t *buf, int32_t len)
{
    uint32_t n = (uint32_t)len;
    if (n > g_tx_limit) {
        n = g_tx_limit;
    }
    if (n > T_UART - g_tx_len) {
        n = T_UART - g_tx_len;
    }
    memcpy(&g_tx[g_tx_len], buf, n);
    g_tx_len += n;
    return (int32_t)n;
}

static int fifo_pop(sensor_fifo *f, kf_raw_sample *out)
{
    if (f->tail == f->head) {
        return 0;
    }
    *out = f->s[f->tail % T_SENSOR];
    f->tail++;
    return 1;
}

int kf_hal_sensor_read(kf_raw_sample *out)
{
    return fifo_pop(&g_sensor[0], out);
}

int kf_hal_sensor2_read(kf_raw_sample *out)
{
    return fifo_pop(&g_sensor[1], out);
}

uint32_t kf_hal_storage_size(void)
{
    return g_storage_size;
}

int kf_hal_storage_read(uint32_t offset, void *buf, uint32_t len)
{
    if (offset > g_storage_size || len > g_storage_size - offset) {
        return -1;
    }
    memcpy(buf, &g_storage[offset], len);
    return 0;
}

int kf_hal_storage_write(uint32_t offset, const void *buf, uint32_t len)
{
    if (offset > g_storage_size || len > g_storage_size - offset) {
        return -1;
    }
    uint32_t n = len;
    if (g_budget >= 0 && (int64_t)n > g_budget) {
        n = (uint32_t)g_budget;       /* the power fails after n bytes of this write */
    }
    memcpy(&g_storage[offset], buf, n);
    g_written += n;
    if (g_budget >= 0) {
        g_budget -= n;
    }
    return 0;                         /* the unit cannot tell: it lost power */
}

void kf_hal_reboot(void)
{
    g_reboots++;
}

int32_t kf_hal_sensor_configure(uint32_t rate_hz)
{
    g_asked = rate_hz;
    if (g_grant < 0) {
        return -1;
    }
    return g_grant == 0 ? (int32_t)rate_hz : g_grant;
}

/* --- test control ------------------------------------------------------------------------ */

uint32_t kft_app_size(void)
{
    return (uint32_t)sizeof(kf_app);
}

void kft_reset(uint32_t storage_size)
{
    g_rx_len = g_rx_pos = g_tx_len = 0u;
    g_tx_limit = T_UART;
    g_now = 0u;
    g_storage_size = storage_size <= T_STORAGE ? storage_size : T_STORAGE;
    memset(g_storage, 0xFF, sizeof g_storage);
    g_budget = -1;
    g_written = 0u;
    g_sensor[0].head = g_sensor[0].tail = g_sensor[1].head = g_sensor[1].tail = 0u;
    g_reboots = 0;
    g_grant = -1;
    g_asked = 0u;
    g_battery_mv = UINT16_MAX;
}

uint16_t kf_hal_battery_mv(void)
{
    return g_battery_mv;
}

void kft_set_battery_mv(uint16_t mv)
{
    g_battery_mv = mv;
}

uint32_t kft_feed(const uint8_t *data, uint32_t len)
{
    if (g_rx_pos == g_rx_len) {
        g_rx_pos = g_rx_len = 0u;
    }
    uint32_t n = len < T_UART - g_rx_len ? len : T_UART - g_rx_len;
    memcpy(&g_rx[g_rx_len], data, n);
    g_rx_len += n;
    return n;
}

uint32_t kft_rx_left(void)
{
    return g_rx_len - g_rx_pos;
}

uint32_t kft_take(uint8_t *out, uint32_t max)
{
    uint32_t n = g_tx_len < max ? g_tx_len : max;
    memcpy(out, g_tx, n);
    memmove(g_tx, &g_tx[n], g_tx_len - n);
    g_tx_len -= n;
    return n;
}

void kft_tx_limit(uint32_t bytes_per_call)
{
    g_tx_limit = bytes_per_call;
}

void kft_set_time(uint32_t us)
{
    g_now = us;
}

void kft_budget(int64_t bytes)
{
    g_budget = bytes;
}

uint32_t kft_written(void)
{
    return g_written;
}

uint8_t *kft_storage(void)
{
    return g_storage;
}

static int fifo_push(sensor_fifo *f, const kf_raw_sample *s)
{
    if (f->head - f->tail >= T_SENSOR) {
        return 0;
    }
    f->s[f->head % T_SENSOR] = *s;
    f->head++;
    return 1;
}

int kft_sensor_push(const kf_raw_sample *s)
{
    return fifo_push(&g_sensor[0], s);
}

int kft_sensor2_push(const kf_raw_sample *s)
{
    return fifo_push(&g_sensor[1], s);
}

int kft_reboots(void)
{
    return g_reboots;
}

void kft_sensor_grant(int32_t hz)
{
    g_grant = hz;
}

uint32_t kft_sensor_asked(void)
{
    return g_asked;
}

/* --- views of the application ------------------------------------------------------------ */

void kft_counters(const void *vapp, uint32_t out[12])
{
    const kf_app *app = (const kf_app *)vapp;
    out[0] = app->rx.crc_errors;
    out[1] = app->rx.bad_frames;
    out[2] = app->rx.unknown_ids;
    out[3] = app->cnt.unknown_messages;
    out[4] = app->cnt.param_rejects;
    out[5] = app->cnt.unsigned_refused;
    out[6] = app->cnt.signature_failures;
    out[7] = app->rx.frames_ok;
    out[8] = app->tx.frames_dropped;
    out[9] = app->cnt.samples;
    out[10] = app->store.errors;
    out[11] = app->cnt.stored_rejects;
}

/* rejection counters: sensor 0's base and instance, sensor 1's base and instance */
void kft_rejected(const void *vapp, uint32_t out[4])
{
    const kf_app *app = (const kf_app *)vapp;
    out[0] = app->cnt.rejected_base;
    out[1] = (uint32_t)app->out.rejected;
    out[2] = app->cnt.rejected2_base;
    out[3] = (uint32_t)app->out2.rejected;
}

/* what the unit does after a non-finite output of sensor 1's filter */
void kft_reset_filter2(void *vapp)
{
    kf_config_reset_filter2((kf_app *)vapp);
}

/* a non-finite filter state (every 32-bit word a NaN) for sensor 0 or 1: the next update of
 * that sensor's filter gives a non-finite quaternion, the unit's numeric reset path */
void kft_poison_filter(void *vapp, int sensor)
{
    kf_app *app = (kf_app *)vapp;
    kf_filter_state_u *f = sensor ? &app->filt2 : &app->filt;
    const uint32_t nan = 0x7FC00000u;
    for (uint32_t i = 0; i + sizeof nan <= sizeof *f; i += sizeof nan) {
        memcpy((uint8_t *)f + i, &nan, sizeof nan);
    }
}

uint32_t kft_param_count(void)
{
    return KF_PARAM_COUNT;
}

const char *kft_param_name(uint32_t i)
{
    return i < KF_PARAM_COUNT ? kf_param_table[i].name : "";
}

uint32_t kft_param_get(const void *vapp, uint32_t i)
{
    const kf_app *app = (const kf_app *)vapp;
    return i < KF_PARAM_COUNT ? app->values[i].u : 0u;
}

uint8_t kft_param_type(uint32_t i)
{
    return i < KF_PARAM_COUNT ? kf_param_table[i].type : 0u;
}

void kft_output(const void *vapp, float q[4], int32_t q_raw[4])
{
    const kf_app *app = (const kf_app *)vapp;
    memcpy(q, app->out.q, sizeof app->out.q);
    memcpy(q_raw, app->out.q_raw, sizeof app->out.q_raw);
}

void kft_app_init(void *app)
{
    kf_app_init((kf_app *)app);
}

int kft_app_poll(void *app)
{
    return kf_app_poll((kf_app *)app);
}

void kft_app_sample(void *app, const kf_sample *s)
{
    kf_app_sample((kf_app *)app, s);
}
