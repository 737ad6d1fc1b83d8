/*
 * rv32/stdio_uart.c — picolibc's stdin/stdout/stderr on the platform's UART (bsp_uart_putc,
 * bsp_uart_getc_nonblock). picolibc does not define the standard streams; a BSP must. Output is
 * unbuffered and '\n' is sent as is (no CR added), so a captured log compares byte for byte.
 */
#include <stdio.h>

#include "bsp.h"

static int uart_stream_put(char c, FILE *stream)
{
    (void)stream;
    bsp_uart_putc(c);
    return (unsigned char)c;
}

static int uart_stream_get(FILE *stream)
{
    int c;

    (void)stream;
    do {
        c = bsp_uart_getc_nonblock();
    } while (c < 0);
    return c;
}

static FILE uart_stream = FDEV_SETUP_STREAM(uart_stream_put, uart_stream_get, NULL, _FDEV_SETUP_RW);

FILE *const stdin = &uart_stream;
FILE *const stdout = &uart_stream;
FILE *const stderr = &uart_stream;
