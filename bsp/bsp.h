/*
 * bsp.h — the platform interface: everything the firmware asks of a platform, declared once.
 *
 * Every platform implements it: bsp/qemu_virt/, bsp/soc/, bsp/host/, and the test doubles
 * tests/firmware/fake_bsp/, tests/fuzz/driver_bsp/ and tests/stress/. A platform folder is on the
 * include path before bsp/ and provides bsp_platform.h: the macros below and the definitions it
 * wants inline (static inline, for the accessors on the frame loop's path); its .c files define
 * the rest. This header includes bsp_platform.h first and then declares every function, so:
 *   - a definition whose signature differs from the prototype here is a compile error
 *     ("conflicting types") in every file that includes bsp.h;
 *   - a function a platform does not define is a link error ("undefined reference") in every
 *     program that uses it — the firmware uses all of them (app.c, main.c, gpu/gpu.c; the USB
 *     keyboard's two where it is built with FW_USB_KEYBOARD);
 *   - a missing macro is a compile error (#error below).
 * Only the frame loop (firmware/app/), the target's main() and the GPU driver's edge
 * (firmware/gpu/gpu.c) include this header; the pipeline never touches the platform.
 */
#ifndef BSP_H
#define BSP_H

#include <stdint.h>

#include "bsp_platform.h"

/* ---- macros ------------------------------------------------------------------------------- */

/* BSP_NAME       the platform's name, a string, printed in the boot banner
 * BSP_GPU_BASE   base address of the GPU's 128 KiB bus window (contract/gpu-contract.md)
 * BSP_EXIT_TRAP  exit status when a CPU trap ends the program
 * BSP_GPU_BUFFERS_MAPPED  1: bsp_gpu_buffer returns CPU-writable memory for the vertex and index
 *                buffers, so the firmware builds batches in place and compiles no staging arrays
 *                (12 KiB); 0: it may return NULL, and batches are staged and copied */
#ifndef BSP_NAME
#error "bsp_platform.h must define BSP_NAME"
#endif
#ifndef BSP_GPU_BASE
#error "bsp_platform.h must define BSP_GPU_BASE"
#endif
#ifndef BSP_EXIT_TRAP
#error "bsp_platform.h must define BSP_EXIT_TRAP"
#endif
#ifndef BSP_GPU_BUFFERS_MAPPED
#error "bsp_platform.h must define BSP_GPU_BUFFERS_MAPPED (1: bsp_gpu_buffer never returns NULL)"
#endif

/* ---- start and end ------------------------------------------------------------------------ */

/* Install the trap handler (it prints the cause, the faulting PC and the trap value and calls
 * bsp_exit(BSP_EXIT_TRAP)), set up the console. Call first in main(). Idempotent. */
void bsp_init(void);

/* End the program: 0 = success, anything else = failure with that status. exit() and returning
 * from main() reach it too (the platform's C-library hook). */
void bsp_exit(int code) __attribute__((noreturn));

/* ---- console ------------------------------------------------------------------------------ */

/* One byte from the console, or -1 when none is waiting. Never blocks. */
int bsp_uart_getc_nonblock(void);

/* One byte to the console, blocking while the transmitter is full. stdout goes here, unbuffered,
 * `\n` not translated. */
void bsp_uart_putc(char c);

/* ---- USB keyboard ------------------------------------------------------------------------- */

/* The oldest key event of a USB HID boot keyboard, taken from the platform's queue: the key's
 * usage (Keyboard/Keypad page; 0xE0..0xE7 the modifiers) in BSP_USB_KEY_USAGE_MASK, with
 * BSP_USB_KEY_PRESS set for a press and clear for a release; or -1 when none is waiting, and
 * always on a platform without a USB host. Never blocks. The first call of this or of
 * bsp_usb_state switches the port on. Only the frame loop built with FW_USB_KEYBOARD calls them,
 * so a program without that option never touches a USB host (the SoC's window is a bus error on
 * a SoC built without one). */
#define BSP_USB_KEY_USAGE_MASK 0x0FFu
#define BSP_USB_KEY_PRESS      0x100u
int bsp_usb_key_nonblock(void);

/* The USB port's state, one of enum bsp_usb_state, or -1 where the platform has no USB host. */
enum bsp_usb_state {
    BSP_USB_DETACHED = 0,      /* nothing plugged in (or the port off) */
    BSP_USB_ATTACHED = 1,      /* a device plugged in, its connection debounced */
    BSP_USB_RESETTING = 2,     /* the bus reset before enumeration */
    BSP_USB_ENUMERATING = 3,
    BSP_USB_RUNNING = 4,       /* a boot keyboard, polled: its keys arrive */
    BSP_USB_NOT_KEYBOARD = 5,  /* the device has no boot keyboard interface (until unplugged) */
    BSP_USB_BABBLE = 6,        /* the device talked out of turn: the port off until unplugged */
};
int bsp_usb_state(void);

/* ---- counters and ordering ---------------------------------------------------------------- */

/* Retired instructions, 64 bits, read consistently (a platform without such a counter returns a
 * cycle counter, and says so in its name, or 0). */
uint64_t bsp_instret(void);

/* Clock cycles, 64 bits, read consistently (RISC-V: mcycle/mcycleh). A platform without a cycle
 * counter returns 0 and says so here in its bsp_platform.h. Under QEMU the count follows the
 * emulation (with -icount, one per instruction), not a core: a board's figure is the real one. */
uint64_t bsp_cycles(void);

/* Full memory barrier: every earlier load and store is ordered before every later one (the
 * driver's fence before DOORBELL and after seeing DONE_SEQ). */
void bsp_fence(void);

/* ---- the GPU's bus window ----------------------------------------------------------------- */

/* One aligned 32-bit store / load at a byte offset of the window (offsets from gpu_regs.h).
 * Every device access of the driver goes through these. */
void bsp_gpu_write(uint32_t offset, uint32_t value);
uint32_t bsp_gpu_read(uint32_t offset);

/* n consecutive stores from offset on (the vertex and index buffer copies). */
void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n);

/* The vertex or index buffer at offset as plain CPU memory, so that a batch is built in place,
 * or NULL where the window is reached only through the accessors (batches are then staged and
 * copied). */
uint32_t *bsp_gpu_buffer(uint32_t offset);

#endif /* BSP_H */
