/*
 * semihost.h - ARM semihosting calls (BKPT 0xAB), enough for test programs on QEMU:
 * console and file I/O on the host, command line, exit with a status code.
 *
 * Only works under a debugger or QEMU with -semihosting-config enable=on; on a bare board the
 * BKPT instruction faults.  No state: every call is a self-contained request.
 */
#ifndef KF_SEMIHOST_H
#define KF_SEMIHOST_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Open modes of SYS_OPEN (ISO C fopen equivalents). */
#define KF_SH_MODE_RB  1   /* "rb" */
#define KF_SH_MODE_WB  5   /* "wb" */
#define KF_SH_MODE_AB  9   /* "ab" */

/* Open a host file (path relative to QEMU's working directory); ":tt" is the console.
 * Returns a handle >= 0 or -1. */
int32_t kf_sh_open(const char *path, int32_t mode);
int32_t kf_sh_close(int32_t handle);

/* Write len bytes; returns the number of bytes NOT written (0 = all written). */
uint32_t kf_sh_write(int32_t handle, const void *buf, uint32_t len);

/* Read up to len bytes; returns the number of bytes read (0 at end of file). */
uint32_t kf_sh_read(int32_t handle, void *buf, uint32_t len);

/* Write a NUL-terminated string to the debug console. */
void kf_sh_write0(const char *s);

/* Copy the command line (QEMU -semihosting-config arg=...) into buf; returns 0 on success. */
int32_t kf_sh_get_cmdline(char *buf, uint32_t size);

/* Stop the simulation; QEMU exits with `status` (SYS_EXIT_EXTENDED). */
void kf_sh_exit(int32_t status) __attribute__((noreturn));

#ifdef __cplusplus
}
#endif

#endif /* KF_SEMIHOST_H */
