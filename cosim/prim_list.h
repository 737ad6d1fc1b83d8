// prim_list: the primitive-list text format of `make raster` and `gpusim cosim --dump-lists`: its
// parser, its writer, and the batches a list becomes.
//
// One primitive per line, integers: `clear C`, `tri X0 Y0 X1 Y1 X2 Y2 C`, `line X0 Y0 X1 Y1 C`
// (coordinates Q12.4, -32768..32767; C a palette index 0..255); `#` starts a comment; blank lines
// are ignored. Primitives are drawn in list order, later over earlier. On a GPU built with the depth
// buffer, `ztri X0 Y0 Z0 X1 Y1 Z1 X2 Y2 Z2 C` (Z 0..65535) draws a depth-tested triangle; a `clear`
// also resets the depths when the list has any `ztri`. On a GPU built with Gouraud triangles,
// `gtri X0 Y0 I0 X1 Y1 I1 X2 Y2 I2 C` (I: VTX_I, 0..65535, Q4.12) draws one shaded from palette
// index C up its ramp, dithered (CTRL_DITHER is set for a list with any `gtri`).
#ifndef PRIM_LIST_H
#define PRIM_LIST_H

#include <cstdint>
#include <string>
#include <vector>

struct ListOp {
    enum Kind { Clear, Tri, Line, ZTri, GTri } kind;
    int32_t v[6];   // x0 y0 x1 y1 x2 y2 (unused ones 0)
    uint32_t z[3];  // depths of a ztri, intensities of a gtri
    uint32_t color;
};

// Two ops are the same when every field is (the parser leaves the fields a kind does not use 0).
bool operator==(const ListOp &a, const ListOp &b);
inline bool operator!=(const ListOp &a, const ListOp &b) { return !(a == b); }

// Parses text and appends its primitives to ops. On error returns false, sets error to
// "LINE: what is wrong" (LINE counted from 1) and leaves ops as it was.
bool prim_list_parse(const std::string &text, std::vector<ListOp> &ops, std::string &error);

// Reads the file at path and parses it as above. On error returns false with error set to
// "cannot read PATH" or "PATH:LINE: what is wrong", ops as it was.
bool prim_list_read(const std::string &path, std::vector<ListOp> &ops, std::string &error);

// The text of ops, one op per line in the format above (the first value of each field its kind uses;
// values are expected in their documented ranges, as the parser gives them). The inverse of
// prim_list_parse: parsing the text gives ops back, every kind (ztri included) and field the parser
// sets (tests/raster/roundtrip.sh, tests/fuzz/fuzz_prim_list.cpp).
std::string prim_list_write(const std::vector<ListOp> &ops);

// One GPU batch: its vertex and index words, whether it clears first, and with what colour.
struct Batch {
    bool clear = false;
    bool depth = false;          // ZTEST (and ZCLEAR with the clear): the list has a ztri
    bool dither = false;         // CTRL_DITHER: the list has a gtri
    uint32_t clear_color = 0;
    std::vector<uint32_t> vtx;   // 2 words per vertex
    std::vector<uint32_t> idx;   // 2 words per primitive
};

// Splits ops into batches that fit the capacities; a `clear` starts a new batch (or, when the current
// batch has no primitive yet, becomes its clear).
std::vector<Batch> prim_list_batches(const std::vector<ListOp> &ops, uint32_t vtx_cap, uint32_t tri_cap);

#endif
