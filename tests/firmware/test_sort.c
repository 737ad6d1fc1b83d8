/*
 * test_sort.c — the painter's radix sort: ascending by key, stable (equal keys keep their order),
 * for short lists (insertion sort) and long ones (two bucket passes, either skippable), against
 * a reference stable sort. Items are sort.h's: 32-bit, or 64-bit where the build's frame indices
 * are wide (FW_RENDER_WIDE_INDEX), whose payloads then start beyond 16 bits.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "render/sort.h"
#include "unit.h"

#define SORT_TEST_MAX 20000u

static sort_item_t items[SORT_TEST_MAX];
static sort_item_t tmp[SORT_TEST_MAX];
static sort_item_t expect[SORT_TEST_MAX];

/* Payloads start beyond 16 bits where items allow. */
#define PAYLOAD_BASE (FW_RENDER_WIDE_INDEX ? 100000u : 0u)

/* Reference: stable insertion sort by key (slow, obviously right). */
static void ref_sort(sort_item_t *a, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++) {
        const sort_item_t x = a[i];
        uint32_t j = i;

        while (j > 0u && sort_item_key(a[j - 1u]) > sort_item_key(x)) {
            a[j] = a[j - 1u];
            j--;
        }
        a[j] = x;
    }
}

static void check_sort(uint32_t n, uint32_t key_mask, uint32_t key_or)
{
    struct sort_scratch s;

    for (uint32_t i = 0; i < n; i++) {
        items[i] = sort_item_make((unit_rand() & key_mask) | key_or, PAYLOAD_BASE + i);  /* submission order */
    }
    memcpy(expect, items, n * sizeof items[0]);
    ref_sort(expect, n);
    sort_items(items, tmp, n, &s);
    for (uint32_t i = 0; i < n; i++) {
        if (items[i] != expect[i]) {
            unit_fail(__FILE__, __LINE__, "n=%u mask=0x%x: item %u is key %u payload %u, expected "
                      "key %u payload %u", n, key_mask, i, sort_item_key(items[i]), sort_item_payload(items[i]),
                      sort_item_key(expect[i]), sort_item_payload(expect[i]));
            return;
        }
    }
    /* Stability spelled out: among equal keys, payloads (submission order) increase. */
    for (uint32_t i = 1; i < n; i++) {
        CHECK(sort_item_key(items[i - 1u]) < sort_item_key(items[i]) ||
              sort_item_payload(items[i - 1u]) < sort_item_payload(items[i]));
    }
}

void test_sort_order_and_stability(void)
{
    static const uint32_t sizes[] = {0, 1, 2, 3, 31, 32, 33, 100, 1000, 16384};

    for (unsigned i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        check_sort(sizes[i], 0xFFFFu, 0);   /* keys everywhere */
        check_sort(sizes[i], 0x000Fu, 0);   /* many equal keys: stability matters */
        check_sort(sizes[i], 0x00FFu, 0);   /* high byte constant: one pass skipped */
        check_sort(sizes[i], 0xFF00u, 0);   /* low byte constant: the other pass skipped */
        check_sort(sizes[i], 0x0000u, 0x1234u);  /* all equal: order unchanged */
    }
}

extern uint64_t sort_work;  /* sort.c, built with SORT_COUNT_WORK for these tests */

/* Reverse-ordered keys (the adversarial input for quicksort and insertion sort) of n items. */
static uint64_t sort_reverse_work(uint32_t n)
{
    struct sort_scratch s;

    for (uint32_t i = 0; i < n; i++) {
        items[i] = sort_item_make(0xFFFFu - (i % 65536u), PAYLOAD_BASE + i);
    }
    sort_work = 0;
    sort_items(items, tmp, n, &s);
    for (uint32_t i = 1; i < n; i++) {
        CHECK(sort_item_key(items[i - 1u]) <= sort_item_key(items[i]));
    }
    return sort_work;
}

/* Linear cost on reverse order: the work sort.c counts (items read and moved, histogram slots)
 * is at most 6 per item (two counting passes: 2 reads for the histograms, 2 moves, 1 copy back at
 * most) plus a fixed cost per sort for the slots of its two 256-slot histograms (cleared, checked
 * and prefix-summed; bounded here by 3 x 1024 with room to spare), and doubling n at most doubles
 * it (+256: the fixed cost is not doubled). An insertion sort on this input would do n^2 / 2. */
void test_sort_reverse_input(void)
{
    const uint64_t w1 = sort_reverse_work(SORT_TEST_MAX / 2u);
    const uint64_t w2 = sort_reverse_work(SORT_TEST_MAX);

    CHECK(w2 <= 6u * SORT_TEST_MAX + 3u * 1024u);
    CHECK(w2 <= 2u * w1 + 256u);
    CHECK(w2 >= 2u * SORT_TEST_MAX);  /* it did count: two passes read every item */
}

/* A list shorter than SORT_SMALL_N needs no scratch: a frame too small for the radix sort has none
 * (NULL), and sort_items must not touch it, not even to form a member's address (UBSan found
 * that in `make stress`'s 8-primitive frame). */
void test_sort_small_without_scratch(void)
{
    sort_item_t few[SORT_SMALL_N - 1u];
    sort_item_t few_tmp[SORT_SMALL_N - 1u];
    const uint32_t n = SORT_SMALL_N - 1u;

    for (uint32_t i = 0; i < n; i++) {
        few[i] = sort_item_make(n - i, PAYLOAD_BASE + i);
    }
    sort_items(few, few_tmp, n, NULL);
    for (uint32_t i = 0; i < n; i++) {
        CHECK(few[i] == sort_item_make(i + 1u, PAYLOAD_BASE + n - 1u - i));
    }
}
