/*
 * say.h — text on the SoC's UART for bare-metal programs without the firmware's stdio: the boot
 * program and the SoC's test programs. Busy-waits on TX_FULL, so nothing is dropped.
 */
#ifndef SAY_H
#define SAY_H

#include <stdint.h>

void say_char(char c);
void say(const char *s);
void say_dec(uint32_t v);
void say_hex(uint32_t v);  /* "0x" and eight digits */
void say_drain(void);      /* until everything written has left the pin */

#endif /* SAY_H */
