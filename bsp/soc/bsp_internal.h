/* bsp_internal.h — shared between the soc BSP's own files; not part of the interface. */
#ifndef BSP_INTERNAL_H
#define BSP_INTERNAL_H

#include "rv32/trap.h"  /* bsp_trap_install and the platform's trap hooks */

void bsp_uart_init(void);

#endif /* BSP_INTERNAL_H */
