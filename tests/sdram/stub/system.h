/* system.h — what LiteDRAM's generated csr.h includes from LiteX's BSP; nothing is needed from it
 * in tests/sdram's host-side bench. */
