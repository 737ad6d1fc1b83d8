/*
 * input.h — keyboard over the UART: bytes -> keys -> per-frame key counts. Pure code.
 *
 * The decoder is a small state machine so that terminal escape sequences (arrow keys send
 * ESC [ A .. D) are understood and every other sequence is swallowed whole instead of leaking its
 * letters as commands. Letters are case-insensitive. Unknown bytes are ignored.
 *
 * A frame collects at most INPUT_MAX_BYTES_PER_FRAME bytes (app.c; FW_UART_BYTES_PER_FRAME in a
 * build with the UART upload, whose receiver sees every byte first, model/upload.h); the rest stay
 * in the UART for the next frame, so a burst of keys costs a bounded amount of work per frame and
 * never stalls rendering. Keys are counted, not queued: eight presses of W move eight steps in one frame.
 */
#ifndef INPUT_H
#define INPUT_H

#include <stdint.h>

#define INPUT_MAX_BYTES_PER_FRAME 32u

enum input_key {
    KEY_NONE = 0,
    KEY_FORWARD,     /* w */
    KEY_BACK,        /* s */
    KEY_LEFT,        /* a */
    KEY_RIGHT,       /* d */
    KEY_UP,          /* space */
    KEY_DOWN,        /* c */
    KEY_LOOK_UP,     /* i, arrow up */
    KEY_LOOK_DOWN,   /* k, arrow down */
    KEY_LOOK_LEFT,   /* j, arrow left */
    KEY_LOOK_RIGHT,  /* l, arrow right */
    KEY_ROLL_LEFT,   /* u */
    KEY_ROLL_RIGHT,  /* o */
    KEY_MODE,        /* m: fly -> orbit -> object -> fly */
    KEY_WIREFRAME,   /* f */
    KEY_ANAGLYPH,    /* g */
    KEY_DEPTH,       /* z: GPU depth buffer on/off (if the GPU has one) */
    KEY_ANIMATE,     /* t: scene animation on/off */
    KEY_PLACE,       /* p: voxel: place a block */
    KEY_BREAK,       /* b: voxel: break the block under the crosshair */
    KEY_NEXT_BLOCK,  /* n: voxel: next block type to place */
    KEY_RESET_VIEW,  /* r */
    KEY_HELP,        /* h or ? */
    KEY_QUIT,        /* q */
    KEY_SCENE_1,     /* 1 .. 9: switch to scene 1 .. 9 of the scene table (keys beyond the */
    KEY_SCENE_2,     /* table's scenes do nothing) */
    KEY_SCENE_3,
    KEY_SCENE_4,
    KEY_SCENE_5,
    KEY_SCENE_6,
    KEY_SCENE_7,
    KEY_SCENE_8,
    KEY_SCENE_9,
    KEY_SCENE_LAST = KEY_SCENE_9,
    KEY_COUNT
};

struct input_decoder {
    uint8_t state;  /* private: position inside an escape sequence */
};

/* Key presses of one frame, counted per key. */
struct input_counts {
    /* saturates at 255 (a frame reads at most 32 bytes anyway); word-aligned so that clearing
     * the counts is a few word stores */
    _Alignas(4) uint8_t n[KEY_COUNT];
    uint8_t total;
};

void input_decoder_init(struct input_decoder *d);

/* Feed one byte; returns the key it completes, or KEY_NONE. */
enum input_key input_decode(struct input_decoder *d, uint8_t byte);

void input_counts_clear(struct input_counts *c);
void input_counts_add(struct input_counts *c, enum input_key k);

/* Convenience: feed `len` bytes into the decoder and count the keys (host tests, scripted input). */
void input_feed(struct input_decoder *d, struct input_counts *c, const uint8_t *bytes,
                uint32_t len);

/* Presses of `plus` minus presses of `minus`. */
static inline int32_t input_axis(const struct input_counts *c, enum input_key plus,
                                 enum input_key minus)
{
    return (int32_t)c->n[plus] - (int32_t)c->n[minus];
}

/* An odd number of presses of a toggle key flips it. */
static inline int input_toggled(const struct input_counts *c, enum input_key k)
{
    return (c->n[k] & 1u) != 0u;
}

#endif /* INPUT_H */
