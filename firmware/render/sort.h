/*
 * sort.h — the painter's sort: a stable O(n) radix sort of 16-bit depth keys. Pure code.
 *
 * Items are 32-bit words, key << 16 | payload (render.c: the draw key and the primitive's
 * index), sorted ascending by the key with two least-significant-digit counting passes of 8 bits;
 * in a build with wide frame indices (config/build_options.h: FW_RENDER_WIDE_INDEX) 64-bit words,
 * key << 32 | payload, sorted the same way.
 * Carrying the payload inside the item means each pass reads and writes one sequential word,
 * with no indirection. Counting sort is stable, so items with equal keys keep their order —
 * for the painter, submission order (object order, then face order): frames are reproducible and
 * a coplanar face listed later stays on top. A pass whose digit is the same for every item is
 * skipped; lists shorter than SORT_SMALL_N use a stable insertion sort instead (same result,
 * none of the 2 x 256-bucket overhead).
 *
 * The key itself (render.c): 65535 minus the sum of the three vertices' sort depths (proj.h), so
 * ascending keys run from far to near; a later primitive overwrites an earlier one on the GPU.
 */
#ifndef SORT_H
#define SORT_H

#include <stdint.h>

#include "config/build_options.h"

/* A sort item, where its 16-bit key starts, and the payload's bits below it. */
#if FW_RENDER_WIDE_INDEX
typedef uint64_t sort_item_t;
#define SORT_KEY_SHIFT 32u
#define SORT_PAYLOAD_MASK 0xFFFFFFFFu
#else
typedef uint32_t sort_item_t;
#define SORT_KEY_SHIFT 16u
#define SORT_PAYLOAD_MASK 0xFFFFu
#endif

/* The item of a key (< 2^16) and a payload (within SORT_PAYLOAD_MASK), and its two parts. */
static inline sort_item_t sort_item_make(uint32_t key, uint32_t payload)
{
    return ((sort_item_t)key << SORT_KEY_SHIFT) | payload;
}

static inline uint32_t sort_item_key(sort_item_t x)
{
    return (uint32_t)(x >> SORT_KEY_SHIFT);
}

static inline uint32_t sort_item_payload(sort_item_t x)
{
    return (uint32_t)x & SORT_PAYLOAD_MASK;
}

/* Below this many items a stable insertion sort is cheaper than the two bucket passes. */
#define SORT_SMALL_N 32u

/* Each digit's slot holds its count, then, during its pass, where the digit's next item goes (a
 * pointer as an integer: the same word on the SoC), so one array serves both: 2 KiB, small enough
 * for the SoC's on-chip RAM beside the stack in a build that runs from the SDRAM (FW_FAST_DATA). */
struct sort_scratch {
    uintptr_t slot[2][256];  /* [0]: the low digit's, [1]: the high digit's */
};

/* Sort item[0 .. n-1] ascending by item >> SORT_KEY_SHIFT, stable; tmp must hold n items. scratch
 * may be NULL when n < SORT_SMALL_N (a frame too small ever to need it has none:
 * render_frame_init). */
void sort_items(sort_item_t *item, sort_item_t *tmp, uint32_t n, struct sort_scratch *scratch);

#endif /* SORT_H */
