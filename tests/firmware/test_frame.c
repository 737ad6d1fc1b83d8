/*
 * test_frame.c — see test_frame.h.
 */
#include "test_frame.h"

RENDER_FRAME_STORAGE(test_frame_store, TEST_FRAME_VERTS, TEST_FRAME_PRIMS);
struct render_frame test_frame;

static void test_frame_attach(void) __attribute__((constructor));
static void test_frame_attach(void)
{
    RENDER_FRAME_ATTACH(&test_frame, test_frame_store);
}
