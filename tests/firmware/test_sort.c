/*
 * test_sort.c — the painter's radix sort: ascending by key, stable (equal keys keep their order),
 * for short lists (insertion sort) and long ones (two bucket passes, either skippable), against
 * a reference stable sort.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "render/sort.h"
#include "unit.h"

#define SORT_TEST_MAX 20000u

static uint32_t items[SORT_TEST_MAX];
static uint32_t tmp[SORT_TEST_MAX];
static uint32_t expect[SORT_TEST_MAX];

/* Reference: stable insertion sort by key (slow, obviously right). */
static void ref_sort(uint32_t *a, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++) {
        const uint32_t x = a[i];
        uint32_t j = i;

        while (j > 0u && (a[j - 1u] >> 16) > (x >> 16)) {
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
        items[i] = (((unit_rand() & key_mask) | key_or) << 16) | i;  /* payload: submission order */
    }
    memcpy(expect, items, n * sizeof items[0]);
    ref_sort(expect, n);
    sort_items(items, tmp, n, &s);
    for (uint32_t i = 0; i < n; i++) {
        if (items[i] != expect[i]) {
            unit_fail(__FILE__, __LINE__, "n=%u mask=0x%x: item %u is 0x%08x, expected 0x%08x", n,
                      key_mask, i, items[i], expect[i]);
            return;
        }
    }
    /* Stability spelled out: among equal keys, payloads (submission order) increase. */
    for (uint32_t i = 1; i < n; i++) {
        CHECK((items[i - 1u] >> 16) < (items[i] >> 16) ||
              (items[i - 1u] & 0xFFFFu) < (items[i] & 0xFFFFu));
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

/* Reverse order, the adversarial input for quicksort and insertion sort, at the largest size
 * (16384 items, the radix path): sorted. This checks the order only; the linear cost of the two
 * counting passes (O(n + 256)) is an argument about sort.c's loops, not measured here
 * (`make profile-fw` gives the sort's instructions per frame). */
void test_sort_reverse_input_sorted(void)
{
    struct sort_scratch s;
    const uint32_t n = SORT_TEST_MAX;

    for (uint32_t i = 0; i < n; i++) {
        items[i] = ((0xFFFFu - (i % 65536u)) << 16) | (i & 0xFFFFu);
    }
    sort_items(items, tmp, n, &s);
    for (uint32_t i = 1; i < n; i++) {
        CHECK((items[i - 1u] >> 16) <= (items[i] >> 16));
    }
}
