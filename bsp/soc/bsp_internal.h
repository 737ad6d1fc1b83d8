/* bsp_internal.h — shared between the soc BSP's own files; not part of the interface. */
#ifndef BSP_INTERNAL_H
#define BSP_INTERNAL_H

void bsp_uart_init(void);
void bsp_trap_install(void);

#endif /* BSP_INTERNAL_H */
