/*
 * kf_hal_host.c - kf_hal.h on a POSIX host: the software-in-the-loop unit.
 *
 * UART = a file descriptor pair (pty master, or stdin/stdout), non-blocking; clock =
 * CLOCK_MONOTONIC in microseconds since the last reset; storage = a file (or RAM); sensor =
 * the synthetic IMU of kf_host_sensor.c at the rate the application configures, with the
 * sample times it would have on hardware (exact multiples of the period) and a 1024-sample
 * FIFO: samples older than that when the application comes to read them are dropped and
 * counted, as a sensor FIFO overrun would.
 * The port's state is this file's statics: one process, one unit.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "kf_hal.h"
#include "kf_host.h"
#include "kf_host_sensor.h"

#define KF_HOST_FIFO_SAMPLES 1024u
#define KF_HOST_RAM_STORAGE 65536u

kf_host_config kf_host = {0, 1, NULL, 4096u, -1, 1, 0u, 0u, 0u};

static uint64_t g_t0_ns;                 /* monotonic time of the last reset */
static int g_storage_fd = -1;
static uint8_t g_ram_storage[KF_HOST_RAM_STORAGE];
static int64_t g_storage_written;        /* bytes written since start (power-cut simulation) */
static int g_reboot;

static uint32_t g_rate;                  /* sensor rate (0: not configured) */
static uint64_t g_sensor_t0;             /* device time (us) when the rate was set */
static uint64_t g_k;                     /* next sample index since then */
static uint64_t g_total;                 /* samples delivered since start */
static uint32_t g_dropped;
static uint64_t g_gap_end;               /* device time the --sensor-gap ends (0: not begun) */
static int g_gap_done;

static uint64_t mono_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

static uint64_t now_us(void)
{
    return (mono_ns() - g_t0_ns) / 1000u;
}

void kf_hal_init(void)
{
    g_t0_ns = mono_ns();
    g_rate = 0u;
    g_k = 0u;
    g_dropped = 0u;
    if (kf_host.storage_path != NULL && g_storage_fd < 0) {
        g_storage_fd = open(kf_host.storage_path, O_RDWR | O_CREAT, 0644);
        if (g_storage_fd >= 0) {
            struct stat st;
            if (fstat(g_storage_fd, &st) == 0 && (uint64_t)st.st_size < kf_host.storage_size) {
                uint8_t ff[256];
                memset(ff, 0xFF, sizeof ff);   /* like erased flash */
                for (uint32_t off = (uint32_t)st.st_size; off < kf_host.storage_size; off += sizeof ff) {
                    uint32_t n = kf_host.storage_size - off < sizeof ff ? kf_host.storage_size - off : (uint32_t)sizeof ff;
                    if (pwrite(g_storage_fd, ff, n, (off_t)off) != (ssize_t)n) {
                        break;
                    }
                }
            }
        }
    } else if (kf_host.storage_path == NULL && g_storage_written == 0) {
        memset(g_ram_storage, 0xFF, sizeof g_ram_storage);
    }
    if (kf_host.storage_path == NULL && kf_host.storage_size > KF_HOST_RAM_STORAGE) {
        kf_host.storage_size = KF_HOST_RAM_STORAGE;
    }
}

uint32_t kf_hal_micros(void)
{
    return (uint32_t)now_us();
}

int32_t kf_hal_uart_read(uint8_t *buf, int32_t max)
{
    if (max <= 0) {
        return 0;
    }
    ssize_t n = read(kf_host.uart_in, buf, (size_t)max);
    return n > 0 ? (int32_t)n : 0;   /* EAGAIN, EOF or an error: nothing this turn */
}

int32_t kf_hal_uart_write(const uint8_t *buf, int32_t len)
{
    if (len <= 0) {
        return 0;
    }
    ssize_t n = write(kf_host.uart_out, buf, (size_t)len);
    return n > 0 ? (int32_t)n : 0;   /* EAGAIN: the link is full, the app keeps the bytes */
}

int32_t kf_hal_sensor_configure(uint32_t rate_hz)
{
    if (!kf_host.sensor) {
        return -1;
    }
    if (rate_hz != g_rate && rate_hz != 0u) {
        g_rate = rate_hz;
        g_sensor_t0 = now_us();
        g_k = 0u;
    }
    return (int32_t)g_rate;
}

static uint64_t sample_time(uint64_t k)
{
    return (k * 1000000u) / g_rate;      /* exact period on average, no drift */
}

int kf_hal_sensor_read(kf_raw_sample *out)
{
    if (!kf_host.sensor || g_rate == 0u) {
        return 0;
    }
    if (kf_host.max_samples != 0u && g_total >= kf_host.max_samples) {
        return 0;
    }
    uint64_t now = now_us();
    if (kf_host.gap_us != 0u && !g_gap_done && g_total >= kf_host.gap_after) {
        /* a stalled sensor: nothing for gap_us, then the same samples go on from its end */
        if (g_gap_end == 0u) {
            g_gap_end = now + kf_host.gap_us;
        }
        if (now < g_gap_end) {
            return 0;
        }
        g_sensor_t0 = g_gap_end - sample_time(g_k);
        g_gap_done = 1;
    }
    if (g_sensor_t0 + sample_time(g_k) > now) {
        return 0;
    }
    /* FIFO overrun: keep only the newest KF_HOST_FIFO_SAMPLES */
    uint64_t due = (now - g_sensor_t0) * g_rate / 1000000u + 1u;   /* samples due so far */
    if (due > g_k + KF_HOST_FIFO_SAMPLES) {
        uint64_t lost = due - KF_HOST_FIFO_SAMPLES - g_k;
        g_dropped += (uint32_t)lost;
        g_k += lost;
        g_total += lost;
    }
    uint64_t t_rel = sample_time(g_k);
    memset(out, 0, sizeof *out);
    kf_host_sensor_sample(g_k, t_rel, out);
    out->time_us = (uint32_t)(g_sensor_t0 + t_rel);
    g_k++;
    g_total++;
    return 1;
}

uint32_t kf_hal_sensor_dropped(void)
{
    return g_dropped;
}

uint32_t kf_host_sensor_wait_us(void)
{
    if (!kf_host.sensor || g_rate == 0u) {
        return 100000u;
    }
    uint64_t now = now_us();
    uint64_t t = g_sensor_t0 + sample_time(g_k);
    if (g_gap_end != 0u && !g_gap_done) {
        t = g_gap_end;                   /* no busy loop through a --sensor-gap */
    }
    return t <= now ? 0u : (uint32_t)(t - now > 100000u ? 100000u : t - now);
}

uint32_t kf_hal_storage_size(void)
{
    return kf_host.storage_size;
}

static int range_ok(uint32_t offset, uint32_t len)
{
    return offset <= kf_host.storage_size && len <= kf_host.storage_size - offset;
}

int kf_hal_storage_read(uint32_t offset, void *buf, uint32_t len)
{
    if (!range_ok(offset, len) || (buf == NULL && len != 0u)) {
        return -1;
    }
    if (g_storage_fd < 0) {
        memcpy(buf, &g_ram_storage[offset], len);
        return 0;
    }
    return pread(g_storage_fd, buf, len, (off_t)offset) == (ssize_t)len ? 0 : -1;
}

int kf_hal_storage_write(uint32_t offset, const void *buf, uint32_t len)
{
    if (!range_ok(offset, len) || (buf == NULL && len != 0u)) {
        return -1;
    }
    uint32_t n = len;
    int cut = 0;
    if (kf_host.storage_fail_after >= 0 && g_storage_written + (int64_t)len > kf_host.storage_fail_after) {
        n = (uint32_t)(kf_host.storage_fail_after - g_storage_written);   /* power fails mid-write */
        cut = 1;
    }
    if (g_storage_fd < 0) {
        memcpy(&g_ram_storage[offset], buf, n);
    } else if (n != 0u && pwrite(g_storage_fd, buf, n, (off_t)offset) != (ssize_t)n) {
        return -1;
    }
    g_storage_written += n;
    if (cut) {
        _exit(75);
    }
    return 0;
}

void kf_hal_reboot(void)
{
    g_reboot = 1;
}

int kf_host_take_reboot(void)
{
    int r = g_reboot;
    g_reboot = 0;
    return r;
}
