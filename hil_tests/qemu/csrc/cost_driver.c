/*
 * cost_driver.c - template of the per-call cost program (kinefuse.hil_tests.qemu.cost).
 *
 * Runs the user's setup once, then the call snippet K times; K comes from the semihosting
 * command line as exactly ten decimal digits, so parsing it costs the same for every K and
 * (instructions with K calls - instructions with 0 calls) / K is the cost of one call plus
 * the loop around it (a counter increment, compare and branch).  The loop index is kf_i.
 * Built with KF_COST_BASELINE the setup and call are replaced by the baseline snippet (which
 * may keep input tables referenced so they cancel out): the size difference between the two
 * programs is what the setup and call add.  Valid C99 and C++ (for C++ libraries).
 * Placeholders @...@ are replaced by Python.
 */
#include <stdint.h>

#include "semihost.h"

/* ---- user prelude ---- */
@PRELUDE@
/* ---- end of user prelude ---- */

#define KF_K_DIGITS 10

/* Keeps K's parsing in the baseline program too, so it cancels out of size deltas. */
static volatile uint32_t kf_k_sink;

static uint32_t kf_parse_k(void)
{
    char line[80];
    uint32_t k = 0u;
    uint32_t len = 0u;
    if (kf_sh_get_cmdline(line, (uint32_t)sizeof line) != 0) {
        return 0u;
    }
    while (len < (uint32_t)sizeof line && line[len] != '\0') {
        len++;
    }
    if (len < KF_K_DIGITS) {
        return 0u;
    }
    for (uint32_t i = len - KF_K_DIGITS; i < len; i++) {
        k = k * 10u + (uint32_t)(line[i] - '0');
    }
    return k;
}

int main(void)
{
    uint32_t kf_k = kf_parse_k();
    kf_k_sink = kf_k;
#ifndef KF_COST_BASELINE
    {
        /* ---- user setup ---- */
        @SETUP@
        /* ---- end of user setup ---- */
        for (uint32_t kf_i = 0u; kf_i < kf_k; ++kf_i) {
            /* ---- user call ---- */
            @CALL@
            /* ---- end of user call ---- */
        }
        /* ---- user finish ---- */
        @FINISH@
        /* ---- end of user finish ---- */
    }
#else
    {
        /* ---- user baseline ---- */
        @BASELINE@
        /* ---- end of user baseline ---- */
    }
#endif
    return 0;
}
