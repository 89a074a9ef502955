/*
 * main.c - the kinefuse unit as a host program (software in the loop).
 *
 *   kinefuse-unit [--uart pty|stdio|PATH] [--pty-link PATH] [--storage FILE]
 *                 [--storage-size BYTES] [--no-sensor] [--max-samples N] [--wait-connect]
 *                 [--exit-after SECONDS] [--storage-fail-after BYTES] [--sensor-gap N:MS]
 *
 * --uart pty (default) creates a pseudo-terminal and prints "uart <path>" on stderr: open that
 * path as the unit's serial port (kinefuse record --port pty:<path>).  --wait-connect starts
 * the unit only when the first byte arrives (so nothing is sent before a host listens).
 * --sensor-gap N:MS: after N samples the synthetic sensor delivers nothing for MS ms, then goes
 * on (a stalled sensor, once per process: KF_UNIT_STATUS SENSOR_FAULT).
 * Exit status: 0 (signal, --exit-after, end of stdin), 2 (bad arguments or pty failure), 75
 * (simulated power cut).
 */
#define _XOPEN_SOURCE 600
#define _DEFAULT_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <sys/time.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "kf_app.h"
#include "kf_host.h"

static kf_app g_app;
static volatile sig_atomic_t g_stop;

static void on_signal(int sig)
{
    (void)sig;
    g_stop = 1;
}

static int usage(const char *msg)
{
    fprintf(stderr, "kinefuse-unit: %s\n", msg);
    return 2;
}

static int make_raw(int fd)
{
    struct termios t;
    if (tcgetattr(fd, &t) != 0) {
        return -1;
    }
    cfmakeraw(&t);
    return tcsetattr(fd, TCSANOW, &t);
}

static int open_pty(const char *link_path, int *slave_keep)
{
    int m = posix_openpt(O_RDWR | O_NOCTTY);
    if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0) {
        return -1;
    }
    const char *name = ptsname(m);
    if (name == NULL) {
        return -1;
    }
    /* keep the slave open and raw: bytes written before a host opens it are kept unmangled */
    int s = open(name, O_RDWR | O_NOCTTY);
    if (s < 0 || make_raw(s) != 0 || make_raw(m) != 0) {
        return -1;
    }
    *slave_keep = s;
    if (link_path != NULL) {
        (void)unlink(link_path);
        if (symlink(name, link_path) != 0) {
            fprintf(stderr, "kinefuse-unit: cannot create %s: %s\n", link_path, strerror(errno));
        }
    }
    fprintf(stderr, "uart %s\n", name);
    fflush(stderr);
    return m;
}

static int parse_u64(const char *s, unsigned long long *out)
{
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno != 0 || end == s || *end != '\0' || s[0] == '-') {
        return -1;
    }
    *out = v;
    return 0;
}

int main(int argc, char **argv)
{
    const char *uart = "pty";
    const char *link_path = NULL;
    int wait_connect = 0;
    double exit_after = -1.0;
    int slave_keep = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = (i + 1 < argc) ? argv[i + 1] : NULL;
        unsigned long long n;
        if (strcmp(a, "--uart") == 0 && v) {
            uart = v;
            i++;
        } else if (strcmp(a, "--pty-link") == 0 && v) {
            link_path = v;
            i++;
        } else if (strcmp(a, "--storage") == 0 && v) {
            kf_host.storage_path = v;
            i++;
        } else if (strcmp(a, "--storage-size") == 0 && v && parse_u64(v, &n) == 0 && n >= 256u && n <= 1048576u) {
            kf_host.storage_size = (uint32_t)n;
            i++;
        } else if (strcmp(a, "--storage-fail-after") == 0 && v && parse_u64(v, &n) == 0) {
            kf_host.storage_fail_after = (int64_t)n;
            i++;
        } else if (strcmp(a, "--max-samples") == 0 && v && parse_u64(v, &n) == 0) {
            kf_host.max_samples = n;
            i++;
        } else if (strcmp(a, "--sensor-gap") == 0 && v) {
            char *end;
            errno = 0;
            unsigned long long after = strtoull(v, &end, 10);
            unsigned long long ms = (*end == ':' && end[1] != '-') ? strtoull(end + 1, &end, 10) : 0u;
            if (errno != 0 || v[0] == '-' || *end != '\0' || ms == 0u || ms > 3600000u) {
                return usage("--sensor-gap needs N:MS (samples, then milliseconds 1..3600000)");
            }
            kf_host.gap_after = after;
            kf_host.gap_us = (uint32_t)(ms * 1000u);
            i++;
        } else if (strcmp(a, "--exit-after") == 0 && v) {
            char *end;
            exit_after = strtod(v, &end);
            if (*end != '\0' || !(exit_after > 0.0)) {
                return usage("--exit-after needs a positive number of seconds");
            }
            i++;
        } else if (strcmp(a, "--no-sensor") == 0) {
            kf_host.sensor = 0;
        } else if (strcmp(a, "--wait-connect") == 0) {
            wait_connect = 1;
        } else {
            return usage("bad argument (see the header of firmware/ports/host/main.c)");
        }
    }
    if (strcmp(uart, "stdio") == 0) {
        kf_host.uart_in = STDIN_FILENO;
        kf_host.uart_out = STDOUT_FILENO;
    } else if (strcmp(uart, "pty") == 0) {
        int m = open_pty(link_path, &slave_keep);
        if (m < 0) {
            return usage("cannot create a pseudo-terminal");
        }
        kf_host.uart_in = kf_host.uart_out = m;
    } else {
        int fd = open(uart, O_RDWR | O_NOCTTY);
        if (fd < 0) {
            return usage("cannot open the --uart device");
        }
        (void)make_raw(fd);
        kf_host.uart_in = kf_host.uart_out = fd;
    }
    fcntl(kf_host.uart_in, F_SETFL, fcntl(kf_host.uart_in, F_GETFL) | O_NONBLOCK);
    fcntl(kf_host.uart_out, F_SETFL, fcntl(kf_host.uart_out, F_GETFL) | O_NONBLOCK);
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);
    signal(SIGPIPE, SIG_IGN);

    if (wait_connect) {
        struct pollfd p = {kf_host.uart_in, POLLIN, 0};
        while (!g_stop && poll(&p, 1, 100) <= 0) {
        }
    }
    kf_hal_init();
    kf_app_init(&g_app);
    while (!g_stop) {
        int work = kf_app_poll(&g_app);
        if (kf_host_take_reboot()) {
            kf_hal_init();
            kf_app_init(&g_app);
            continue;
        }
        if (exit_after > 0.0 && (double)kf_app_time(&g_app) * 1e-6 >= exit_after) {
            break;
        }
        if (!work) {
            uint32_t wait = kf_host_sensor_wait_us();
            if (kf_tx_pending(&g_app.tx) != 0u && wait > 200u) {
                wait = 200u;           /* the link is full: retry soon */
            }
            if (wait > 1000u) {
                wait = 1000u;          /* status and parameter lists keep moving */
            }
            struct pollfd p = {kf_host.uart_in, POLLIN, 0};
            fd_set rd;
            struct timeval tv = {0, (long)wait};
            FD_ZERO(&rd);
            FD_SET(kf_host.uart_in, &rd);
            (void)select(kf_host.uart_in + 1, &rd, NULL, NULL, &tv);
            if (kf_host.uart_in == STDIN_FILENO && poll(&p, 1, 0) > 0
                && (p.revents & POLLHUP) != 0 && (p.revents & POLLIN) == 0) {
                break;                 /* stdin closed: the host is gone */
            }
        }
    }
    for (int i = 0; i < 1000 && kf_tx_pending(&g_app.tx) != 0u; i++) {
        (void)kf_tx_flush(&g_app.tx);
        usleep(1000);
    }
    if (slave_keep >= 0) {
        close(slave_keep);
    }
    if (link_path != NULL) {
        (void)unlink(link_path);
    }
    return 0;
}
