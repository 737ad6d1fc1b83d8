/*
 * input.c — see input.h.
 */
#include "input/input.h"

enum {
    INPUT_S_GROUND = 0,  /* ordinary bytes */
    INPUT_S_ESC = 1,     /* after ESC */
    INPUT_S_CSI = 2,     /* after ESC [ : parameters until a final byte 0x40..0x7E */
};

#define INPUT_ESC 0x1Bu

void input_decoder_init(struct input_decoder *d)
{
    d->state = INPUT_S_GROUND;
}

static enum input_key input_plain(uint8_t b)
{
    if (b >= 'A' && b <= 'Z') {
        b = (uint8_t)(b - 'A' + 'a');
    }
    switch (b) {
    case 'w':
        return KEY_FORWARD;
    case 's':
        return KEY_BACK;
    case 'a':
        return KEY_LEFT;
    case 'd':
        return KEY_RIGHT;
    case ' ':
        return KEY_UP;
    case 'c':
        return KEY_DOWN;
    case 'i':
        return KEY_LOOK_UP;
    case 'k':
        return KEY_LOOK_DOWN;
    case 'j':
        return KEY_LOOK_LEFT;
    case 'l':
        return KEY_LOOK_RIGHT;
    case 'u':
        return KEY_ROLL_LEFT;
    case 'o':
        return KEY_ROLL_RIGHT;
    case 'm':
        return KEY_MODE;
    case 'f':
        return KEY_WIREFRAME;
    case 'g':
        return KEY_ANAGLYPH;
    case 'z':
        return KEY_DEPTH;
    case 't':
        return KEY_ANIMATE;
    case 'p':
        return KEY_PLACE;
    case 'b':
        return KEY_BREAK;
    case 'n':
        return KEY_NEXT_BLOCK;
    case 'r':
        return KEY_RESET_VIEW;
    case 'h':
    case '?':
        return KEY_HELP;
    case 'q':
        return KEY_QUIT;
    case '1':
        return KEY_SCENE_1;
    case '2':
        return KEY_SCENE_2;
    case '3':
        return KEY_SCENE_3;
    case '4':
        return KEY_SCENE_4;
    case '5':
        return KEY_SCENE_5;
    case '6':
        return KEY_SCENE_6;
    case '7':
        return KEY_SCENE_7;
    case '8':
        return KEY_SCENE_8;
    case '9':
        return KEY_SCENE_9;
    default:
        return KEY_NONE;
    }
}

enum input_key input_decode(struct input_decoder *d, uint8_t b)
{
    switch (d->state) {
    case INPUT_S_ESC:
        if (b == '[' || b == 'O') {  /* CSI, or SS3 (application cursor keys send ESC O A) */
            d->state = INPUT_S_CSI;
            return KEY_NONE;
        }
        d->state = INPUT_S_GROUND;
        if (b == INPUT_ESC) {
            d->state = INPUT_S_ESC;
            return KEY_NONE;
        }
        return input_plain(b);  /* a lone ESC followed by a key: the key counts */
    case INPUT_S_CSI:
        if (b >= 0x40u && b <= 0x7Eu) {  /* final byte ends the sequence */
            d->state = INPUT_S_GROUND;
            switch (b) {
            case 'A':
                return KEY_LOOK_UP;
            case 'B':
                return KEY_LOOK_DOWN;
            case 'C':
                return KEY_LOOK_RIGHT;
            case 'D':
                return KEY_LOOK_LEFT;
            default:
                return KEY_NONE;
            }
        }
        if (b < 0x20u || b > 0x3Fu) {  /* not a parameter byte: malformed, drop it */
            d->state = INPUT_S_GROUND;
        }
        return KEY_NONE;
    default:
        if (b == INPUT_ESC) {
            d->state = INPUT_S_ESC;
            return KEY_NONE;
        }
        return input_plain(b);
    }
}

void input_counts_clear(struct input_counts *c)
{
    *c = (struct input_counts){{0}, 0};
}

void input_counts_add(struct input_counts *c, enum input_key k)
{
    if (k == KEY_NONE || k >= KEY_COUNT) {
        return;
    }
    if (c->n[k] < 255u) {
        c->n[k]++;
    }
    if (c->total < 255u) {
        c->total++;
    }
}

void input_feed(struct input_decoder *d, struct input_counts *c, const uint8_t *bytes,
                uint32_t len)
{
    for (uint32_t i = 0; i < len; i++) {
        input_counts_add(c, input_decode(d, bytes[i]));
    }
}
