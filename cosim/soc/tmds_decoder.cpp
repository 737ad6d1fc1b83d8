// TmdsDecoder: see tmds_decoder.h. The reference encoder here is written from the DVI 1.0 spec's
// flow chart (section 3.2.2) on arrays of bits, independently of boards/common/tmds_encoder.v.
#include "tmds_decoder.h"

#include <bitset>
#include <cstdio>

namespace {

constexpr uint16_t kClockWord = 0x01F;  // 0000011111: bits 0..4 set
constexpr uint16_t kToken[4] = {0x354, 0x0AB, 0x154, 0x2AB};  // ctrl 00, 01, 10, 11
const char *const kChannel[4] = {"0 (blue)", "1 (green)", "2 (red)", "3 (clock)"};

struct Encoded {
    uint16_t symbol;
    int cnt;
};

// DVI 1.0 data encoding of byte d with running disparity cnt (ones minus zeros so far).
Encoded reference_encode(uint8_t d, int cnt) {
    int D[8], qm[9];
    int n1d = 0;
    for (int i = 0; i < 8; i++) {
        D[i] = (d >> i) & 1;
        n1d += D[i];
    }
    qm[0] = D[0];
    if (n1d > 4 || (n1d == 4 && D[0] == 0)) {
        for (int i = 1; i < 8; i++) qm[i] = !(qm[i - 1] ^ D[i]);
        qm[8] = 0;
    } else {
        for (int i = 1; i < 8; i++) qm[i] = qm[i - 1] ^ D[i];
        qm[8] = 1;
    }
    int n1 = 0;
    for (int i = 0; i < 8; i++) n1 += qm[i];
    int n0 = 8 - n1;
    int q[10];
    if (cnt == 0 || n1 == n0) {
        q[9] = !qm[8];
        q[8] = qm[8];
        for (int i = 0; i < 8; i++) q[i] = qm[8] ? qm[i] : !qm[i];
        cnt += qm[8] ? (n1 - n0) : (n0 - n1);
    } else if ((cnt > 0 && n1 > n0) || (cnt < 0 && n0 > n1)) {
        q[9] = 1;
        q[8] = qm[8];
        for (int i = 0; i < 8; i++) q[i] = !qm[i];
        cnt += 2 * qm[8] + (n0 - n1);
    } else {
        q[9] = 0;
        q[8] = qm[8];
        for (int i = 0; i < 8; i++) q[i] = qm[i];
        cnt += -2 * (1 - qm[8]) + (n1 - n0);
    }
    uint16_t s = 0;
    for (int i = 0; i < 10; i++) s |= uint16_t(q[i] << i);
    return {s, cnt};
}

// 10b -> 8b: bit 9 says bits 7:0 were inverted, bit 8 says XOR (1) or XNOR (0).
uint8_t data_decode(uint16_t s) {
    uint8_t q = uint8_t(s & 0xFF);
    if (s & 0x200) q = uint8_t(~q);
    uint8_t d = q & 1;
    for (int i = 1; i < 8; i++) {
        int x = ((q >> i) ^ (q >> (i - 1))) & 1;
        if (!(s & 0x100)) x ^= 1;
        d |= uint8_t(x << i);
    }
    return d;
}

int token_index(uint16_t s) {
    for (int c = 0; c < 4; c++)
        if (s == kToken[c]) return c;
    return -1;
}

// Every 10-bit code that some byte encodes to at some reachable disparity (-8..8, even).
const std::bitset<1024> &valid_data_codes() {
    static const std::bitset<1024> codes = [] {
        std::bitset<1024> v;
        for (int cnt = -TmdsDecoder::kDisparityBound; cnt <= TmdsDecoder::kDisparityBound; cnt += 2)
            for (int d = 0; d < 256; d++) v.set(reference_encode(uint8_t(d), cnt).symbol);
        return v;
    }();
    return codes;
}

std::string hex10(uint16_t s) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%03x", s);
    return buf;
}

}  // namespace

TmdsDecoder::TmdsDecoder() { (void)valid_data_codes(); }

void TmdsDecoder::fail(const std::string &what) {
    if (error_.empty()) error_ = "pixel " + std::to_string(pixels_) + ": " + what;
}

bool TmdsDecoder::clock(uint8_t d0, uint8_t d1, TmdsPixel *out) {
    bool done = bit(d0, out);
    if (bit(d1, out)) done = true;
    return done;
}

bool TmdsDecoder::bit(uint8_t bits, TmdsPixel *out) {
    if (!error_.empty()) return false;
    int clk_bit = (bits >> 3) & 1;
    if (!aligned_) {
        bool edge = clk_bit == 1 && last_clk_bit_ == 0;
        last_clk_bit_ = clk_bit;
        if (!edge) return false;
        aligned_ = true;
        nbits_ = 0;
        for (auto &w : word_) w = 0;
    }
    for (int k = 0; k < 4; k++) word_[k] |= uint16_t(((bits >> k) & 1) << nbits_);
    if (++nbits_ < 10) return false;
    nbits_ = 0;
    bool done = symbol(out);
    for (auto &w : word_) w = 0;
    return done;
}

bool TmdsDecoder::symbol(TmdsPixel *out) {
    if (word_[3] != kClockWord) {
        fail("clock channel word " + hex10(word_[3]) + " is not 0000011111 (" + hex10(kClockWord) + ")");
        return false;
    }
    int tok[3];
    for (int k = 0; k < 3; k++) {
        tok[k] = token_index(word_[k]);
        if (tok[k] < 0 && !valid_data_codes().test(word_[k])) {
            fail("channel " + std::string(kChannel[k]) + " symbol " + hex10(word_[k]) +
                 " is neither a control token nor a data code");
            return false;
        }
    }
    bool control = tok[0] >= 0;
    if ((tok[1] >= 0) != control || (tok[2] >= 0) != control) {
        fail(std::string("channels disagree on data vs control (blue, green, red symbols ") + hex10(word_[0]) +
             ", " + hex10(word_[1]) + ", " + hex10(word_[2]) + ")");
        return false;
    }
    TmdsPixel px{};
    if (control) {
        for (int k = 1; k < 3; k++) {
            if (tok[k] != 0) {
                fail("channel " + std::string(kChannel[k]) + " carries ctrl " + std::to_string(tok[k] >> 1) +
                     std::to_string(tok[k] & 1) + ", must be 00");
                return false;
            }
        }
        for (int &c : cnt_) c = 0;
        hsync_ = tok[0] & 1;
        vsync_ = (tok[0] >> 1) & 1;
        control_symbols_ += 3;
    } else {
        uint8_t byte[3];
        for (int k = 0; k < 3; k++) {
            byte[k] = data_decode(word_[k]);
            Encoded e = reference_encode(byte[k], cnt_[k]);
            if (e.symbol != word_[k]) {
                fail("channel " + std::string(kChannel[k]) + " symbol " + hex10(word_[k]) + " decodes to 0x" +
                     hex10(byte[k]).substr(3) + " but at running disparity " + std::to_string(cnt_[k]) +
                     " the encoder must send " + hex10(e.symbol) + " (DC balance)");
                return false;
            }
            cnt_[k] = e.cnt;
            int a = cnt_[k] < 0 ? -cnt_[k] : cnt_[k];
            if (a > max_abs_cnt_[k]) max_abs_cnt_[k] = a;
            if (a > kDisparityBound) {
                fail("channel " + std::string(kChannel[k]) + " running disparity " + std::to_string(cnt_[k]) +
                     " exceeds +-" + std::to_string(kDisparityBound));
                return false;
            }
        }
        px.de = true;
        px.b = byte[0];
        px.g = byte[1];
        px.r = byte[2];
        data_symbols_ += 3;
    }
    px.hsync = hsync_;
    px.vsync = vsync_;
    symbols_ += 3;
    pixels_++;
    *out = px;
    return true;
}
