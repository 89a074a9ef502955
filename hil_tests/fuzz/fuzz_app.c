/*
 * fuzz_app.c - coverage-guided fuzz target of the unit application's receive path: the frame
 * parser (kf_link), message handling, the parameter handler and the parameter storage.
 *
 * One input = one life of a unit:
 *   byte 0..1   storage write budget in bytes (little endian; 0xFFFF: unlimited): a power
 *               cut after that many bytes written, possibly in the middle of a write;
 *   rest        bytes arriving on the UART, delivered in chunks of 1..64 bytes (chunk sizes
 *               derived from the data), the clock advancing 1 ms per main-loop turn.
 * After the bytes are consumed the unit is "powered up again" from the same storage.
 *
 * Invariants (abort = finding):
 *   - every parameter value is within its descriptor's range while running and after the
 *     restart (random or hostile PARAM_SETs never leave the unit misconfigured);
 *   - the restarted unit's values are, per parameter, its default or a value that was in
 *     effect before the cut (stored values are never invented);
 *   - the transmit path never writes outside its buffer (ASan) and nothing is undefined
 *     (UBSan) - checked by the sanitizers, not here.
 *
 * Build: libFuzzer (clang -fsanitize=fuzzer,address,undefined) or, with -DKF_FUZZ_REPLAY, a
 * main() that replays files given on the command line (gcc + sanitizers in the test suite).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kf_app.h"
#include "kf_params.h"

#define F_STORAGE 4096u

static const uint8_t *g_rx;
static uint32_t g_rx_len, g_rx_pos, g_rx_chunk;
static uint32_t g_now;
static uint8_t g_storage[F_STORAGE];
static int64_t g_budget;
static kf_app g_app, g_app2;
static uint8_t g_seen[KF_PARAM_COUNT];      /* 1 when a non-default value was in effect */
static uint32_t g_seen_val[KF_PARAM_COUNT][8];
static uint8_t g_seen_n[KF_PARAM_COUNT];
static uint32_t g_inputs_changed, g_inputs_restored;   /* statistics for the replay report */

void kf_hal_init(void) {}

uint32_t kf_hal_micros(void)
{
    return g_now;
}

int32_t kf_hal_uart_read(uint8_t *buf, int32_t max)
{
    uint32_t n = g_rx_len - g_rx_pos;
    if (n > g_rx_chunk) {
        n = g_rx_chunk;
    }
    if (max < 0) {
        abort();
    }
    if (n > (uint32_t)max) {
        n = (uint32_t)max;
    }
    memcpy(buf, g_rx + g_rx_pos, n);
    g_rx_pos += n;
    return (int32_t)n;
}

int32_t kf_hal_uart_write(const uint8_t *buf, int32_t len)
{
    volatile uint8_t sink = 0u;
    if (len < 0) {
        abort();
    }
    for (int32_t i = 0; i < len; i++) {
        sink ^= buf[i];          /* touch every byte: ASan sees reads past the buffer */
    }
    (void)sink;
    return len;
}

int kf_hal_sensor_read(kf_raw_sample *out)
{
    (void)out;
    return 0;
}

uint32_t kf_hal_storage_size(void)
{
    return F_STORAGE;
}

int kf_hal_storage_read(uint32_t offset, void *buf, uint32_t len)
{
    if (offset > F_STORAGE || len > F_STORAGE - offset) {
        return -1;
    }
    memcpy(buf, &g_storage[offset], len);
    return 0;
}

int kf_hal_storage_write(uint32_t offset, const void *buf, uint32_t len)
{
    if (offset > F_STORAGE || len > F_STORAGE - offset) {
        return -1;
    }
    uint32_t n = len;
    if (g_budget >= 0 && (int64_t)n > g_budget) {
        n = (uint32_t)g_budget;             /* power fails after n bytes of this write */
    }
    memcpy(&g_storage[offset], buf, n);
    if (g_budget >= 0) {
        g_budget -= n;
    }
    return 0;
}

void kf_hal_reboot(void) {}

static void check_ranges(const kf_app *app, const char *when)
{
    for (uint32_t i = 0u; i < KF_PARAM_COUNT; i++) {
        if (!kf_param_in_range(&kf_param_table[i], app->values[i])) {
            fprintf(stderr, "fuzz_app: %s: %s = 0x%08lx out of range\n", when,
                    kf_param_table[i].name, (unsigned long)app->values[i].u);
            abort();
        }
    }
}

static void remember(const kf_app *app)
{
    for (uint32_t i = 0u; i < KF_PARAM_COUNT; i++) {
        uint32_t v = app->values[i].u;
        uint8_t known = 0u;
        for (uint8_t k = 0u; k < g_seen_n[i]; k++) {
            known |= (uint8_t)(g_seen_val[i][k] == v);
        }
        if (!known && g_seen_n[i] < 8u) {
            g_seen_val[i][g_seen_n[i]++] = v;
        } else if (!known) {
            g_seen[i] = 1u;                 /* too many distinct values: do not check */
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2u || size > 65536u) {
        return 0;
    }
    uint32_t budget = (uint32_t)data[0] | ((uint32_t)data[1] << 8);
    g_budget = budget == 0xFFFFu ? -1 : (int64_t)budget;
    memset(g_storage, 0xFF, sizeof g_storage);
    memset(g_seen, 0, sizeof g_seen);
    memset(g_seen_n, 0, sizeof g_seen_n);
    g_rx = data + 2;
    g_rx_len = (uint32_t)(size - 2u);
    g_rx_pos = 0u;
    g_now = 1000u;

    kf_app_init(&g_app);
    check_ranges(&g_app, "after init");
    remember(&g_app);
    uint32_t turns = 0u;
    while (g_rx_pos < g_rx_len && turns < 100000u) {
        g_rx_chunk = 1u + (uint32_t)(g_rx[g_rx_pos] % 64u);
        (void)kf_app_poll(&g_app);
        g_now += 1000u;
        turns++;
        check_ranges(&g_app, "while running");
        remember(&g_app);
    }
    for (int k = 0; k < 8; k++) {           /* let pending answers and saves go out */
        (void)kf_app_poll(&g_app);
        g_now += 1000u;
    }
    check_ranges(&g_app, "at the power cut");
    remember(&g_app);

    /* power up again from the same storage; no more bytes arrive */
    g_budget = -1;
    g_rx_len = g_rx_pos = 0u;
    kf_app_init(&g_app2);
    check_ranges(&g_app2, "after the restart");
    uint8_t changed = 0u, restored = 0u;
    for (uint32_t i = 0u; i < KF_PARAM_COUNT; i++) {
        changed |= (uint8_t)(g_seen_n[i] > 1u || g_app.values[i].u != kf_param_table[i].def.u);
        restored |= (uint8_t)(g_app2.values[i].u != kf_param_table[i].def.u);
    }
    g_inputs_changed += changed;
    g_inputs_restored += restored;
    for (uint32_t i = 0u; i < KF_PARAM_COUNT; i++) {
        uint32_t v = g_app2.values[i].u;
        uint8_t ok = (uint8_t)(g_seen[i] || v == kf_param_table[i].def.u);
        for (uint8_t k = 0u; k < g_seen_n[i]; k++) {
            ok |= (uint8_t)(g_seen_val[i][k] == v);
        }
        if (!ok) {
            fprintf(stderr, "fuzz_app: after the restart %s = 0x%08lx was never in effect\n",
                    kf_param_table[i].name, (unsigned long)v);
            abort();
        }
    }
    return 0;
}

#ifdef KF_FUZZ_REPLAY
int main(int argc, char **argv)
{
    static uint8_t buf[65536];
    for (int a = 1; a < argc; a++) {
        FILE *f = fopen(argv[a], "rb");
        if (f == NULL) {
            fprintf(stderr, "fuzz_app: cannot open %s\n", argv[a]);
            return 2;
        }
        size_t n = fread(buf, 1u, sizeof buf, f);
        fclose(f);
        (void)LLVMFuzzerTestOneInput(buf, n);
    }
    printf("fuzz_app: %d inputs replayed; %lu changed parameters, %lu restarted with stored "
           "non-default values\n", argc - 1, (unsigned long)g_inputs_changed,
           (unsigned long)g_inputs_restored);
    return 0;
}
#endif
