/*
 * batch_driver.c - template of the generic record-in / record-out driver (kinefuse.hil_tests.qemu.batch).
 *
 * Reads fixed-size input records from the host file kf_batch_in.bin with semihosting in
 * large blocks, calls the user's step once per record, and writes fixed-size output records
 * to kf_batch_out.bin.  Each record is copied to an 8-byte aligned buffer first, so the step
 * may cast kf_in/kf_out to float/int pointers on any core (Cortex-M0 faults on unaligned
 * access).  Output buffers start zeroed for every record: bytes the step does not write are
 * deterministic.
 * Exit status: 0 ok, 2 cannot open files, 3 host write failed, 4 trailing partial record.
 * Placeholders @...@ are replaced by Python.
 */
#include <stdint.h>
#include <string.h>

#include "semihost.h"

/* ---- user prelude ---- */
@PRELUDE@
/* ---- end of user prelude ---- */

#define KF_IN_SIZE  @IN_SIZE@u
#define KF_OUT_SIZE @OUT_SIZE@u
#define KF_BLOCK    @BLOCK@u   /* records per semihosting transfer */

static uint8_t kf_in_block[KF_BLOCK * KF_IN_SIZE] __attribute__((aligned(8)));
static uint8_t kf_out_block[KF_BLOCK * KF_OUT_SIZE] __attribute__((aligned(8)));
static uint64_t kf_in_rec[(KF_IN_SIZE + 7u) / 8u];
static uint64_t kf_out_rec[(KF_OUT_SIZE + 7u) / 8u];

static uint32_t kf_read_full(int32_t handle, uint8_t *buf, uint32_t len)
{
    uint32_t done = 0u;
    while (done < len) {
        uint32_t got = kf_sh_read(handle, buf + done, len - done);
        if (got == 0u) {
            break;
        }
        done += got;
    }
    return done;
}

int main(void)
{
    int32_t fin = kf_sh_open("kf_batch_in.bin", KF_SH_MODE_RB);
    int32_t fout = kf_sh_open("kf_batch_out.bin", KF_SH_MODE_WB);
    if (fin < 0 || fout < 0) {
        return 2;
    }
    {
        /* ---- user setup ---- */
        @SETUP@
        /* ---- end of user setup ---- */
    }
    for (;;) {
        uint32_t got = kf_read_full(fin, kf_in_block, (uint32_t)sizeof kf_in_block);
        uint32_t n = got / KF_IN_SIZE;
        for (uint32_t kf_i = 0u; kf_i < n; ++kf_i) {
            memcpy(kf_in_rec, &kf_in_block[kf_i * KF_IN_SIZE], KF_IN_SIZE);
            memset(kf_out_rec, 0, sizeof kf_out_rec);
            {
                const void *kf_in = kf_in_rec;
                void *kf_out = kf_out_rec;
                (void)kf_in;
                (void)kf_out;
                /* ---- user step ---- */
                @STEP@
                /* ---- end of user step ---- */
            }
            memcpy(&kf_out_block[kf_i * KF_OUT_SIZE], kf_out_rec, KF_OUT_SIZE);
        }
        if (n > 0u && kf_sh_write(fout, kf_out_block, n * KF_OUT_SIZE) != 0u) {
            return 3;
        }
        if (got < (uint32_t)sizeof kf_in_block) {
            if (got % KF_IN_SIZE != 0u) {
                return 4;
            }
            break;
        }
    }
    (void)kf_sh_close(fin);
    (void)kf_sh_close(fout);
    return 0;
}
