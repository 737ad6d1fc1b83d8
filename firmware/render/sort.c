/*
 * sort.c — see sort.h.
 */
#include "render/sort.h"

#include "config/hot_path.h"

/* Work counter for the unit tests, which build this file with SORT_COUNT_WORK (firmware.mk,
 * FW_UNIT_CFLAGS): every item read or moved counts one, every histogram slot cleared or scanned
 * one. The firmware's builds leave it out (SORT_WORK is then nothing). */
#ifdef SORT_COUNT_WORK
uint64_t sort_work;
#define SORT_WORK(n) (sort_work += (uint64_t)(n))
#else
#define SORT_WORK(n) ((void)0)
#endif

/* Stable insertion sort by the key half, for short lists. */
static void sort_insertion(sort_item_t *item, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++) {
        const sort_item_t x = item[i];
        const uint32_t k = sort_item_key(x);
        uint32_t j = i;

        while (j > 0u && sort_item_key(item[j - 1u]) > k) {
            item[j] = item[j - 1u];
            j--;
            SORT_WORK(1);
        }
        item[j] = x;
        SORT_WORK(1);
    }
}

/* A pass can be skipped when one digit value holds every item. */
static int sort_pass_needed(const uintptr_t hist[256], uint32_t n)
{
    for (uint32_t d = 0; d < 256u; d++) {
        SORT_WORK(1);
        if (hist[d] != 0u) {
            return hist[d] != n;
        }
    }
    return 0;
}

/* One stable counting pass on the item byte at `shift` (SORT_KEY_SHIFT: the key's low byte, + 8:
 * its high byte).
 * slot holds the digit counts and becomes each digit's write position (a pointer, so placing an
 * item is one load, two stores and an increment). Always inlined with a constant shift, so the
 * digit costs two instructions (shift, mask) and the loop nine per item. */
static inline __attribute__((always_inline)) void sort_pass(const sort_item_t *in,
                                                            sort_item_t *out, uint32_t n,
                                                            uintptr_t slot[256], uint32_t shift)
{
    uintptr_t start = (uintptr_t)out;
    const sort_item_t *const in_end = in + n;

    /* The high digit's slots are the low digit's + 1 KiB: without this, GCC adds that offset to
     * every item's slot address (an instruction an item) instead of to the base once. */
    FW_ONE_REGISTER(slot);

    for (uint32_t d = 0; d < 256u; d += 4u) {  /* by four: a fixed cost of every sort */
        const uintptr_t c0 = slot[d];
        const uintptr_t c1 = slot[d + 1u];
        const uintptr_t c2 = slot[d + 2u];
        const uintptr_t c3 = slot[d + 3u];

        slot[d] = start;
        start += c0 * sizeof(sort_item_t);
        slot[d + 1u] = start;
        start += c1 * sizeof(sort_item_t);
        slot[d + 2u] = start;
        start += c2 * sizeof(sort_item_t);
        slot[d + 3u] = start;
        start += c3 * sizeof(sort_item_t);
        SORT_WORK(4);
    }
    /* Two items an iteration (one loop test for both), the first placed first: stable. */
    for (const sort_item_t *p = in; p != in_end - (n & 1u); p += 2) {
        const sort_item_t x0 = p[0];
        const sort_item_t x1 = p[1];
        uintptr_t *const s0 = &slot[(uint32_t)(x0 >> shift) & 0xFFu];

        *(sort_item_t *)*s0 = x0;
        *s0 += sizeof(sort_item_t);
        {
            uintptr_t *const s1 = &slot[(uint32_t)(x1 >> shift) & 0xFFu];

            *(sort_item_t *)*s1 = x1;
            *s1 += sizeof(sort_item_t);
        }
        SORT_WORK(2);
    }
    if ((n & 1u) != 0u) {
        const sort_item_t x = in_end[-1];
        uintptr_t *const s = &slot[(uint32_t)(x >> shift) & 0xFFu];

        *(sort_item_t *)*s = x;
        *s += sizeof(sort_item_t);
        SORT_WORK(1);
    }
}

void sort_items(sort_item_t *item, sort_item_t *tmp, uint32_t n, struct sort_scratch *scratch)
{
    uintptr_t(*hist)[256];
    sort_item_t *src = item;
    sort_item_t *dst = tmp;

    if (n < SORT_SMALL_N) {
        sort_insertion(item, n);
        return;
    }
    /* Only now: a frame too small for the radix sort has no scratch (NULL), and even forming
     * &scratch->slot from a null pointer is undefined behaviour. */
    hist = scratch->slot;
    for (uint32_t d = 0; d < 256u; d += 2u) {
        hist[0][d] = 0;
        hist[0][d + 1u] = 0;
        hist[1][d] = 0;
        hist[1][d + 1u] = 0;
        SORT_WORK(4);
    }
    /* Two items an iteration (one loop test for both), then the odd one. */
    for (uint32_t i = 0; i + 1u < n; i += 2u) {
        const uint32_t k0 = sort_item_key(item[i]);
        const uint32_t k1 = sort_item_key(item[i + 1u]);

        hist[0][k0 & 0xFFu]++;
        hist[1][k0 >> 8]++;
        hist[0][k1 & 0xFFu]++;
        hist[1][k1 >> 8]++;
        SORT_WORK(2);
    }
    if ((n & 1u) != 0u) {
        const uint32_t key = sort_item_key(item[n - 1u]);

        hist[0][key & 0xFFu]++;
        hist[1][key >> 8]++;
        SORT_WORK(1);
    }
    /* Low digit, then high digit; a skipped pass leaves the items where they are. */
    if (sort_pass_needed(hist[0], n)) {
        sort_pass(src, dst, n, hist[0], SORT_KEY_SHIFT);
        src = tmp;
        dst = item;
    }
    if (sort_pass_needed(hist[1], n)) {
        sort_pass(src, dst, n, hist[1], SORT_KEY_SHIFT + 8u);
        src = dst;
    }
    if (src != item) {
        for (uint32_t i = 0; i < n; i++) {
            item[i] = src[i];
            SORT_WORK(1);
        }
    }
}
