/*
 * say.c — text on the SoC's UART (say.h).
 */
#include "say.h"

#include "soc_map.h"

#define UART_REG(r) (*(volatile uint32_t *)(uintptr_t)(SOC_UART_BASE + SOC_UART_REG_##r))

void say_char(char c)
{
    while (UART_REG(STATUS) & SOC_UART_STATUS_TX_FULL_MASK) {
    }
    UART_REG(DATA) = (uint8_t)c;
}

void say(const char *s)
{
    while (*s != '\0') {
        say_char(*s++);
    }
}

void say_dec(uint32_t v)
{
    char digits[10];
    unsigned n = 0;
    do {
        digits[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    while (n != 0u) {
        say_char(digits[--n]);
    }
}

void say_hex(uint32_t v)
{
    say("0x");
    for (int shift = 28; shift >= 0; shift -= 4) {
        say_char("0123456789abcdef"[(v >> shift) & 15u]);
    }
}

void say_drain(void)
{
    while ((UART_REG(STATUS) & SOC_UART_STATUS_TX_IDLE_MASK) == 0u) {
    }
}
