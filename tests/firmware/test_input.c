/*
 * test_input.c — the UART key decoder: the key map, case, arrow-key escape sequences, unknown
 * bytes and sequences ignored, counting.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "input/input.h"
#include "unit.h"

static void feed_n(struct input_counts *c, const char *s, uint32_t n)
{
    struct input_decoder d;

    input_decoder_init(&d);
    input_counts_clear(c);
    input_feed(&d, c, (const uint8_t *)s, n);
}

static void feed(struct input_counts *c, const char *s)
{
    feed_n(c, s, (uint32_t)strlen(s));
}

struct key_count {
    enum input_key key;
    uint32_t n;
};

/* Each listed key counted exactly as often as listed (the failure names the key by number). */
static void check_counts(const struct input_counts *c, const struct key_count *want, size_t n_want)
{
    for (size_t i = 0; i < n_want; i++) {
        if (c->n[want[i].key] != want[i].n) {
            unit_fail(__FILE__, __LINE__, "key %u counted %u times, expected %u",
                      (unsigned)want[i].key, (unsigned)c->n[want[i].key], (unsigned)want[i].n);
        }
    }
}

#define CHECK_COUNTS(c, ...)                                                          \
    do {                                                                              \
        static const struct key_count want_[] = { __VA_ARGS__ };                      \
        check_counts((c), want_, sizeof want_ / sizeof want_[0]);                     \
    } while (0)

void test_input_key_map(void)
{
    struct input_counts c;

    feed(&c, "wasd c");
    CHECK_COUNTS(&c, { KEY_FORWARD, 1 }, { KEY_LEFT, 1 }, { KEY_BACK, 1 }, { KEY_RIGHT, 1 },
                 { KEY_UP, 1 }, { KEY_DOWN, 1 });
    feed(&c, "IJKLuo");
    CHECK_COUNTS(&c, { KEY_LOOK_UP, 1 }, { KEY_LOOK_LEFT, 1 }, { KEY_LOOK_DOWN, 1 },
                 { KEY_LOOK_RIGHT, 1 });
    CHECK_EQ(c.n[KEY_ROLL_LEFT] + c.n[KEY_ROLL_RIGHT], 2);
    feed(&c, "mfgztpbnrh?q123456789");
    CHECK_EQ(c.n[KEY_MODE] + c.n[KEY_WIREFRAME] + c.n[KEY_ANAGLYPH] + c.n[KEY_DEPTH] +
                 c.n[KEY_ANIMATE] + c.n[KEY_PLACE] + c.n[KEY_BREAK] + c.n[KEY_NEXT_BLOCK] +
                 c.n[KEY_RESET_VIEW] + c.n[KEY_QUIT],
             10);
    CHECK_EQ(c.n[KEY_HELP], 2);
    for (uint32_t k = KEY_SCENE_1; k <= KEY_SCENE_LAST; k++) {
        CHECK_EQ(c.n[k], 1);  /* 1 .. 9, one each */
    }
    CHECK_EQ(KEY_SCENE_LAST - KEY_SCENE_1 + 1, 9);
    CHECK_EQ(c.total, 21);
    CHECK_EQ(input_axis(&c, KEY_PLACE, KEY_BREAK), 0);
    CHECK(input_toggled(&c, KEY_MODE));
}

/* Arrow keys (ESC [ A..D and ESC O A..D) look around; other sequences vanish whole, letters
 * inside them included; unknown bytes are ignored. */
void test_input_escape_and_unknown(void)
{
    struct input_counts c;

    feed(&c, "\x1b[A\x1b[B\x1b[C\x1b[D\x1bOA");
    CHECK_COUNTS(&c, { KEY_LOOK_UP, 2 }, { KEY_LOOK_DOWN, 1 }, { KEY_LOOK_RIGHT, 1 },
                 { KEY_LOOK_LEFT, 1 });
    CHECK_EQ(c.total, 5);
    /* F5 is ESC [ 1 5 ~; Shift-arrow ESC [ 1 ; 2 A counts as the arrow. */
    feed(&c, "\x1b[15~\x1b[1;2A");
    CHECK_EQ(c.total, 1);
    CHECK_EQ(c.n[KEY_LOOK_UP], 1);
    /* A lone ESC then a key: the key counts. ESC ESC [ A: one arrow. */
    feed(&c, "\x1bw\x1b\x1b[A");
    CHECK_EQ(c.n[KEY_FORWARD], 1);
    CHECK_EQ(c.n[KEY_LOOK_UP], 1);
    /* Garbage: control bytes, high bytes, punctuation, the digit 0, a broken sequence. */
    {
        static const char junk[] = "\x00\x01\x7f\x80\xff!@#0xyvXYV\x1b[\x01w";

        feed_n(&c, junk, sizeof junk - 1u);
    }
    CHECK_EQ(c.total, 1);
    CHECK_EQ(c.n[KEY_FORWARD], 1);  /* the broken CSI ended at \x01; w is a key again */
}

void test_input_counts_saturate(void)
{
    struct input_decoder d;
    struct input_counts c;

    input_decoder_init(&d);
    input_counts_clear(&c);
    for (int i = 0; i < 1000; i++) {
        input_counts_add(&c, input_decode(&d, 'w'));
    }
    CHECK_EQ(c.n[KEY_FORWARD], 255);
    CHECK_EQ(c.total, 255);
    input_counts_add(&c, KEY_NONE);
    input_counts_add(&c, KEY_COUNT);  /* out of range: ignored, no write past the array */
    CHECK_EQ(c.total, 255);
}
