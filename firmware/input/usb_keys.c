/*
 * usb_keys.c — see usb_keys.h.
 */
#include "input/usb_keys.h"

/* Usages 0x04..0x38 of the US layout, one character each, without and with Shift; '\0' where the
 * key sends nothing (0x32, the non-US # ~, which a US keyboard does not have). */
#define USB_KEYS_CHAR_FIRST 0x04u
#define USB_KEYS_CHAR_LAST  0x38u
static const char usb_keys_plain[] =
    "abcdefghijklmnopqrstuvwxyz"    /* 0x04..0x1D */
    "1234567890"                    /* 0x1E..0x27 */
    "\r\x1b\x7f\t "                 /* 0x28..0x2C Enter, Escape, Backspace, Tab, Space */
    "-=[]\\\0;'`,./";               /* 0x2D..0x38 */
static const char usb_keys_shifted[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
    "!@#$%^&*()"
    "\r\x1b\x7f\t "
    "_+{}|\0:\"~<>?";
_Static_assert(sizeof usb_keys_plain - 1u == USB_KEYS_CHAR_LAST - USB_KEYS_CHAR_FIRST + 1u,
               "one plain character per usage 0x04..0x38");
_Static_assert(sizeof usb_keys_shifted == sizeof usb_keys_plain,
               "one shifted character per usage 0x04..0x38");

/* The arrows, usages 0x4F..0x52 (right, left, down, up): the final byte of ESC [ x. */
#define USB_KEYS_ARROW_FIRST 0x4Fu
#define USB_KEYS_ARROW_LAST  0x52u
static const char usb_keys_arrow[] = "CDBA";

/* The keypad, usages 0x54..0x63, as with Num Lock on. */
#define USB_KEYS_KEYPAD_FIRST 0x54u
#define USB_KEYS_KEYPAD_LAST  0x63u
static const char usb_keys_keypad[] = "/*-+\r1234567890.";
_Static_assert(sizeof usb_keys_keypad - 1u == USB_KEYS_KEYPAD_LAST - USB_KEYS_KEYPAD_FIRST + 1u,
               "one character per keypad usage 0x54..0x63");

#define USB_KEYS_ESC 0x1Bu
#define USB_KEYS_SHIFT_BITS                                                                   \
    ((1u << (USB_KEYS_LEFT_SHIFT - USB_KEYS_MODIFIER_FIRST)) |                                \
     (1u << (USB_KEYS_RIGHT_SHIFT - USB_KEYS_MODIFIER_FIRST)))

void usb_keys_init(struct usb_keys *u, uint16_t repeat_delay, uint16_t repeat_period)
{
    input_decoder_init(&u->decoder);
    u->modifiers = 0u;
    u->held = 0u;
    u->repeat_in = 0u;
    u->repeat_delay = repeat_delay;
    u->repeat_period = (repeat_period != 0u) ? repeat_period : 1u;
}

uint32_t usb_keys_bytes(uint8_t usage, bool shift, uint8_t out[USB_KEYS_MAX_BYTES])
{
    if (usage >= USB_KEYS_CHAR_FIRST && usage <= USB_KEYS_CHAR_LAST) {
        const char ch = (shift ? usb_keys_shifted : usb_keys_plain)[usage - USB_KEYS_CHAR_FIRST];

        out[0] = (uint8_t)ch;
        return (ch != '\0') ? 1u : 0u;
    }
    if (usage >= USB_KEYS_ARROW_FIRST && usage <= USB_KEYS_ARROW_LAST) {
        out[0] = USB_KEYS_ESC;
        out[1] = '[';
        out[2] = (uint8_t)usb_keys_arrow[usage - USB_KEYS_ARROW_FIRST];
        return 3u;
    }
    if (usage >= USB_KEYS_KEYPAD_FIRST && usage <= USB_KEYS_KEYPAD_LAST) {
        out[0] = (uint8_t)usb_keys_keypad[usage - USB_KEYS_KEYPAD_FIRST];
        return 1u;
    }
    return 0u;
}

/* The key's bytes, with the Shift held now, through the USB keys' decoder into the counts. */
static void usb_keys_send(struct usb_keys *u, struct input_counts *c, uint8_t usage)
{
    uint8_t bytes[USB_KEYS_MAX_BYTES];
    const uint32_t n = usb_keys_bytes(usage, (u->modifiers & USB_KEYS_SHIFT_BITS) != 0u, bytes);

    input_feed(&u->decoder, c, bytes, n);
}

void usb_keys_event(struct usb_keys *u, struct input_counts *c, uint8_t usage, bool press)
{
    if (usage >= USB_KEYS_MODIFIER_FIRST && usage <= USB_KEYS_MODIFIER_LAST) {
        const uint8_t bit = (uint8_t)(1u << (usage - USB_KEYS_MODIFIER_FIRST));

        u->modifiers = press ? (uint8_t)(u->modifiers | bit) : (uint8_t)(u->modifiers & ~bit);
        return;
    }
    if (!press) {
        if (usage == u->held) {
            u->held = 0u;  /* the repeating key let go: no more repeats */
        }
        return;
    }
    u->held = usage;
    u->repeat_in = u->repeat_delay;
    usb_keys_send(u, c, usage);
}

void usb_keys_frame(struct usb_keys *u, struct input_counts *c)
{
    if (u->repeat_delay == 0u || u->held == 0u) {
        return;
    }
    if (--u->repeat_in == 0u) {
        u->repeat_in = u->repeat_period;
        usb_keys_send(u, c, u->held);
    }
}
