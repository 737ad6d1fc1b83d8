/*
 * uart.c — the SoC's UART (115200 8N1, contract/soc_map.h SOC_UART_*), polled (picolibc's streams
 * on it: rv32/stdio_uart.c).
 *
 * DATA: a write queues a TX byte (dropped when the TX FIFO is full, so putc waits on TX_FULL
 * first); a read returns [7:0] the byte and bit 8 "valid", popping it.
 */
#include <stdint.h>

#include "bsp.h"
#include "bsp_internal.h"

#define UART_REG(offset) BSP_MMIO32(SOC_UART_BASE, offset)

void bsp_uart_init(void)
{
    /* The divider's reset value already gives SOC_UART_BAUD at the RTL's CLK_HZ: nothing to set. */
}

void bsp_uart_putc(char c)
{
    while ((UART_REG(SOC_UART_REG_STATUS) & SOC_UART_STATUS_TX_FULL_MASK) != 0u) {
    }
    UART_REG(SOC_UART_REG_DATA) = (uint8_t)c;
}

int bsp_uart_getc_nonblock(void)
{
    const uint32_t d = UART_REG(SOC_UART_REG_DATA);  /* one read: pops the byte when valid */

    if ((d & SOC_UART_DATA_VALID_MASK) == 0u) {
        return -1;
    }
    return (int)((d & SOC_UART_DATA_BYTE_MASK) >> SOC_UART_DATA_BYTE_LSB);
}
