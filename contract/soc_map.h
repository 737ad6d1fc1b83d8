/* soc_map.h — STAND-IN written by branch socsim against the names branch `soc` generates; the `soc`
 * branch's generated file replaces it on merge (take theirs). */
#ifndef SOC_MAP_H
#define SOC_MAP_H

#define SOC_RAM_BASE              0x00000000u
#define SOC_RAM_DEFAULT_BYTES     0x00030000u
#define SOC_GPU_BASE              0x80000000u
#define SOC_UART_BASE             0x81000000u
#define SOC_UART_REG_DATA         0x0u
#define SOC_UART_REG_STATUS       0x4u
#define SOC_UART_REG_ERRORS       0x8u
#define SOC_UART_REG_DIVIDER      0xCu
#define SOC_UART_STATUS_RX_VALID_LSB  0
#define SOC_UART_STATUS_RX_VALID_MASK 0x1u
#define SOC_UART_STATUS_TX_FULL_LSB   1
#define SOC_UART_STATUS_TX_FULL_MASK  0x2u
#define SOC_UART_STATUS_TX_IDLE_LSB   2
#define SOC_UART_STATUS_TX_IDLE_MASK  0x4u
#define SOC_SYS_BASE              0x82000000u
#define SOC_SYS_REG_ID            0x00u
#define SOC_SYS_REG_CLK_HZ        0x04u
#define SOC_SYS_REG_RAM_BYTES     0x08u
#define SOC_SYS_REG_EXIT          0x0Cu
#define SOC_SYS_REG_LEDS          0x10u
#define SOC_SYS_REG_MTIME_LO      0x18u
#define SOC_SYS_REG_MTIME_HI      0x1Cu
#define SOC_SYS_REG_MTIMECMP_LO   0x20u
#define SOC_SYS_REG_MTIMECMP_HI   0x24u
#define SOC_CLK_HZ_DEFAULT        50000000u
#define SOC_UART_BAUD             115200u

#endif
