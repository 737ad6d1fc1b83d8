/*
 * main.c — the program's entry point on every platform: crt0 (or the host's C runtime) calls
 * main(), which runs the frame loop (app.c). A platform with a command line (the host build,
 * BSP_HAS_ARGS) reads it first (bsp_args), so the BSP never calls into the application.
 */
#include "app/app.h"
#include "bsp.h"

#if BSP_HAS_ARGS
int main(int argc, char **argv)
{
    const int rc = bsp_args(argc, argv);

    return (rc != 0) ? rc : app_run();
}
#else
int main(void)
{
    return app_run();
}
#endif
