/*
 * usb.c — the SoC's USB keyboard host (contract/soc_map.h SOC_USB_*, docs/usb.md), polled: key
 * events from KEY, the port's state from STATUS.
 *
 * The window is decoded only on a SoC built with the USB host (soc_top USB_HOST); on another, any
 * access to it is a bus error (trap.c). So nothing here runs unless the firmware asks: app.c calls
 * these functions only when built with FW_USB_KEYBOARD, and a program that does not call them
 * links neither their code nor the flag below (-ffunction-sections, -fdata-sections,
 * --gc-sections): its image is the same as without this file.
 */
#include <stdbool.h>
#include <stdint.h>

#include "bsp.h"

#define USB_REG(offset) BSP_MMIO32(SOC_USB_BASE, offset)

/* CTRL.ENABLE written: the port resets off (nothing driven), and is switched on at first use. */
static bool usb_enabled;

static void usb_enable_once(void)
{
    if (!usb_enabled) {
        USB_REG(SOC_USB_REG_CTRL) = SOC_USB_CTRL_ENABLE;
        usb_enabled = true;
    }
}

int bsp_usb_key_nonblock(void)
{
    uint32_t k;

    usb_enable_once();
    k = USB_REG(SOC_USB_REG_KEY);  /* one read: pops the event when VALID */
    if ((k & SOC_USB_KEY_VALID_MASK) == 0u) {
        return -1;
    }
    return (int)(((k & SOC_USB_KEY_USAGE_MASK) >> SOC_USB_KEY_USAGE_LSB) |
                 (((k & SOC_USB_KEY_PRESS_MASK) != 0u) ? BSP_USB_KEY_PRESS : 0u));
}

/* STATE's numbers are enum bsp_usb_state's (0 detached .. 6 babble, usb_ls_host's states). */
int bsp_usb_state(void)
{
    usb_enable_once();
    return (int)((USB_REG(SOC_USB_REG_STATUS) & SOC_USB_STATUS_STATE_MASK) >>
                 SOC_USB_STATUS_STATE_LSB);
}
