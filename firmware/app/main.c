/*
 * main.c — the target's entry point: crt0 calls main(), which runs the frame loop (app.c). The
 * host build (bsp/host) has its own main() that parses options first.
 */
#include "app/app.h"

int main(void)
{
    return app_run();
}
