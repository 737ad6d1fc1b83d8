// usb_ref.h: the USB low-speed line as the USB 1.1 specification describes it, for the testbenches
// of tests/usb/ (line_tb.cpp, packet_tb.cpp), written from the specification and not from the RTL:
// the bit grid of a SYS_HZ clock, the encoder (SYNC, stuffing counted from the SYNC's last 1,
// NRZI, EOP), a waveform generator for the receiver (any rate, edge jitter, D- skewed against D+),
// a decoder of the host's wire, and the CRCs (8.3.5) computed bit by bit.
#pragma once
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#ifndef TB_SYS_HZ
#define TB_SYS_HZ 50000000
#endif
static const uint64_t SYS_HZ = TB_SYS_HZ;
static const uint64_t BIT_HZ = 1500000;
static uint64_t gcd_u(uint64_t a, uint64_t b) { return b ? gcd_u(b, a % b) : a; }
static const uint64_t GD = gcd_u(SYS_HZ, BIT_HZ);
static const uint64_t NUM = SYS_HZ / GD, DEN = BIT_HZ / GD;  // a bit is NUM / DEN clocks
static const double N_BIT = double(SYS_HZ) / double(BIT_HZ);
static const double NS_PER_CLK = 1e9 / double(SYS_HZ);

enum Sym { J, K, SE0, SE1, Z };
static inline const char *sym_name(Sym s) { return s == J ? "J" : s == K ? "K" : s == SE0 ? "0" : s == SE1 ? "1" : "z"; }

// ---- the reference encoder (USB 1.1 7.1.7 to 7.1.9) ----
static std::vector<int> bits_lsb_first(const std::vector<uint8_t> &bytes)
{
    std::vector<int> b;
    for (uint8_t v : bytes) {
        for (int i = 0; i < 8; i++) b.push_back((v >> i) & 1);
    }
    return b;
}
// A 0 after every six 1s in a row, also at the very end.
static std::vector<int> stuff_bits(const std::vector<int> &in)
{
    std::vector<int> out;
    int ones = 0;
    for (int b : in) {
        out.push_back(b);
        ones = b ? ones + 1 : 0;
        if (ones == 6) {
            out.push_back(0);
            ones = 0;
        }
    }
    return out;
}
// NRZI: a 0 changes the level, a 1 keeps it; the idle before the SYNC is J.
static std::vector<Sym> nrzi(const std::vector<int> &bits)
{
    std::vector<Sym> s;
    Sym level = J;
    for (int b : bits) {
        if (!b) level = level == J ? K : J;
        s.push_back(level);
    }
    return s;
}
static const std::vector<int> SYNC = {0, 0, 0, 0, 0, 0, 0, 1};
// A whole packet: SYNC and data stuffed together (the SYNC's last 1 counts), NRZI, EOP.
static std::vector<Sym> packet_symbols(const std::vector<uint8_t> &bytes, bool eop = true)
{
    std::vector<int> bits = SYNC;
    std::vector<int> data = bits_lsb_first(bytes);
    bits.insert(bits.end(), data.begin(), data.end());
    std::vector<Sym> s = nrzi(stuff_bits(bits));
    if (eop) {
        s.push_back(SE0);
        s.push_back(SE0);
        s.push_back(J);
    }
    return s;
}
// The clock at which bit k starts: the clock nearest k * NUM / DEN, ties to the earlier one.
static uint64_t bit_start(uint64_t k)
{
    if (k == 0) return 0;
    uint64_t num = 2 * k * NUM - DEN;          // ceil(k * N - 1/2) = ceil(num / (2 DEN))
    return (num + 2 * DEN - 1) / (2 * DEN);
}

// ---- a reference waveform for the receiver: symbols at any rate, with jitter and skew ----
struct Wave {
    std::vector<Sym> syms;
    std::vector<double> dp_edge, dn_edge;     // when symbol i starts on D+ and on D-
    double end = 0;                           // after it: released (the pull-up's J)
    bool active(double t) const { return !syms.empty() && t >= dp_edge[0] && t < end; }
};
static std::mt19937 rng;
static double urand(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
static int irand(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

// Symbol i at start + i * period, every edge moved by up to +-jitter clocks, D-'s edge between two
// data levels moved by up to +-skew clocks against D+'s.
static Wave make_wave(const std::vector<Sym> &syms, double start, double period, double jitter, double skew)
{
    Wave w;
    w.syms = syms;
    for (size_t i = 0; i < syms.size(); i++) {
        double e = start + double(i) * period + (i ? urand(-jitter, jitter) : 0.0);
        w.dp_edge.push_back(e);
        bool data_change = i && syms[i] != syms[i - 1] && syms[i] != SE0 && syms[i - 1] != SE0;
        w.dn_edge.push_back(data_change ? e + urand(-skew, skew) : e);
    }
    w.end = start + double(syms.size()) * period;
    return w;
}
static void wave_lines(const Wave &w, double t, int &dp, int &dn)
{
    auto level_at = [&](const std::vector<double> &edge) {
        size_t i = std::upper_bound(edge.begin(), edge.end(), t) - edge.begin();
        return i == 0 ? J : w.syms[i - 1];
    };
    Sym a = level_at(w.dp_edge), b = level_at(w.dn_edge);
    dp = a == K || a == SE1;
    dn = b == J || b == SE1;
}

// ---- the decoder: a symbol per bit (the host's wire sampled in the middle of each bit) back to
// bits: NRZI (no change is a 1), the SYNC checked, stuffed 0s dropped; stops at the SE0 ----
static std::vector<int> decode_bits(const std::vector<Sym> &syms, bool *ok)
{
    std::vector<int> bits;
    Sym prev = J;
    int ones = 0;
    size_t i = 0;
    *ok = true;
    for (; i < syms.size() && syms[i] != SE0; i++) {
        int b = syms[i] == prev;
        prev = syms[i];
        if (i < SYNC.size()) {
            if (b != SYNC[i]) *ok = false;
            ones = b ? ones + 1 : 0;
            continue;
        }
        if (ones == 6) {
            if (b) *ok = false;
            ones = 0;
            continue;
        }
        ones = b ? ones + 1 : 0;
        bits.push_back(b);
    }
    return bits;
}

// ---- CRCs (8.3.5): the shift register preset to ones, the bits in the order sent ----
static std::vector<int> crc_bits(const std::vector<int> &data, int n, uint32_t poly)
{
    uint32_t r = (1u << n) - 1, mask = (1u << n) - 1;
    for (int b : data) {
        uint32_t top = (r >> (n - 1)) & 1;
        r = (r << 1) & mask;
        if (top ^ uint32_t(b)) r ^= poly;
    }
    std::vector<int> out;
    for (int i = n - 1; i >= 0; i--) out.push_back(int((~r >> i) & 1));   // complemented, MSB first
    return out;
}
static uint32_t crc_residual(const std::vector<int> &data, int n, uint32_t poly)
{
    uint32_t r = (1u << n) - 1, mask = (1u << n) - 1;
    for (int b : data) {
        uint32_t top = (r >> (n - 1)) & 1;
        r = (r << 1) & mask;
        if (top ^ uint32_t(b)) r ^= poly;
    }
    return r;
}
static std::vector<uint8_t> bytes_of_bits(const std::vector<int> &bits)
{
    std::vector<uint8_t> out((bits.size() + 7) / 8, 0);
    for (size_t i = 0; i < bits.size(); i++) out[i / 8] |= uint8_t(bits[i] << (i % 8));
    return out;
}
// The packets, as bytes on the wire (8.4).
static std::vector<uint8_t> ref_token(int pid, int addr, int endp)
{
    std::vector<int> f;
    for (int i = 0; i < 7; i++) f.push_back((addr >> i) & 1);
    for (int i = 0; i < 4; i++) f.push_back((endp >> i) & 1);
    std::vector<int> c = crc_bits(f, 5, 0x05);
    f.insert(f.end(), c.begin(), c.end());
    std::vector<uint8_t> b = {uint8_t((~pid & 15) << 4 | pid)};
    std::vector<uint8_t> t = bytes_of_bits(f);
    b.insert(b.end(), t.begin(), t.end());
    return b;
}
static std::vector<uint8_t> ref_data(int pid, const std::vector<uint8_t> &payload)
{
    std::vector<int> c = crc_bits(bits_lsb_first(payload), 16, 0x8005);
    std::vector<uint8_t> b = {uint8_t((~pid & 15) << 4 | pid)};
    b.insert(b.end(), payload.begin(), payload.end());
    std::vector<uint8_t> cb = bytes_of_bits(c);
    b.insert(b.end(), cb.begin(), cb.end());
    return b;
}
