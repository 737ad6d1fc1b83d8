/*
 * test_frame.h — the unit tests' frame (test_frame.c): the historical 16384 vertices and
 * primitives (a firmware build sizes its own, scenes/scene_set.h), attached before any case runs.
 * One frame for every test file that needs a large one; each case starts its own frame on it
 * (render_frame_begin), so no case sees another's primitives.
 */
#ifndef TEST_FRAME_H
#define TEST_FRAME_H

#include "render/render.h"

#define TEST_FRAME_VERTS 16384u
#define TEST_FRAME_PRIMS 16384u

extern struct render_frame test_frame;

#endif /* TEST_FRAME_H */
