/*
 * kf_main.c - entry point on a board: initialise the HAL and run the application forever.
 * (The host build has its own main in firmware/ports/host.)
 */
#include "kf_app.h"

static kf_app g_app;   /* the one application instance of this board (not library state) */

int main(void)
{
    kf_hal_init();
    kf_app_init(&g_app);
    for (;;) {
        if (!kf_app_poll(&g_app)) {
            kf_hal_idle();         /* nothing to do this turn: wait for an interrupt */
        }
    }
}
