/*
 * test_usb_keys.c — the USB keyboard's keys (input/usb_keys.h) against the UART's: every usage of
 * the mapping gives the bytes of this file's own table (what a terminal sends for that key on the
 * US layout, written here apart from the module's tables) and the same key counts as those bytes
 * fed to a UART decoder (input_feed, the oracle); every other usage gives nothing; Shift (left and
 * right, in any order), releases, arrows, a mixed sequence, the two decoders' independence, and
 * the typematic repeat counted in frames.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "input/input.h"
#include "input/usb_keys.h"
#include "unit.h"

/* Usages of the Keyboard/Keypad page used by name below (HID Usage Tables 1.12, section 10). */
#define U_A          0x04u
#define U_D          0x07u
#define U_H          0x0Bu
#define U_O          0x12u
#define U_Q          0x14u
#define U_S          0x16u
#define U_W          0x1Au
#define U_1          0x1Eu
#define U_2          0x1Fu
#define U_ESCAPE     0x29u
#define U_SPACE      0x2Cu
#define U_LBRACKET   0x2Fu
#define U_SLASH      0x38u
#define U_CAPS_LOCK  0x39u
#define U_F1         0x3Au
#define U_RIGHT      0x4Fu
#define U_LEFT       0x50u
#define U_DOWN       0x51u
#define U_UP         0x52u
#define U_KP_8       0x60u
#define U_LEFT_CTRL  0xE0u
#define U_LEFT_SHIFT 0xE1u
#define U_RIGHT_SHIFT 0xE5u

/* One key of the mapping: its usage, Shift held or not, and a terminal's bytes for it. */
struct term_key {
    uint8_t usage;
    bool shift;
    const char *bytes;  /* "" for none; ESC as \x1b */
};

/* Every key but the letters (generated below: a..z, A..Z from 0x04), without and with Shift. Enter
 * is \r (a terminal in raw mode), Backspace DEL, the keypad as with Num Lock on, Shift ignored on
 * the arrows and the keypad. */
static const struct term_key term_keys[] = {
    {0x1E, false, "1"}, {0x1E, true, "!"}, {0x1F, false, "2"}, {0x1F, true, "@"},
    {0x20, false, "3"}, {0x20, true, "#"}, {0x21, false, "4"}, {0x21, true, "$"},
    {0x22, false, "5"}, {0x22, true, "%"}, {0x23, false, "6"}, {0x23, true, "^"},
    {0x24, false, "7"}, {0x24, true, "&"}, {0x25, false, "8"}, {0x25, true, "*"},
    {0x26, false, "9"}, {0x26, true, "("}, {0x27, false, "0"}, {0x27, true, ")"},
    {0x28, false, "\r"}, {0x28, true, "\r"},      /* Enter */
    {0x29, false, "\x1b"}, {0x29, true, "\x1b"},  /* Escape */
    {0x2A, false, "\x7f"}, {0x2A, true, "\x7f"},  /* Backspace */
    {0x2B, false, "\t"}, {0x2B, true, "\t"},      /* Tab */
    {0x2C, false, " "}, {0x2C, true, " "},        /* Space */
    {0x2D, false, "-"}, {0x2D, true, "_"}, {0x2E, false, "="}, {0x2E, true, "+"},
    {0x2F, false, "["}, {0x2F, true, "{"}, {0x30, false, "]"}, {0x30, true, "}"},
    {0x31, false, "\\"}, {0x31, true, "|"}, {0x33, false, ";"}, {0x33, true, ":"},
    {0x34, false, "'"}, {0x34, true, "\""}, {0x35, false, "`"}, {0x35, true, "~"},
    {0x36, false, ","}, {0x36, true, "<"}, {0x37, false, "."}, {0x37, true, ">"},
    {0x38, false, "/"}, {0x38, true, "?"},
    {0x4F, false, "\x1b[C"}, {0x4F, true, "\x1b[C"},  /* arrows: right, left, down, up */
    {0x50, false, "\x1b[D"}, {0x50, true, "\x1b[D"},
    {0x51, false, "\x1b[B"}, {0x51, true, "\x1b[B"},
    {0x52, false, "\x1b[A"}, {0x52, true, "\x1b[A"},
    {0x54, false, "/"}, {0x54, true, "/"}, {0x55, false, "*"}, {0x55, true, "*"},  /* keypad */
    {0x56, false, "-"}, {0x56, true, "-"}, {0x57, false, "+"}, {0x57, true, "+"},
    {0x58, false, "\r"}, {0x58, true, "\r"},
    {0x59, false, "1"}, {0x59, true, "1"}, {0x5A, false, "2"}, {0x5A, true, "2"},
    {0x5B, false, "3"}, {0x5B, true, "3"}, {0x5C, false, "4"}, {0x5C, true, "4"},
    {0x5D, false, "5"}, {0x5D, true, "5"}, {0x5E, false, "6"}, {0x5E, true, "6"},
    {0x5F, false, "7"}, {0x5F, true, "7"}, {0x60, false, "8"}, {0x60, true, "8"},
    {0x61, false, "9"}, {0x61, true, "9"}, {0x62, false, "0"}, {0x62, true, "0"},
    {0x63, false, "."}, {0x63, true, "."},
};
#define TERM_KEYS (sizeof term_keys / sizeof term_keys[0])

/* The table entry of (usage, shift), the letters included; false if the key sends nothing. */
static bool term_lookup(uint8_t usage, bool shift, char bytes[4])
{
    if (usage >= 0x04u && usage <= 0x1Du) {
        bytes[0] = (char)((shift ? 'A' : 'a') + (usage - 0x04u));
        bytes[1] = '\0';
        return true;
    }
    for (size_t i = 0; i < TERM_KEYS; i++) {
        if (term_keys[i].usage == usage && term_keys[i].shift == shift) {
            strcpy(bytes, term_keys[i].bytes);
            return true;
        }
    }
    return false;
}

/* The counts the UART gives for these bytes, from a decoder at rest: the oracle. */
static void uart_counts(struct input_counts *c, const char *bytes)
{
    struct input_decoder d;

    input_decoder_init(&d);
    input_counts_clear(c);
    input_feed(&d, c, (const uint8_t *)bytes, (uint32_t)strlen(bytes));
}

/* A whole key stroke on a fresh keyboard: Shift down (the given one) if asked, the key down and
 * up, Shift up; the keys counted. */
static void usb_stroke(struct usb_keys *u, struct input_counts *c, uint8_t usage, uint8_t shift_key)
{
    if (shift_key != 0u) {
        usb_keys_event(u, c, shift_key, true);
    }
    usb_keys_event(u, c, usage, true);
    usb_keys_event(u, c, usage, false);
    if (shift_key != 0u) {
        usb_keys_event(u, c, shift_key, false);
    }
}

/* Every key's count and the total the same (the failure names the usage and the key). */
static void check_same_counts(const struct input_counts *got, const struct input_counts *want,
                              uint8_t usage, bool shift, int line)
{
    for (uint32_t k = 0; k < KEY_COUNT; k++) {
        if (got->n[k] != want->n[k]) {
            unit_fail(__FILE__, line, "usage 0x%02x%s: key %u counted %u times, the UART's %u",
                      (unsigned)usage, shift ? " with Shift" : "", (unsigned)k,
                      (unsigned)got->n[k], (unsigned)want->n[k]);
        }
    }
    if (got->total != want->total) {
        unit_fail(__FILE__, line, "usage 0x%02x%s: %u keys in all, the UART's %u", (unsigned)usage,
                  shift ? " with Shift" : "", (unsigned)got->total, (unsigned)want->total);
    }
}

/* Every usage, with and without Shift (left or right): the table's bytes, the UART's counts for
 * them, the decoder at rest after the key (a w after it counts as w); a usage the table does not
 * have sends nothing. Every key input.h lists is reached by some USB key. */
void test_usb_keys_same_as_uart(void)
{
    bool reached[KEY_COUNT] = {false};

    for (uint32_t usage = 0; usage <= 0xFFu; usage++) {
        for (int s = 0; s < 2; s++) {
            const bool shift = (s != 0);
            char want_bytes[4];
            uint8_t got_bytes[USB_KEYS_MAX_BYTES];
            const uint32_t n = usb_keys_bytes((uint8_t)usage, shift, got_bytes);

            if (usage >= USB_KEYS_MODIFIER_FIRST && usage <= USB_KEYS_MODIFIER_LAST) {
                CHECK_EQ(n, 0);  /* a modifier sends nothing of its own */
                continue;
            }
            if (!term_lookup((uint8_t)usage, shift, want_bytes)) {
                if (n != 0u) {
                    unit_fail(__FILE__, __LINE__, "usage 0x%02x%s sends %u bytes, expected none",
                              (unsigned)usage, shift ? " with Shift" : "", (unsigned)n);
                }
                want_bytes[0] = '\0';
            } else if (n != strlen(want_bytes) || memcmp(got_bytes, want_bytes, n) != 0) {
                unit_fail(__FILE__, __LINE__, "usage 0x%02x%s: the bytes differ from a terminal's",
                          (unsigned)usage, shift ? " with Shift" : "");
            }
            for (int side = 0; side < (shift ? 2 : 1); side++) {
                const uint8_t shift_key = !shift ? 0u : (side == 0) ? U_LEFT_SHIFT : U_RIGHT_SHIFT;
                struct usb_keys u;
                struct input_counts got;
                struct input_counts want;

                usb_keys_init(&u, 0u, 0u);
                input_counts_clear(&got);
                usb_stroke(&u, &got, (uint8_t)usage, shift_key);
                uart_counts(&want, want_bytes);
                check_same_counts(&got, &want, (uint8_t)usage, shift, __LINE__);
                for (uint32_t k = 1; k < KEY_COUNT; k++) {
                    reached[k] = reached[k] || got.n[k] != 0u;
                }
                input_counts_clear(&got);
                usb_stroke(&u, &got, U_W, 0u);
                CHECK_EQ(got.n[KEY_FORWARD], 1);
                CHECK_EQ(got.total, 1);
            }
        }
    }
    for (uint32_t k = 1; k < KEY_COUNT; k++) {
        if (!reached[k]) {
            unit_fail(__FILE__, __LINE__, "key %u: no USB key gives it", (unsigned)k);
        }
    }
}

/* input.h's key map typed on the USB keyboard, checked against the keys it names (not through the
 * decoder): the letters, space, the arrows, h and Shift+/ for help, 1..9. */
void test_usb_keys_key_map(void)
{
    static const struct {
        uint8_t usage;
        uint8_t shift_key;
        enum input_key key;
    } map[] = {
        {U_W, 0, KEY_FORWARD},       {U_S, 0, KEY_BACK},
        {U_A, 0, KEY_LEFT},          {U_D, 0, KEY_RIGHT},
        {U_SPACE, 0, KEY_UP},        {0x06, 0, KEY_DOWN},                  /* c */
        {0x0C, 0, KEY_LOOK_UP},      {U_UP, 0, KEY_LOOK_UP},               /* i */
        {0x0E, 0, KEY_LOOK_DOWN},    {U_DOWN, 0, KEY_LOOK_DOWN},           /* k */
        {0x0D, 0, KEY_LOOK_LEFT},    {U_LEFT, 0, KEY_LOOK_LEFT},           /* j */
        {0x0F, 0, KEY_LOOK_RIGHT},   {U_RIGHT, 0, KEY_LOOK_RIGHT},         /* l */
        {0x18, 0, KEY_ROLL_LEFT},    {U_O, 0, KEY_ROLL_RIGHT},             /* u, o */
        {0x10, 0, KEY_MODE},         {0x09, 0, KEY_WIREFRAME},             /* m, f */
        {0x0A, 0, KEY_ANAGLYPH},     {0x1D, 0, KEY_DEPTH},                 /* g, z */
        {0x17, 0, KEY_ANIMATE},      {0x13, 0, KEY_PLACE},                 /* t, p */
        {0x05, 0, KEY_BREAK},        {0x11, 0, KEY_NEXT_BLOCK},            /* b, n */
        {0x15, 0, KEY_RESET_VIEW},   {U_H, 0, KEY_HELP},                   /* r */
        {U_SLASH, U_LEFT_SHIFT, KEY_HELP}, {U_SLASH, U_RIGHT_SHIFT, KEY_HELP},
        {U_W, U_LEFT_SHIFT, KEY_FORWARD},  {U_Q, 0, KEY_QUIT},
        {U_1, 0, KEY_SCENE_1},       {U_2, 0, KEY_SCENE_2},
        {0x20, 0, KEY_SCENE_3},      {0x21, 0, KEY_SCENE_4},
        {0x22, 0, KEY_SCENE_5},      {0x23, 0, KEY_SCENE_6},
        {0x24, 0, KEY_SCENE_7},      {0x25, 0, KEY_SCENE_8},
        {0x26, 0, KEY_SCENE_9},      {U_KP_8, 0, KEY_SCENE_8},
        {U_UP, U_LEFT_SHIFT, KEY_LOOK_UP},
    };

    for (size_t i = 0; i < sizeof map / sizeof map[0]; i++) {
        struct usb_keys u;
        struct input_counts c;

        usb_keys_init(&u, 0u, 0u);
        input_counts_clear(&c);
        usb_stroke(&u, &c, map[i].usage, map[i].shift_key);
        if (c.n[map[i].key] != 1u || c.total != 1u) {
            unit_fail(__FILE__, __LINE__,
                      "usage 0x%02x (shift 0x%02x): key %u counted %u, %u in all",
                      (unsigned)map[i].usage, (unsigned)map[i].shift_key, (unsigned)map[i].key,
                      (unsigned)c.n[map[i].key], (unsigned)c.total);
        }
    }
}

/* Shift is held while either Shift key is down, whatever the order of presses and releases; the
 * other modifiers are not Shift and change nothing; Shift on a digit sends its symbol (no key). */
void test_usb_keys_shift(void)
{
    struct usb_keys u;
    struct input_counts c;

    usb_keys_init(&u, 0u, 0u);
    input_counts_clear(&c);
    usb_stroke(&u, &c, U_SLASH, 0u);  /* '/': nothing */
    CHECK_EQ(c.total, 0);
    usb_keys_event(&u, &c, U_LEFT_SHIFT, true);
    usb_stroke(&u, &c, U_SLASH, 0u);  /* '?' */
    CHECK_EQ(c.n[KEY_HELP], 1);
    usb_keys_event(&u, &c, U_RIGHT_SHIFT, true);
    usb_keys_event(&u, &c, U_LEFT_SHIFT, false);  /* right still down */
    usb_stroke(&u, &c, U_SLASH, 0u);
    CHECK_EQ(c.n[KEY_HELP], 2);
    usb_keys_event(&u, &c, U_LEFT_SHIFT, true);
    usb_keys_event(&u, &c, U_RIGHT_SHIFT, false);  /* left down again */
    usb_stroke(&u, &c, U_SLASH, 0u);
    CHECK_EQ(c.n[KEY_HELP], 3);
    usb_keys_event(&u, &c, U_LEFT_SHIFT, false);  /* both up */
    usb_stroke(&u, &c, U_SLASH, 0u);
    CHECK_EQ(c.n[KEY_HELP], 3);
    /* Shift released between the key's press and its release: the press had it. */
    usb_keys_event(&u, &c, U_RIGHT_SHIFT, true);
    usb_keys_event(&u, &c, U_SLASH, true);
    usb_keys_event(&u, &c, U_RIGHT_SHIFT, false);
    usb_keys_event(&u, &c, U_SLASH, false);
    CHECK_EQ(c.n[KEY_HELP], 4);
    CHECK_EQ(c.total, 4);
    /* A release of a Shift that was never pressed, twice: still no Shift. */
    usb_keys_event(&u, &c, U_LEFT_SHIFT, false);
    usb_keys_event(&u, &c, U_LEFT_SHIFT, false);
    usb_stroke(&u, &c, U_SLASH, 0u);
    CHECK_EQ(c.total, 4);
    /* Ctrl is not Shift; Shift+1 is '!': nothing; Shift+h is 'H': help, as h. */
    input_counts_clear(&c);
    usb_stroke(&u, &c, U_SLASH, U_LEFT_CTRL);
    CHECK_EQ(c.total, 0);
    usb_stroke(&u, &c, U_1, U_LEFT_SHIFT);
    CHECK_EQ(c.total, 0);
    usb_stroke(&u, &c, U_H, U_RIGHT_SHIFT);
    CHECK_EQ(c.n[KEY_HELP], 1);
    usb_stroke(&u, &c, U_W, U_LEFT_CTRL);  /* Ctrl held: w as without */
    CHECK_EQ(c.n[KEY_FORWARD], 1);
    CHECK_EQ(c.total, 2);
}

/* Releases send nothing, of any usage, pressed before or not; modifiers alone send nothing; keys
 * without a terminal character (Caps Lock, F1, usage 0) send nothing. */
void test_usb_keys_releases_and_unknown(void)
{
    struct usb_keys u;
    struct input_counts c;

    usb_keys_init(&u, 0u, 0u);
    input_counts_clear(&c);
    for (uint32_t usage = 0; usage <= 0xFFu; usage++) {
        usb_keys_event(&u, &c, (uint8_t)usage, false);
    }
    CHECK_EQ(c.total, 0);
    for (uint32_t usage = USB_KEYS_MODIFIER_FIRST; usage <= USB_KEYS_MODIFIER_LAST; usage++) {
        usb_keys_event(&u, &c, (uint8_t)usage, true);
    }
    CHECK_EQ(c.total, 0);
    for (uint32_t usage = USB_KEYS_MODIFIER_FIRST; usage <= USB_KEYS_MODIFIER_LAST; usage++) {
        usb_keys_event(&u, &c, (uint8_t)usage, false);
    }
    usb_stroke(&u, &c, U_CAPS_LOCK, 0u);
    usb_stroke(&u, &c, U_F1, 0u);
    usb_stroke(&u, &c, 0x00u, 0u);
    usb_stroke(&u, &c, 0x32u, 0u);  /* the non-US # ~ */
    CHECK_EQ(c.total, 0);
    usb_keys_event(&u, &c, U_W, true);
    usb_keys_event(&u, &c, U_W, false);
    usb_keys_event(&u, &c, U_W, false);  /* a second release: nothing */
    CHECK_EQ(c.n[KEY_FORWARD], 1);
    CHECK_EQ(c.total, 1);
}

/* A mixed sequence — letters, Shift, arrows, digits, keys held across others, releases out of
 * order — counts what the same keys typed in a terminal count. */
void test_usb_keys_sequence(void)
{
    static const struct {
        uint8_t usage;
        bool press;
    } ev[] = {
        {U_W, true},          {U_A, true},  {U_W, false},      {U_W, true}, {U_A, false},
        {U_W, false},         {U_UP, true}, {U_LEFT_SHIFT, true}, {U_UP, false},
        {U_SLASH, true},      {U_D, true},  {U_LEFT_SHIFT, false}, {U_SLASH, false},
        {U_D, false},         {U_2, true},  {0x2F, true},      {U_RIGHT, true}, {0x2F, false},
        {U_RIGHT, false},     {U_2, false}, {U_LEFT, true},    {U_LEFT, false}, {U_SPACE, true},
        {U_SPACE, false},     {U_DOWN, true}, {U_DOWN, false}, {U_Q, true},
    };
    /* What a terminal sends for the presses above, in order. */
    static const char term[] = "waw\x1b[A?D2[\x1b[C\x1b[D \x1b[Bq";
    struct usb_keys u;
    struct input_counts got;
    struct input_counts want;

    usb_keys_init(&u, 0u, 0u);
    input_counts_clear(&got);
    for (size_t i = 0; i < sizeof ev / sizeof ev[0]; i++) {
        usb_keys_event(&u, &got, ev[i].usage, ev[i].press);
    }
    uart_counts(&want, term);
    check_same_counts(&got, &want, 0u, false, __LINE__);
    CHECK_EQ(got.n[KEY_FORWARD], 2);
    CHECK_EQ(got.n[KEY_LEFT], 1);
    CHECK_EQ(got.n[KEY_HELP], 1);
    CHECK_EQ(got.n[KEY_LOOK_UP], 1);
    CHECK_EQ(got.n[KEY_LOOK_RIGHT], 1);
    CHECK_EQ(got.n[KEY_LOOK_LEFT], 1);
    CHECK_EQ(got.n[KEY_LOOK_DOWN], 1);
    CHECK_EQ(got.n[KEY_SCENE_2], 1);
    CHECK_EQ(got.n[KEY_QUIT], 1);
    CHECK_EQ(got.total, 12);
}

/* The USB keys' decoder is their own: an escape sequence half-received on the UART neither eats
 * nor is completed by a USB key, and the other way round; Escape on the USB keyboard then [ or
 * Shift+O starts a sequence of the USB keys alone, as a terminal's would. */
void test_usb_keys_decoders_independent(void)
{
    struct input_decoder uart;
    struct usb_keys u;
    struct input_counts c;

    input_decoder_init(&uart);
    usb_keys_init(&u, 0u, 0u);
    input_counts_clear(&c);
    input_feed(&uart, &c, (const uint8_t *)"\x1b[", 2u);  /* the UART's arrow, half of it */
    usb_stroke(&u, &c, U_A, 0u);                           /* a final byte for the UART: not here */
    usb_stroke(&u, &c, U_UP, 0u);
    CHECK_EQ(c.n[KEY_LEFT], 1);
    CHECK_EQ(c.n[KEY_LOOK_UP], 1);
    input_feed(&uart, &c, (const uint8_t *)"B", 1u);       /* the UART's arrow completes */
    CHECK_EQ(c.n[KEY_LOOK_DOWN], 1);
    CHECK_EQ(c.n[KEY_BACK], 0);
    CHECK_EQ(c.total, 3);

    /* Escape on USB; the UART's "[A" is [ and a, its own keys. */
    input_counts_clear(&c);
    usb_stroke(&u, &c, U_ESCAPE, 0u);
    input_feed(&uart, &c, (const uint8_t *)"[A", 2u);
    CHECK_EQ(c.n[KEY_LEFT], 1);
    CHECK_EQ(c.total, 1);
    /* The USB Escape is still pending: [ then a complete a sequence of the USB keys (no key), as
     * ESC [ a typed in a terminal; then w counts again. */
    usb_stroke(&u, &c, U_LBRACKET, 0u);
    usb_stroke(&u, &c, U_A, 0u);
    CHECK_EQ(c.total, 1);
    usb_stroke(&u, &c, U_W, 0u);
    CHECK_EQ(c.n[KEY_FORWARD], 1);
    /* Escape, Shift+O (ESC O, SS3) and an arrow-letter: an arrow, as on a terminal. */
    usb_stroke(&u, &c, U_ESCAPE, 0u);
    usb_stroke(&u, &c, U_O, U_LEFT_SHIFT);
    usb_stroke(&u, &c, U_A, U_RIGHT_SHIFT);
    CHECK_EQ(c.n[KEY_LOOK_UP], 1);
    /* Escape then w: the w counts (a lone ESC). */
    usb_stroke(&u, &c, U_ESCAPE, 0u);
    usb_stroke(&u, &c, U_W, 0u);
    CHECK_EQ(c.n[KEY_FORWARD], 2);
    CHECK_EQ(c.total, 4);
}

/* `frames` frames: each the repeat tick, then nothing else. */
static void run_frames(struct usb_keys *u, struct input_counts *c, uint32_t frames)
{
    for (uint32_t f = 0; f < frames; f++) {
        usb_keys_frame(u, c);
    }
}

/* Typematic repeat in frames: none unless asked; with a delay of 3 and a period of 2 a key pressed
 * in frame 0 repeats in frames 3, 5, 7, ... while held; the last key pressed repeats, a modifier
 * does not take over, another key's release does not stop it, the repeat has the Shift of its
 * frame. */
void test_usb_keys_repeat(void)
{
    struct usb_keys u;
    struct input_counts c;

    usb_keys_init(&u, 0u, 2u);  /* off */
    input_counts_clear(&c);
    usb_keys_event(&u, &c, U_W, true);
    run_frames(&u, &c, 1000u);
    CHECK_EQ(c.n[KEY_FORWARD], 1);

    usb_keys_init(&u, 3u, 2u);
    input_counts_clear(&c);
    usb_keys_frame(&u, &c);             /* frame 0's tick: nothing held */
    usb_keys_event(&u, &c, U_W, true);  /* frame 0: the press */
    run_frames(&u, &c, 2u);             /* frames 1, 2 */
    CHECK_EQ(c.n[KEY_FORWARD], 1);
    run_frames(&u, &c, 1u);             /* frame 3: the first repeat */
    CHECK_EQ(c.n[KEY_FORWARD], 2);
    run_frames(&u, &c, 1u);             /* 4 */
    CHECK_EQ(c.n[KEY_FORWARD], 2);
    run_frames(&u, &c, 1u);             /* 5 */
    CHECK_EQ(c.n[KEY_FORWARD], 3);
    usb_keys_event(&u, &c, U_LEFT_SHIFT, true);   /* a modifier: w goes on */
    usb_keys_event(&u, &c, U_A, false);           /* a release of another key: w goes on */
    run_frames(&u, &c, 2u);             /* 6, 7 */
    CHECK_EQ(c.n[KEY_FORWARD], 4);
    usb_keys_event(&u, &c, U_LEFT_SHIFT, false);
    usb_keys_event(&u, &c, U_W, false);
    run_frames(&u, &c, 20u);
    CHECK_EQ(c.n[KEY_FORWARD], 4);
    CHECK_EQ(c.total, 4);

    /* w held, then a held: a repeats (from its own press), w no more; w's release does not stop
     * a. */
    input_counts_clear(&c);
    usb_keys_event(&u, &c, U_W, true);
    run_frames(&u, &c, 1u);
    usb_keys_event(&u, &c, U_A, true);
    usb_keys_event(&u, &c, U_W, false);
    run_frames(&u, &c, 5u);             /* a's repeats at 3 and 5 frames after its press */
    CHECK_EQ(c.n[KEY_FORWARD], 1);
    CHECK_EQ(c.n[KEY_LEFT], 3);
    /* A key that sends nothing takes over too: a stops. */
    usb_keys_event(&u, &c, U_F1, true);
    run_frames(&u, &c, 10u);
    CHECK_EQ(c.n[KEY_LEFT], 3);
    CHECK_EQ(c.total, 4);
    usb_keys_event(&u, &c, U_F1, false);
    usb_keys_event(&u, &c, U_A, false);

    /* / held, Shift pressed while it repeats: the repeats are ? (help). Period 0 counts as 1. */
    usb_keys_init(&u, 1u, 0u);
    input_counts_clear(&c);
    usb_keys_event(&u, &c, U_SLASH, true);
    run_frames(&u, &c, 2u);
    CHECK_EQ(c.total, 0);
    usb_keys_event(&u, &c, U_RIGHT_SHIFT, true);
    run_frames(&u, &c, 3u);
    CHECK_EQ(c.n[KEY_HELP], 3);
    /* An arrow repeats whole: the decoder at rest between repeats. */
    usb_keys_event(&u, &c, U_SLASH, false);
    usb_keys_event(&u, &c, U_UP, true);
    run_frames(&u, &c, 4u);
    CHECK_EQ(c.n[KEY_LOOK_UP], 5);
    CHECK_EQ(c.total, 8);
}
