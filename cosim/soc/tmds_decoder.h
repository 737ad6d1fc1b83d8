// TmdsDecoder: turns the four ODDRX1F input pairs of boards/common/dvi_tx.v (ddr_d0/ddr_d1, one pair
// per clk_tmds period, bit k: 0 blue, 1 green, 2 red, 3 clock; d0 is the earlier bit) back into
// pixels, and checks the link while doing so. C++17, no Verilator dependency.
//
// Alignment: the clock channel carries 0000011111 (bit 0 first on the wire: five ones, five zeros);
// a symbol starts at the first 1 after a 0 on it. Before that, input is ignored; after it, every clock
// word must be exactly that pattern. The stream must start (at the first aligned symbol) with the
// encoders in their reset state or in a control period: the running disparity is taken as 0 there.
//
// Checks, per symbol: it is a control token or a code some data byte encodes to (e); a data symbol is
// bit-exactly what an independent DVI 1.0 reference encoder emits for the decoded byte at the
// channel's running disparity (a: the DC-balance check), and that disparity stays within +-8, the
// algorithm's bound (b); per pixel: the three channels agree on data vs control (c) and channels 1, 2
// carry ctrl 00 (d). The first violation is kept in error() ("pixel N: ...") and no pixel is produced
// after it.
#pragma once

#include <cstdint>
#include <string>

struct TmdsPixel {
    bool de;        // 1: data period (r, g, b valid); 0: control period (r = g = b = 0)
    bool hsync;     // level: c0 of channel 0 (held from the last control period while de)
    bool vsync;     // level: c1 of channel 0 (held likewise)
    uint8_t r, g, b;
};

class TmdsDecoder {
public:
    static constexpr int kDisparityBound = 8;

    TmdsDecoder();
    // Feed one clk_tmds period: bit k of d0 (then d1) is channel k's bit. Returns true when a pixel
    // was completed by these bits (at most one per call) and stores it in *out.
    bool clock(uint8_t d0, uint8_t d1, TmdsPixel *out);

    bool ok() const { return error_.empty(); }
    const std::string &error() const { return error_; }  // empty while no violation was seen
    bool aligned() const { return aligned_; }
    uint64_t pixels() const { return pixels_; }           // pixels produced
    uint64_t symbols() const { return symbols_; }         // symbols decoded, three per pixel
    uint64_t data_symbols() const { return data_symbols_; }
    uint64_t control_symbols() const { return control_symbols_; }
    int max_disparity(int ch) const { return max_abs_cnt_[ch]; }  // max |running disparity| seen

private:
    bool bit(uint8_t bits, TmdsPixel *out);  // one bit per channel; true when a pixel completed
    bool symbol(TmdsPixel *out);
    void fail(const std::string &what);

    bool aligned_ = false;
    int last_clk_bit_ = 1;  // a 0 must be seen before the first 0 -> 1 edge counts
    int nbits_ = 0;
    uint16_t word_[4] = {0, 0, 0, 0};
    int cnt_[3] = {0, 0, 0};
    int max_abs_cnt_[3] = {0, 0, 0};
    bool hsync_ = false, vsync_ = false;
    std::string error_;
    uint64_t pixels_ = 0, symbols_ = 0, data_symbols_ = 0, control_symbols_ = 0;
};
