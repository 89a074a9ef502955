/*
 * selftest_io.c - one test program for the board port and the QEMU runner; the first
 * semihosting argument selects what it does:
 *   hello   "hello semihosting" on :tt, "hello console" on the debug console, "hello uart"
 *           on UART0; exits 3
 *   echo    UART0: sends "ready\n", then echoes bytes upper-cased until '!' (echoed too);
 *           exits with the number of bytes echoed (mod 128)
 *   stdin   reads :tt until end of file and writes it back reversed; exits 0
 *   reboot  storage byte 0: 0xFF (fresh) -> write 1 and reboot; 1 -> exit 42
 *   micros  busy loop; exits 0 if kf_hal_micros advanced monotonically, else 1
 *   fault   executes an undefined instruction (the fault handler exits 134)
 *   spin    loops forever (timeout test)
 */
#include <stdint.h>
#include <string.h>

#include "kf_hal.h"
#include "semihost.h"

static void mode_of(char *mode, uint32_t size)
{
    char line[64];
    mode[0] = '\0';
    if (kf_sh_get_cmdline(line, (uint32_t)sizeof line) != 0) {
        return;
    }
    const char *arg = strchr(line, ' ');   /* skip argv[0] */
    if (arg != NULL) {
        strncpy(mode, arg + 1, size - 1u);
        mode[size - 1u] = '\0';
    }
}

static int run_echo(void)
{
    uint8_t buf[16];
    uint32_t n_echoed = 0u;
    (void)kf_hal_uart_write((const uint8_t *)"ready\n", 6);
    for (;;) {
        int32_t n = kf_hal_uart_read(buf, (int32_t)sizeof buf);
        for (int32_t i = 0; i < n; i++) {
            uint8_t c = buf[i];
            if (c >= 'a' && c <= 'z') {
                c = (uint8_t)(c - 32u);
            }
            (void)kf_hal_uart_write(&c, 1);
            n_echoed++;
            if (buf[i] == '!') {
                return (int)(n_echoed & 0x7Fu);
            }
        }
    }
}

static int run_stdin(void)
{
    static uint8_t data[4096];
    uint32_t len = 0u;
    int32_t in = kf_sh_open(":tt", 0);
    int32_t out = kf_sh_open(":tt", 4);
    for (;;) {
        uint32_t got = kf_sh_read(in, &data[len], (uint32_t)sizeof data - len);
        if (got == 0u) {
            break;
        }
        len += got;
    }
    for (uint32_t i = 0u; i < len / 2u; i++) {
        uint8_t t = data[i];
        data[i] = data[len - 1u - i];
        data[len - 1u - i] = t;
    }
    return kf_sh_write(out, data, len) == 0u ? 0 : 1;
}

static int run_reboot(void)
{
    uint8_t flag = 0u;
    if (kf_hal_storage_read(0u, &flag, 1u) != 0) {
        return 1;
    }
    if (flag == 0xFFu) {
        flag = 1u;
        if (kf_hal_storage_write(0u, &flag, 1u) != 0) {
            return 2;
        }
        kf_hal_reboot();
        return 3;   /* not reached */
    }
    /* out-of-range accesses must fail */
    if (kf_hal_storage_write(kf_hal_storage_size(), &flag, 1u) != -1) {
        return 4;
    }
    return flag == 1u ? 42 : 5;
}

static int run_micros(void)
{
    uint32_t first = kf_hal_micros();
    uint32_t prev = first;
    for (uint32_t i = 0u; i < 200000u; i++) {
        uint32_t now = kf_hal_micros();
        if ((int32_t)(now - prev) < 0) {
            return 1;
        }
        prev = now;
    }
    return prev != first ? 0 : 2;
}

int main(void)
{
    char mode[16];
    mode_of(mode, (uint32_t)sizeof mode);
    kf_hal_init();
    if (strcmp(mode, "hello") == 0) {
        int32_t out = kf_sh_open(":tt", 4);
        (void)kf_sh_write(out, "hello semihosting\n", 18u);
        kf_sh_write0("hello console\n");
        (void)kf_hal_uart_write((const uint8_t *)"hello uart\n", 11);
        return 3;
    }
    if (strcmp(mode, "echo") == 0) {
        return run_echo();
    }
    if (strcmp(mode, "stdin") == 0) {
        return run_stdin();
    }
    if (strcmp(mode, "reboot") == 0) {
        return run_reboot();
    }
    if (strcmp(mode, "micros") == 0) {
        return run_micros();
    }
    if (strcmp(mode, "fault") == 0) {
        __asm__ volatile("udf #0");
    }
    if (strcmp(mode, "spin") == 0) {
        for (;;) {
            __asm__ volatile("nop");
        }
    }
    return 99;
}
