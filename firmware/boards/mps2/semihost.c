/*
 * semihost.c - ARM semihosting requests (see semihost.h).
 *
 * Thumb on M-profile uses BKPT 0xAB; r0 holds the operation, r1 a pointer to its argument
 * block, r0 returns the result.  The "memory" clobber makes the compiler write argument
 * blocks before the trap and re-read buffers after it.
 */
#include "semihost.h"

#include <stdint.h>

#define SYS_OPEN        0x01u
#define SYS_CLOSE       0x02u
#define SYS_WRITE0      0x04u
#define SYS_WRITE       0x05u
#define SYS_READ        0x06u
#define SYS_GET_CMDLINE 0x15u
#define SYS_EXIT        0x18u
#define SYS_EXIT_EXTENDED 0x20u

#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

static uint32_t sh_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

static uint32_t str_len(const char *s)
{
    uint32_t n = 0u;
    while (s[n] != '\0') {
        n++;
    }
    return n;
}

int32_t kf_sh_open(const char *path, int32_t mode)
{
    uint32_t args[3] = {(uint32_t)(uintptr_t)path, (uint32_t)mode, str_len(path)};
    return (int32_t)sh_call(SYS_OPEN, args);
}

int32_t kf_sh_close(int32_t handle)
{
    uint32_t args[1] = {(uint32_t)handle};
    return (int32_t)sh_call(SYS_CLOSE, args);
}

uint32_t kf_sh_write(int32_t handle, const void *buf, uint32_t len)
{
    uint32_t args[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)buf, len};
    return sh_call(SYS_WRITE, args);
}

uint32_t kf_sh_read(int32_t handle, void *buf, uint32_t len)
{
    uint32_t args[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)buf, len};
    /* SYS_READ returns the number of bytes NOT read. */
    return len - sh_call(SYS_READ, args);
}

void kf_sh_write0(const char *s)
{
    (void)sh_call(SYS_WRITE0, s);
}

int32_t kf_sh_get_cmdline(char *buf, uint32_t size)
{
    uint32_t args[2] = {(uint32_t)(uintptr_t)buf, size};
    return (int32_t)sh_call(SYS_GET_CMDLINE, args);
}

void kf_sh_exit(int32_t status)
{
    /* SYS_EXIT on 32-bit ARM carries no status; the extended call does. */
    uint32_t args[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status};
    (void)sh_call(SYS_EXIT_EXTENDED, args);
    (void)sh_call(SYS_EXIT, (const void *)ADP_STOPPED_APPLICATION_EXIT);
    for (;;) {
    }
}
