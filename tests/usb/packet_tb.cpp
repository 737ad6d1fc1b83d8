// packet_tb: the USB low-speed host's packet layer (soc_rtl/usb/usb_ls_packet_tx.v,
// usb_ls_packet_rx.v, with usb_pkg's CRCs) on the line layer, through tests/usb/usb_packet_top.v:
//   - the reference (tests/usb/usb_ref.h, bit-serial CRCs written from USB 1.1 8.3.5) against
//     the USB-IF white paper "Cyclic Redundancy Checks in USB" (crcdes.pdf): its token examples
//     (fields and CRC5 in the order sent) and its CRC16 examples; the residuals 01100 and 0x800D;
//     the CRC catalogue's check values of CRC-5/USB (0x19) and CRC-16/USB (0xB4C8) over "123456789";
//   - the RTL's packets decoded from the wire (NRZI, SYNC, destuffing by the reference decoder):
//     the same three tokens bit for bit; SETUP to address 0 is 2D 00 10; the white paper's data
//     packets; GET_DESCRIPTOR(device) is C3 80 06 00 01 00 00 40 00 DD 94; an empty DATA1 is
//     4B 00 00; random tokens, data packets (0..8 bytes) and handshakes equal the reference's bytes;
//   - each looped into usb_ls_packet_rx: PID, payload and length, pkt_ok;
//   - usb_ls_packet_rx on a reference waveform: a bad check nibble, a flipped payload bit, a wrong
//     CRC5, a handshake with an extra byte, a data packet of 2 bytes, a token of 2, a line error,
//     an empty packet: each flagged, never pkt_ok.
//     packet_tb [SEED]      (built by tests/usb/line.sh)
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>
#include <vector>

#include "Vusb_packet_top.h"
#include "verilated.h"

#include "usb_ref.h"

static long failures = 0, checks = 0;
#define CHECK(cond, ...)                                                      \
    do {                                                                      \
        checks++;                                                             \
        if (!(cond)) {                                                        \
            if (++failures <= 30) {                                           \
                std::printf("packet_tb: FAIL %s:%d: ", __FILE__, __LINE__);   \
                std::printf(__VA_ARGS__);                                     \
                std::printf("\n");                                            \
            }                                                                 \
        }                                                                     \
    } while (0)

enum { PID_OUT = 0x1, PID_IN = 0x9, PID_SETUP = 0xD, PID_DATA0 = 0x3, PID_DATA1 = 0xB, PID_ACK = 0x2,
       PID_NAK = 0xA, PID_STALL = 0xE };

static std::vector<int> bits_of(const std::string &s)
{
    std::vector<int> b;
    for (char c : s) b.push_back(c == '1');
    return b;
}
static std::string str_of(const std::vector<int> &b, size_t from, size_t n)
{
    std::string s;
    for (size_t i = from; i < from + n && i < b.size(); i++) s += char('0' + b[i]);
    return s;
}
static std::string hex(const std::vector<uint8_t> &b)
{
    std::string s;
    char t[4];
    for (uint8_t v : b) {
        std::snprintf(t, sizeof t, "%02X ", v);
        s += t;
    }
    return s;
}

struct Pkt {
    int pid = 0, len = 0;
    bool ok = false, line = false, epid = false, elen = false, ecrc = false;
    std::vector<uint8_t> payload;
};

struct Tb {
    Vusb_packet_top *t = new Vusb_packet_top;
    uint64_t cyc = 0;
    std::vector<Sym> wire;               // wire[c]: the host's drive in clock c
    std::vector<uint8_t> payload;        // the pl_* stream
    size_t pl_at = 0;
    bool cmd = false;
    int cmd_pid = 0, cmd_addr = 0, cmd_endp = 0, cmd_len = 0;
    Wave wave;
    bool have_wave = false;
    std::vector<uint8_t> dat;            // dat_valid bytes since the last verdict
    std::vector<Pkt> got;

    Tb()
    {
        wire.push_back(Z);
        t->rst = 1;
        for (int i = 0; i < 4; i++) tick();
        t->rst = 0;
    }
    void tick()
    {
        t->clk = 0;
        int dp = 0, dn = 1;
        if (have_wave && wave.active(double(cyc) + 0.5)) wave_lines(wave, double(cyc) + 0.5, dp, dn);
        if (t->usb_oe) {
            dp = t->usb_dp_out;
            dn = t->usb_dn_out;
        }
        t->usb_dp_in = dp;
        t->usb_dn_in = dn;
        t->tx_active = 0;                // the receiver sees the host's own packets: a loopback
        t->cmd_valid = cmd;
        t->cmd_pid = cmd_pid;
        t->cmd_addr = cmd_addr;
        t->cmd_endp = cmd_endp;
        t->cmd_len = cmd_len;
        t->pl_valid = pl_at < payload.size();
        t->pl_data = pl_at < payload.size() ? payload[pl_at] : 0;
        t->eval();
        if (t->cmd_valid && t->cmd_ready) cmd = false;
        if (t->pl_valid && t->pl_ready) pl_at++;
        t->clk = 1;
        t->eval();
        cyc++;
        Sym s = Z;
        if (t->usb_oe) {
            s = t->usb_dp_out && !t->usb_dn_out ? K : !t->usb_dp_out && t->usb_dn_out ? J
                : !t->usb_dp_out && !t->usb_dn_out ? SE0 : SE1;
        }
        wire.push_back(s);
        CHECK(!t->tx_underrun, "underrun");
        if (t->dat_valid) dat.push_back(t->dat_data);
        if (t->pkt_valid) {
            Pkt p;
            p.pid = t->pkt_pid;
            p.len = t->pkt_len;
            p.ok = t->pkt_ok;
            p.line = t->err_line;
            p.epid = t->err_pid;
            p.elen = t->err_len;
            p.ecrc = t->err_crc;
            p.payload = dat;
            dat.clear();
            got.push_back(p);
        }
    }
    void run_until(uint64_t c)
    {
        while (cyc < c) tick();
    }
    // One packet from the RTL; returns the host's wire as one symbol per bit.
    std::vector<Sym> send(int pid, int addr, int endp, const std::vector<uint8_t> &pl)
    {
        size_t from = wire.size();
        cmd = true;
        cmd_pid = pid;
        cmd_addr = addr;
        cmd_endp = endp;
        cmd_len = int(pl.size());
        payload = pl;
        pl_at = 0;
        do {
            tick();
        } while (cmd || t->pkt_busy || !t->tx_idle);
        for (int i = 0; i < 60; i++) tick();
        size_t s = from;
        while (s < wire.size() && wire[s] == Z) s++;
        std::vector<Sym> bits;
        for (uint64_t k = 0;; k++) {
            uint64_t c = s + (bit_start(k) + bit_start(k + 1)) / 2;
            if (c >= wire.size() || wire[c] == Z) break;
            bits.push_back(wire[c]);
        }
        return bits;
    }
};

// The bytes of a packet from the host's wire, by the reference decoder.
static std::vector<uint8_t> wire_bytes(const std::vector<Sym> &syms, std::vector<int> *bits_out = nullptr)
{
    bool ok = false;
    std::vector<int> bits = decode_bits(syms, &ok);
    CHECK(ok, "the wire's SYNC or stuffing is wrong");
    CHECK(bits.size() % 8 == 0, "%zu bits on the wire", bits.size());
    size_t e = 0;
    while (e < syms.size() && syms[e] != SE0) e++;
    CHECK(e + 3 == syms.size() && syms[e + 1] == SE0 && syms[e + 2] == J, "the EOP is not SE0 SE0 J");
    if (bits_out) *bits_out = bits;
    return bytes_of_bits(bits);
}

// ---- the reference against the white paper and the catalogue ----
struct TokEx { int pid, addr, endp; const char *field, *crc; };
static const TokEx TOKENS[] = {
    {PID_SETUP, 0x15, 0xE, "10101000111", "10111"},   // "setup addr 15 endp e"
    {PID_OUT, 0x3A, 0xA, "01011100101", "11100"},     // "out addr 3a endp a"
    {PID_IN, 0x70, 0x4, "00001110010", "01110"},      // "in addr 70 endp 4"
};
struct DatEx { std::vector<uint8_t> data; const char *crc; };
static const DatEx DATAS[] = {
    {{0x00, 0x01, 0x02, 0x03}, "1111011101011110"},
    {{0x23, 0x45, 0x67, 0x89}, "0111000000111000"},
};

static void test_reference()
{
    for (const TokEx &e : TOKENS) {
        std::vector<int> f = bits_of(e.field);
        std::vector<int> c = crc_bits(f, 5, 0x05);
        CHECK(str_of(c, 0, 5) == e.crc, "reference CRC5 of %s: %s, paper %s", e.field, str_of(c, 0, 5).c_str(), e.crc);
        std::vector<int> all = f;
        all.insert(all.end(), c.begin(), c.end());
        CHECK(crc_residual(all, 5, 0x05) == 0x0C, "CRC5 residual %x", crc_residual(all, 5, 0x05));
        std::vector<uint8_t> tok = ref_token(e.pid, e.addr, e.endp);
        std::vector<int> tb = bits_lsb_first({tok[1], tok[2]});
        CHECK(str_of(tb, 0, 11) == e.field && str_of(tb, 11, 5) == e.crc, "reference token bytes");
    }
    for (const DatEx &e : DATAS) {
        std::vector<int> c = crc_bits(bits_lsb_first(e.data), 16, 0x8005);
        CHECK(str_of(c, 0, 16) == e.crc, "reference CRC16: %s, paper %s", str_of(c, 0, 16).c_str(), e.crc);
        std::vector<int> all = bits_lsb_first(e.data);
        all.insert(all.end(), c.begin(), c.end());
        CHECK(crc_residual(all, 16, 0x8005) == 0x800D, "CRC16 residual %x", crc_residual(all, 16, 0x8005));
    }
    std::vector<uint8_t> nine = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    std::vector<uint8_t> c5 = bytes_of_bits(crc_bits(bits_lsb_first(nine), 5, 0x05));
    std::vector<uint8_t> c16 = bytes_of_bits(crc_bits(bits_lsb_first(nine), 16, 0x8005));
    CHECK(c5[0] == 0x19, "CRC-5/USB check %02X", c5[0]);
    CHECK((c16[0] | c16[1] << 8) == 0xB4C8, "CRC-16/USB check %04X", c16[0] | c16[1] << 8);
    std::printf("reference: the white paper's 3 token CRC5s and 2 CRC16s, residuals 01100 and 0x800D, "
                "catalogue checks 0x19 and 0xB4C8\n");
}

// ---- the RTL's packets on the wire ----
static void test_tx_packets(int randoms)
{
    Tb tb;
    for (const TokEx &e : TOKENS) {
        std::vector<int> bits;
        std::vector<uint8_t> b = wire_bytes(tb.send(e.pid, e.addr, e.endp, {}), &bits);
        CHECK(str_of(bits, 8, 11) == e.field && str_of(bits, 19, 5) == e.crc, "token %s: wire %s %s", e.field,
              str_of(bits, 8, 11).c_str(), str_of(bits, 19, 5).c_str());
        CHECK(b == ref_token(e.pid, e.addr, e.endp), "token bytes %s", hex(b).c_str());
    }
    std::vector<uint8_t> b = wire_bytes(tb.send(PID_SETUP, 0, 0, {}));
    CHECK(b == std::vector<uint8_t>({0x2D, 0x00, 0x10}), "SETUP 0/0: %s", hex(b).c_str());
    for (const DatEx &e : DATAS) {
        std::vector<int> bits;
        b = wire_bytes(tb.send(PID_DATA0, 0, 0, e.data), &bits);
        CHECK(str_of(bits, 8 + 8 * e.data.size(), 16) == e.crc, "data CRC16 on the wire %s",
              str_of(bits, 8 + 8 * e.data.size(), 16).c_str());
    }
    b = wire_bytes(tb.send(PID_DATA0, 0, 0, {0x80, 0x06, 0x00, 0x01, 0x00, 0x00, 0x40, 0x00}));
    CHECK(b == std::vector<uint8_t>({0xC3, 0x80, 0x06, 0x00, 0x01, 0x00, 0x00, 0x40, 0x00, 0xDD, 0x94}),
          "GET_DESCRIPTOR: %s", hex(b).c_str());
    b = wire_bytes(tb.send(PID_DATA1, 0, 0, {}));
    CHECK(b == std::vector<uint8_t>({0x4B, 0x00, 0x00}), "empty DATA1: %s", hex(b).c_str());
    b = wire_bytes(tb.send(PID_ACK, 0, 0, {}));
    CHECK(b == std::vector<uint8_t>({0xD2}), "ACK: %s", hex(b).c_str());
    size_t looped = tb.got.size();
    int bad = 0;
    for (int i = 0; i < randoms; i++) {
        int kind = irand(0, 2);
        int pid, addr = irand(0, 127), endp = irand(0, 15);
        std::vector<uint8_t> pl, want;
        if (kind == 0) {
            static const int t[] = {PID_OUT, PID_IN, PID_SETUP};
            pid = t[irand(0, 2)];
            want = ref_token(pid, addr, endp);
        } else if (kind == 1) {
            pid = irand(0, 1) ? PID_DATA1 : PID_DATA0;
            int n = irand(0, 8);
            bool runs = irand(0, 1);
            for (int k = 0; k < n; k++) pl.push_back(runs && irand(0, 1) ? 0xFF : uint8_t(irand(0, 255)));
            want = ref_data(pid, pl);
        } else {
            static const int h[] = {PID_ACK, PID_NAK, PID_STALL};
            pid = h[irand(0, 2)];
            want = {uint8_t((~pid & 15) << 4 | pid)};
        }
        size_t n0 = tb.got.size();
        b = wire_bytes(tb.send(pid, addr, endp, pl));
        CHECK(b == want, "random packet %d: wire %s, reference %s", i, hex(b).c_str(), hex(want).c_str());
        // looped back into usb_ls_packet_rx
        bool ok = tb.got.size() == n0 + 1;
        if (ok) {
            const Pkt &p = tb.got.back();
            ok = p.ok && !p.line && !p.epid && !p.elen && !p.ecrc && p.pid == pid && p.len == int(pl.size()) &&
                 p.payload == pl;
        }
        CHECK(ok, "random packet %d (PID %x, %zu bytes) not checked good by usb_ls_packet_rx", i, pid, pl.size());
        bad += !ok;
    }
    std::printf("tx: tokens bit for bit as the white paper's; 2D 00 10; its CRC16s; GET_DESCRIPTOR ... DD 94; "
                "4B 00 00; D2; %d random packets equal the reference's bytes, %d of %zu looped back good\n",
                randoms, randoms - bad, tb.got.size() - looped);
}

// ---- usb_ls_packet_rx's errors, from reference waveforms ----
static Pkt rx_bytes(const std::vector<uint8_t> &bytes, std::vector<Sym> syms = {})
{
    Tb tb;
    if (syms.empty()) syms = packet_symbols(bytes);
    tb.wave = make_wave(syms, 20.5, N_BIT, 1.0, 0.0);
    tb.have_wave = true;
    tb.run_until(uint64_t(tb.wave.end) + 20 * uint64_t(N_BIT));
    CHECK(tb.got.size() == 1, "%zu verdicts for one packet", tb.got.size());
    return tb.got.empty() ? Pkt() : tb.got[0];
}

static void test_rx_errors()
{
    std::vector<uint8_t> good = ref_data(PID_DATA1, {0x01, 0x02, 0x03, 0xFF, 0x00});
    Pkt p = rx_bytes(good);
    CHECK(p.ok && p.pid == PID_DATA1 && p.len == 5 && p.payload == std::vector<uint8_t>({1, 2, 3, 0xFF, 0}),
          "good DATA1 not accepted");
    std::vector<uint8_t> bad = good;
    bad[0] ^= 0x80;                      // the check nibble
    p = rx_bytes(bad);
    CHECK(!p.ok && p.epid && !p.ecrc, "bad check nibble: ok %d pid %d", p.ok, p.epid);
    bad = good;
    bad[3] ^= 0x10;                      // a payload bit
    p = rx_bytes(bad);
    CHECK(!p.ok && p.ecrc && !p.epid && !p.elen, "flipped payload bit: ok %d crc %d", p.ok, p.ecrc);
    std::vector<uint8_t> tok = ref_token(PID_IN, 0x12, 0x1);
    p = rx_bytes(tok);
    CHECK(p.ok && p.pid == PID_IN && p.len == 0 && p.payload.empty(), "good IN token not accepted");
    tok[2] ^= 0x40;                      // a CRC5 bit
    p = rx_bytes(tok);
    CHECK(!p.ok && p.ecrc, "wrong CRC5: ok %d crc %d", p.ok, p.ecrc);
    p = rx_bytes({0xD2, 0x00});
    CHECK(!p.ok && p.elen && p.pid == PID_ACK, "ACK of 2 bytes: ok %d len %d", p.ok, p.elen);
    p = rx_bytes({0xD2});
    CHECK(p.ok && p.pid == PID_ACK, "ACK not accepted");
    p = rx_bytes({0x4B, 0x00});
    CHECK(!p.ok && p.elen, "DATA1 of 2 bytes: ok %d len %d", p.ok, p.elen);
    p = rx_bytes({0x69, 0x00});
    CHECK(!p.ok && p.elen, "token of 2 bytes: ok %d len %d", p.ok, p.elen);
    // a line error: 3 bits after the last byte, then the EOP
    std::vector<int> bits = SYNC;
    std::vector<int> d = bits_lsb_first(good);
    bits.insert(bits.end(), d.begin(), d.end());
    bits.insert(bits.end(), {0, 1, 0});
    std::vector<Sym> s = nrzi(stuff_bits(bits));
    s.insert(s.end(), {SE0, SE0, J});
    p = rx_bytes({}, s);
    CHECK(!p.ok && p.line, "line error: ok %d line %d", p.ok, p.line);
    std::vector<Sym> empty = nrzi(SYNC);
    empty.insert(empty.end(), {SE0, SE0, J});
    p = rx_bytes({}, empty);
    CHECK(!p.ok && p.epid && p.pid == 0, "empty packet: ok %d pid %d", p.ok, p.epid);
    std::printf("rx: good DATA1, IN, ACK accepted; bad check nibble, flipped payload bit, wrong CRC5, ACK of 2 "
                "bytes, DATA1 of 2, token of 2, a line error, an empty packet each flagged\n");
}

int main(int argc, char **argv)
{
    Verilated::commandArgs(argc, argv);
    rng.seed(argc > 1 ? std::strtoul(argv[1], nullptr, 0) : 1);
    test_reference();
    test_tx_packets(300);
    test_rx_errors();
    std::printf("packet_tb: %ld checks, %ld failed\n", checks, failures);
    return failures ? 1 : 0;
}
