/*
 * usb_keys.h — a USB HID boot keyboard's key events -> the same per-frame key counts as the UART's
 * keys (input.h). Pure code.
 *
 * A scene cannot tell which keyboard was used: a press is turned into the bytes a terminal sends
 * for that key on the US layout, and those bytes go through input.c's decoder, an instance of its
 * own (a half-received escape sequence on the UART never mixes with a USB key, nor the other way
 * round). So every key does exactly what it does typed in a terminal, by construction, and a key
 * the UART's decoder learns later needs no change here. The mapping (usage: Keyboard/Keypad page,
 * HID Usage Tables section 10):
 *
 *   0x04..0x1D  a..z (with Shift A..Z: the decoder ignores case)
 *   0x1E..0x27  1..9, 0 (with Shift ! @ # $ % ^ & * ( ): no key, as on a terminal)
 *   0x28 Enter \r, 0x29 Escape ESC, 0x2A Backspace DEL (0x7F), 0x2B Tab \t, 0x2C Space ' '
 *   0x2D..0x38  - = [ ] \ ; ' ` , . /  with Shift _ + { } | : " ~ < > ?  (Shift + / is '?', help;
 *               0x32, the non-US # ~, sends nothing)
 *   0x4F..0x52  arrows right, left, down, up: ESC [ C, D, B, A (with or without Shift: a terminal's
 *               Shift+arrow, ESC [ 1 ; 2 A, decodes to the same arrow)
 *   0x54..0x63  the keypad as with Num Lock on: / * - + Enter 1..9 0 . (Shift ignored; Num Lock
 *               itself is not tracked: the host sends the keyboard no LED report, so its light
 *               says nothing either)
 *   0xE1, 0xE5  left and right Shift: held while either is down
 *
 * The other modifiers (Ctrl, Alt, GUI) change nothing: a key held with them sends what it sends
 * without (where a terminal would send a control character or an ESC prefix). Function and editing
 * keys, Caps Lock and every usage the table does not name send nothing. A release sends nothing;
 * a modifier's press or release only changes what is held. Escape sends
 * ESC as a terminal does, so what follows it decodes as on a terminal too (ESC then [ or Shift+O
 * starts a sequence that swallows the next key; ESC then w counts the w).
 *
 * Held keys: a USB keyboard reports a press once and a release once, it never repeats, where a
 * terminal auto-repeats a held key. Typematic repeat is here, counted in frames (the pure core has
 * no clock), off unless asked for (usb_keys_init's repeat_delay): frames are not time (a scene
 * drawn at 20 frames a second would repeat at a third of the rate of one at 60), and a repeat that
 * depends on how many frames a key stays down would make the same keys give different frames on
 * another build or scene, where the scripted runs (tests/soc/usb_keys.sh) rely on one key, one
 * action. When on: the last key pressed repeats while it is held — its bytes again with the Shift
 * held at that frame — first `repeat_delay` frames after the frame it was pressed in, then every
 * `repeat_period` frames; a modifier neither starts nor stops it, releasing another key does not
 * stop it, pressing another (even one that sends nothing) takes over.
 */
#ifndef USB_KEYS_H
#define USB_KEYS_H

#include <stdbool.h>
#include <stdint.h>

#include "input/input.h"

/* The most bytes one key sends (an arrow: ESC [ A). */
#define USB_KEYS_MAX_BYTES 3u

/* The modifier usages: 0xE0 + bit of the boot report's modifier byte (HID 1.11 Appendix B.1). */
#define USB_KEYS_MODIFIER_FIRST 0xE0u
#define USB_KEYS_MODIFIER_LAST  0xE7u
#define USB_KEYS_LEFT_SHIFT     0xE1u
#define USB_KEYS_RIGHT_SHIFT    0xE5u

struct usb_keys {
    struct input_decoder decoder;  /* the USB keys' own, never the UART's */
    uint8_t modifiers;             /* bit i: modifier usage 0xE0 + i is held */
    uint8_t held;                  /* the last key pressed while it is held (0: none): repeats */
    uint16_t repeat_in;            /* frames until it repeats next */
    uint16_t repeat_delay;         /* frames from a press to its first repeat; 0: no repeat */
    uint16_t repeat_period;        /* frames between repeats after that (at least 1) */
};

/* No key held, no modifier, the decoder idle; typematic repeat after `repeat_delay` frames, then
 * every `repeat_period` frames (0 is taken as 1), or none if `repeat_delay` is 0. */
void usb_keys_init(struct usb_keys *u, uint16_t repeat_delay, uint16_t repeat_period);

/* The bytes a terminal sends for `usage` pressed (with Shift held or not), the mapping above,
 * into out; returns how many (0: the key sends nothing). */
uint32_t usb_keys_bytes(uint8_t usage, bool shift, uint8_t out[USB_KEYS_MAX_BYTES]);

/* One event of the keyboard: a press adds the keys its bytes decode to into c; a modifier's press
 * or release, and a key's release, only change what is held. */
void usb_keys_event(struct usb_keys *u, struct input_counts *c, uint8_t usage, bool press);

/* Once a frame, before that frame's events: the held key's repeat, if one falls due (nothing
 * unless repeat is on). */
void usb_keys_frame(struct usb_keys *u, struct input_counts *c);

#endif /* USB_KEYS_H */
