// line_tb: the USB low-speed host's line layer (soc_rtl/usb/usb_ls_tx.v, usb_ls_rx.v) through
// tests/usb/usb_line_top.v, against a reference written here from the USB 1.1 specification (not
// from the RTL): SYNC, bit stuffing counted from the SYNC's last 1, NRZI, EOP.
//   - the transmitter's wire, clock by clock, against the reference encoder placed on the ideal
//     bit grid (bit k starts at the clock nearest k * SYS_HZ / 1.5 MHz): random packets of 1..11
//     bytes, runs of 1s that need stuffing across bytes and before the EOP, the source stalling up
//     to 7.5 bit times before each byte; the average rate exactly 1.5 Mb/s over every packet; the
//     largest error of an interval between transitions (consecutive and paired) in ns; the EOP's
//     SE0 in 1.25..1.50 us; the keep-alive EOP and the bus reset;
//   - each packet looped into the receiver (the pull-up's J when nothing drives) byte-exact;
//   - the receiver fed by a reference waveform at the nominal rate, +1.5 % and -1.5 %, each edge
//     moved by up to a system clock, D- skewed against D+ by up to 200 ns (the SE0/SE1 of a
//     differential transition, TLST 210 ns), and at +-1.5 % with +-70 ns of edge jitter;
//   - the receiver's errors: seven 1s, a missing last stuff bit, an EOP off a byte boundary, an
//     SE0 then K, an SE0 of 5 bit times, a packet over 11 bytes, babble, a false SYNC; an empty
//     packet; the turnaround timeout (16..18 bit times after the SE0-to-J) after a device's EOP
//     and the host's own, the receiver gated by the host's drive and a device answering 2 bit
//     times after the host's EOP; an underrun made invalid (seven 1s) and flushed.
//     line_tb [SEED]      (built by tests/usb/line.sh with -DTB_SYS_HZ=...)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "Vusb_line_top.h"
#include "verilated.h"

#include "usb_ref.h"

static long failures = 0, checks = 0;
#define CHECK(cond, ...)                                    \
    do {                                                    \
        checks++;                                           \
        if (!(cond)) {                                      \
            if (++failures <= 30) {                         \
                std::printf("line_tb: FAIL %s:%d: ", __FILE__, __LINE__); \
                std::printf(__VA_ARGS__);                   \
                std::printf("\n");                          \
            }                                               \
        }                                                   \
    } while (0)

// ---- the simulation ----
struct RxPkt {
    std::vector<uint8_t> bytes;
    bool stuff = false, align = false, se0 = false, lng = false;
    uint64_t start = 0, end = 0;
    bool ok() const { return !stuff && !align && !se0 && !lng; }
};

struct Tb {
    Vusb_line_top *t = new Vusb_line_top;
    uint64_t cyc = 0;
    bool gate = false;                          // tx_active = usb_oe
    std::vector<Wave> waves;                    // the device's drive
    std::deque<std::pair<uint8_t, bool>> q;     // the transmitter's stream: byte, last
    int max_stall = 0, stall = 0;
    std::vector<Sym> wire;                      // the host's drive, a symbol per clock
    std::vector<RxPkt> rx;
    bool in_pkt = false;
    uint64_t underruns = 0, timeouts = 0, dones = 0;
    std::vector<uint64_t> timeout_at;
    bool babble_seen = false;
    bool eop_pulse = false, reset_pulse = false;
    uint32_t reset_clks = 0;

    Tb()
    {
        wire.push_back(Z);                      // cycle 0: wire[c] is the host's drive in clock c
        t->rst = 1;
        for (int i = 0; i < 4; i++) tick();
        t->rst = 0;
    }
    Sym host_sym() const
    {
        if (!t->usb_oe) return Z;
        if (t->usb_dp_out && !t->usb_dn_out) return K;
        if (!t->usb_dp_out && t->usb_dn_out) return J;
        if (!t->usb_dp_out && !t->usb_dn_out) return SE0;
        return SE1;
    }
    void tick()
    {
        t->clk = 0;
        // the bus in this clock: the host's drive, else a device's, else the pull-up's J
        int dp = 0, dn = 1;
        bool dev = false;
        for (const Wave &w : waves) {
            if (w.active(double(cyc) + 0.5)) {
                wave_lines(w, double(cyc) + 0.5, dp, dn);
                dev = true;
            }
        }
        if (t->usb_oe) {
            CHECK(!dev, "cycle %llu: host and device drive together", (unsigned long long)cyc);
            dp = t->usb_dp_out;
            dn = t->usb_dn_out;
        }
        t->usb_dp_in = dp;
        t->usb_dn_in = dn;
        t->tx_active = gate && t->usb_oe;
        if (stall > 0) stall--;
        t->tx_valid = !q.empty() && stall == 0;
        t->tx_data = q.empty() ? 0 : q.front().first;
        t->tx_last = q.empty() ? 0 : q.front().second;
        t->eop_start = eop_pulse;
        t->reset_start = reset_pulse;
        t->reset_clks = reset_clks;
        eop_pulse = reset_pulse = false;
        t->eval();
        if (t->tx_valid && t->tx_ready) {
            q.pop_front();
            stall = max_stall ? irand(0, max_stall) : 0;
        }
        t->clk = 1;
        t->eval();
        cyc++;
        wire.push_back(host_sym());
        if (t->tx_underrun) underruns++;
        if (t->tx_done) dones++;
        if (t->rx_timeout) {
            timeouts++;
            timeout_at.push_back(cyc);
        }
        if (t->rx_babble) babble_seen = true;
        if (t->rx_start) {
            CHECK(!in_pkt, "rx_start inside a packet");
            in_pkt = true;
            rx.push_back(RxPkt());
            rx.back().start = cyc;
        }
        if (t->rx_valid) {
            CHECK(in_pkt, "rx_valid outside a packet");
            if (in_pkt) rx.back().bytes.push_back(t->rx_data);
        }
        if (t->rx_end) {
            CHECK(in_pkt && !t->rx_valid && !t->rx_start, "rx_end without its packet");
            if (in_pkt) {
                RxPkt &p = rx.back();
                p.stuff = t->rx_err_stuff;
                p.align = t->rx_err_align;
                p.se0 = t->rx_err_se0;
                p.lng = t->rx_err_long;
                p.end = cyc;
            }
            in_pkt = false;
        } else {
            CHECK(!t->rx_err_stuff && !t->rx_err_align && !t->rx_err_se0 && !t->rx_err_long,
                  "an error flag without rx_end");
        }
    }
    void run(uint64_t n)
    {
        for (uint64_t i = 0; i < n; i++) tick();
    }
    void send(const std::vector<uint8_t> &bytes)
    {
        for (size_t i = 0; i < bytes.size(); i++) q.push_back({bytes[i], i + 1 == bytes.size()});
    }
    // until the transmitter is idle again (its stream empty)
    void run_tx()
    {
        while (!q.empty() || !t->tx_idle) tick();
    }
};

// A random packet: lengths 1..11; often long runs of 1s (0xFF, 0x7F, 0xFE ...).
static std::vector<uint8_t> random_packet(int len)
{
    static const uint8_t ones[] = {0xFF, 0x7F, 0xFE, 0x3F, 0xFC, 0xFF, 0xEF};
    std::vector<uint8_t> b;
    bool runs = irand(0, 1);
    for (int i = 0; i < len; i++) {
        b.push_back(runs && irand(0, 2) ? ones[irand(0, 6)] : uint8_t(irand(0, 255)));
    }
    return b;
}

// ---- 1. the transmitter's wire against the reference, and looped into the receiver ----
static double worst_next_ns = 0, worst_paired_ns = 0;
static void check_tx_wire(Tb &tb, uint64_t from, const std::vector<Sym> &expect, const char *what)
{
    // the first clock the host drives
    uint64_t s = from;
    while (s < tb.wire.size() && tb.wire[s] == Z) s++;
    CHECK(s < tb.wire.size(), "%s: the host never drove", what);
    if (s >= tb.wire.size()) return;
    uint64_t n = expect.size();
    bool ok = true;
    for (uint64_t k = 0; k < n && ok; k++) {
        for (uint64_t c = bit_start(k); c < bit_start(k + 1); c++) {
            if (s + c >= tb.wire.size() || tb.wire[s + c] != expect[k]) {
                CHECK(false, "%s: bit %llu (%s) clock %llu of it: wire %s", what, (unsigned long long)k,
                      sym_name(expect[k]), (unsigned long long)(c - bit_start(k)),
                      s + c < tb.wire.size() ? sym_name(tb.wire[s + c]) : "?");
                ok = false;
                break;
            }
        }
    }
    CHECK(ok, "%s: the wire differs from the reference", what);
    uint64_t len = bit_start(n);
    CHECK(s + len < tb.wire.size() && tb.wire[s + len] == Z, "%s: not released after the EOP's J", what);
    // the average rate: n bits in n * N clocks, to half a clock
    CHECK(std::fabs(double(len) - double(n) * N_BIT) <= 0.5, "%s: %llu bits in %llu clocks", what,
          (unsigned long long)n, (unsigned long long)len);
    // the EOP's SE0 (TLEOPT 1.25..1.50 us)
    uint64_t se0 = 0;
    for (uint64_t c = s; c < s + len; c++) se0 += tb.wire[c] == SE0;
    double se0_ns = double(se0) * NS_PER_CLK;
    CHECK(se0_ns >= 1250 && se0_ns <= 1500, "%s: EOP SE0 %.0f ns", what, se0_ns);
    // interval errors between transitions: consecutive and paired (the next transition but one)
    std::vector<std::pair<uint64_t, uint64_t>> tr;    // (clock, bit index)
    for (uint64_t k = 1; k < n; k++) {
        if (expect[k] != expect[k - 1]) tr.push_back({bit_start(k), k});
    }
    for (size_t i = 0; i + 1 < tr.size(); i++) {
        for (size_t d = 1; d <= 2 && i + d < tr.size(); d++) {
            double got = double(tr[i + d].first - tr[i].first);
            double ideal = double(tr[i + d].second - tr[i].second) * N_BIT;
            double err = std::fabs(got - ideal) * NS_PER_CLK;
            double &worst = d == 1 ? worst_next_ns : worst_paired_ns;
            worst = std::max(worst, err);
        }
    }
}

static void test_tx_loopback(int packets)
{
    Tb tb;
    int stalled = 0;
    for (int p = 0; p < packets; p++) {
        std::vector<uint8_t> bytes = random_packet(1 + p % 11);
        tb.max_stall = (p & 1) ? int(7.5 * N_BIT) : 0;    // under a byte time (8 bit times)
        stalled += (p & 1);
        uint64_t from = tb.wire.size();
        size_t nrx = tb.rx.size();
        tb.send(bytes);
        tb.run_tx();
        tb.run(irand(70, 200));          // idle between packets
        char what[64];
        std::snprintf(what, sizeof what, "tx packet %d (%zu bytes)", p, bytes.size());
        check_tx_wire(tb, from, packet_symbols(bytes), what);
        CHECK(tb.rx.size() == nrx + 1, "%s: %zu packets received", what, tb.rx.size() - nrx);
        if (tb.rx.size() == nrx + 1) {
            const RxPkt &r = tb.rx.back();
            CHECK(r.ok() && r.bytes == bytes, "%s: received %zu bytes, flags %d%d%d%d", what, r.bytes.size(),
                  r.stuff, r.align, r.se0, r.lng);
        }
    }
    CHECK(tb.underruns == 0, "an underrun with stalls below a byte time");
    std::printf("tx: %d packets (1..11 bytes, %d with the source stalling up to 7.5 bit times a byte) equal the "
                "reference clock by clock and loop back byte-exact; worst interval error %.1f ns to the next "
                "transition, %.1f ns paired (limits 25, 14)\n",
                packets, stalled, worst_next_ns, worst_paired_ns);
    CHECK(worst_next_ns <= 25.0 && worst_paired_ns <= 14.0, "jitter over the limits");
}

// The keep-alive EOP and the bus reset.
static void test_tx_eop_and_reset()
{
    Tb tb;
    tb.run(10);
    uint64_t from = tb.wire.size();
    tb.eop_pulse = true;
    tb.run(uint64_t(4 * N_BIT) + 20);
    check_tx_wire(tb, from, {SE0, SE0, J}, "keep-alive EOP");
    const uint32_t clks[] = {1, 7, 5000, 500000};     // 500000: 10 ms at 50 MHz
    for (uint32_t n : clks) {
        from = tb.wire.size();
        tb.reset_clks = n;
        tb.reset_pulse = true;
        tb.run(n + uint64_t(2 * N_BIT) + 20);
        uint64_t s = from;
        while (tb.wire[s] == Z) s++;
        uint64_t se0 = 0;
        while (tb.wire[s + se0] == SE0) se0++;
        uint64_t j = 0;
        while (tb.wire[s + se0 + j] == J) j++;
        CHECK(se0 == n && j == bit_start(1) && tb.wire[s + se0 + j] == Z, "reset %u: SE0 %llu, J %llu clocks", n,
              (unsigned long long)se0, (unsigned long long)j);
    }
    // a request while busy is ignored; reset wins over a packet in the same clock
    from = tb.wire.size();
    tb.send({0xD2});
    tb.reset_clks = 40;
    tb.reset_pulse = true;
    tb.tick();
    tb.run_tx();
    tb.run(100);
    uint64_t s = from;
    while (tb.wire[s] == Z) s++;
    CHECK(tb.wire[s] == SE0, "reset did not win over a packet");
    std::printf("tx: keep-alive EOP (SE0 %llu clocks, J %llu), resets of 1, 7, 5000, 500000 clocks exact\n",
                (unsigned long long)bit_start(2), (unsigned long long)(bit_start(3) - bit_start(2)));
}

// ---- 2. the receiver from reference waveforms ----
static int rx_run(const char *what, double rate, double jitter, double skew, int packets)
{
    Tb tb;
    double period = N_BIT / rate;
    int good = 0;
    for (int p = 0; p < packets; p++) {
        std::vector<uint8_t> bytes = random_packet(1 + p % 11);
        double start = double(tb.cyc) + 20 + urand(0, 1);
        tb.waves = {make_wave(packet_symbols(bytes), start, period, jitter, skew)};
        size_t nrx = tb.rx.size();
        tb.run(uint64_t(tb.waves[0].end - double(tb.cyc)) + 60);
        bool ok = tb.rx.size() == nrx + 1 && tb.rx.back().ok() && tb.rx.back().bytes == bytes;
        CHECK(ok, "%s: packet %d (%zu bytes) not received", what, p, bytes.size());
        good += ok;
    }
    std::printf("rx: %s: %d of %d packets byte-exact\n", what, good, packets);
    return good;
}

static RxPkt rx_one(const std::vector<Sym> &syms, size_t *count = nullptr, double rate = 1.0)
{
    Tb tb;
    tb.waves = {make_wave(syms, 30.25, N_BIT / rate, 1.0, 0.0)};
    tb.run(uint64_t(tb.waves[0].end) + 40 * uint64_t(N_BIT));
    if (count) *count = tb.rx.size();
    return tb.rx.empty() ? RxPkt() : tb.rx.back();
}

static std::vector<Sym> raw_symbols(std::vector<int> bits, bool do_stuff, int eop_se0 = 2, Sym after = J)
{
    std::vector<int> all = SYNC;
    all.insert(all.end(), bits.begin(), bits.end());
    std::vector<Sym> s = nrzi(do_stuff ? stuff_bits(all) : all);
    for (int i = 0; i < eop_se0; i++) s.push_back(SE0);
    s.push_back(after);
    return s;
}

static void test_rx_errors()
{
    std::vector<int> pid = bits_lsb_first({0xC3});
    size_t n = 0;
    // seven 1s without the stuffed 0
    std::vector<int> b = pid;
    for (int i = 0; i < 7; i++) b.push_back(1);
    b.push_back(0);
    RxPkt r = rx_one(raw_symbols(b, false), &n);
    CHECK(n == 1 && r.stuff && !r.align && r.bytes.size() == 1, "seven 1s: n %zu stuff %d", n, r.stuff);
    // the last stuff bit left out: a byte ending in six 1s, EOP right after
    std::vector<int> all = SYNC;
    std::vector<int> d = bits_lsb_first({0xC3, 0xFC});
    all.insert(all.end(), d.begin(), d.end());
    std::vector<int> st = stuff_bits(all);
    CHECK(st.back() == 0, "the reference stuffs the last bit");
    st.pop_back();
    std::vector<Sym> s = nrzi(st);
    s.insert(s.end(), {SE0, SE0, J});
    r = rx_one(s, &n);
    CHECK(n == 1 && r.stuff && r.bytes.size() == 2, "missing last stuff bit: n %zu stuff %d", n, r.stuff);
    // the same with it: good
    r = rx_one(packet_symbols({0xC3, 0xFC}), &n);
    CHECK(n == 1 && r.ok() && r.bytes.size() == 2, "last stuff bit present: not received");
    // EOP after 8k+3 bits
    b = bits_lsb_first({0xC3, 0x12});
    b.insert(b.end(), {1, 0, 1});
    r = rx_one(raw_symbols(b, true), &n);
    CHECK(n == 1 && r.align && !r.stuff && r.bytes.size() == 2, "EOP off a byte boundary: n %zu align %d", n, r.align);
    // SE0 in mid-packet: SE0 for a bit, then K
    r = rx_one(raw_symbols(bits_lsb_first({0xC3, 0x55}), true, 1, K), &n);
    CHECK(n == 1 && r.se0, "SE0 then K: n %zu se0 %d", n, r.se0);
    // SE0 for 5 bit times (a reset, not an EOP)
    r = rx_one(raw_symbols(bits_lsb_first({0xC3, 0x55}), true, 5, J), &n);
    CHECK(n == 1 && r.se0, "long SE0: n %zu se0 %d", n, r.se0);
    // 12 bytes: 11 delivered, then rx_err_long
    std::vector<uint8_t> twelve = random_packet(12);
    r = rx_one(packet_symbols(twelve), &n);
    CHECK(n == 1 && r.lng && r.bytes.size() == 11 &&
              std::equal(r.bytes.begin(), r.bytes.end(), twelve.begin()),
          "12 bytes: n %zu long %d bytes %zu", n, r.lng, r.bytes.size());
    // babble: 40 bytes without an EOP, then the line released
    {
        Tb tb;
        std::vector<Sym> bab = packet_symbols(random_packet(40), false);
        tb.waves = {make_wave(bab, 30.5, N_BIT, 1.0, 0.0)};
        tb.run(uint64_t(tb.waves[0].end) + 20 * uint64_t(N_BIT));
        bool fell = !tb.t->rx_babble;
        CHECK(tb.babble_seen && fell && tb.rx.size() == 1 && tb.rx[0].lng, "babble: seen %d fell %d",
              tb.babble_seen, fell);
        // and a good packet after it is received
        std::vector<uint8_t> ok = {0x4B, 0x01, 0x02};
        tb.waves = {make_wave(packet_symbols(ok), double(tb.cyc) + 10.5, N_BIT, 1.0, 0.0)};
        tb.run(200 * uint64_t(N_BIT));
        CHECK(tb.rx.size() == 2 && tb.rx[1].ok() && tb.rx[1].bytes == ok, "no packet after babble");
    }
    // a false SYNC (a 1 after two 0s): no packet
    std::vector<Sym> fake = nrzi({0, 0, 1, 0, 1, 0, 1, 1, 0, 1, 0});
    fake.insert(fake.end(), {SE0, SE0, J});
    rx_one(fake, &n);
    CHECK(n == 0, "false SYNC: %zu packets", n);
    // an empty packet: SYNC and EOP
    r = rx_one(raw_symbols({}, true), &n);
    CHECK(n == 1 && r.ok() && r.bytes.empty(), "empty packet: n %zu", n);
    std::printf("rx: errors flagged: seven 1s, missing last stuff bit, EOP off a byte boundary, SE0 then K, "
                "SE0 of 5 bits, 12 bytes (11 delivered), babble (and a packet after it), false SYNC ignored, "
                "empty packet\n");
}

// ---- 3. the turnaround timeout, the gate, an answer 2 bit times after the host's EOP ----
static void test_timeout_and_gate()
{
    Tb tb;
    tb.gate = true;
    tb.run(50);
    // a device's packet: the timeout 16..18 bit times after its SE0-to-J on the pins
    std::vector<Sym> dev = packet_symbols({0x4B, 0x10, 0x20});
    tb.waves = {make_wave(dev, double(tb.cyc) + 5.5, N_BIT, 0.0, 0.0)};
    uint64_t before = tb.timeouts;
    tb.run(uint64_t(tb.waves[0].end - double(tb.cyc)) + 30 * uint64_t(N_BIT));
    double se0_to_j = tb.waves[0].dp_edge[dev.size() - 1];
    CHECK(tb.timeouts == before + 1, "device EOP: %llu timeouts", (unsigned long long)(tb.timeouts - before));
    double bits = (double(tb.timeout_at.back()) - se0_to_j) / N_BIT;
    CHECK(bits >= 16.0 && bits <= 18.0, "device EOP: timeout after %.2f bit times", bits);
    std::printf("rx: turnaround timeout %.2f bit times after a device's SE0-to-J (16..18)\n", bits);
    // the host's own packet: the receiver is gated (nothing received), the timeout still runs
    size_t nrx = tb.rx.size();
    uint64_t from = tb.wire.size();
    tb.send({0x69, 0x00, 0x10});
    tb.run_tx();
    uint64_t j_at = from;
    while (!(tb.wire[j_at] == J && tb.wire[j_at - 1] == SE0)) j_at++;
    tb.run(30 * uint64_t(N_BIT));
    CHECK(tb.rx.size() == nrx, "the host's own packet was received");
    bits = (double(tb.timeout_at.back()) - double(j_at)) / N_BIT;
    CHECK(bits >= 16.0 && bits <= 18.0, "host EOP: timeout after %.2f bit times", bits);
    std::printf("rx: gated during the host's packet; turnaround timeout %.2f bit times after its SE0-to-J\n", bits);
    // a device answering 2 bit times after the host's EOP (the shortest inter-packet gap)
    tb.send({0x69, 0x00, 0x10});
    from = tb.wire.size();
    for (;;) {
        tb.tick();
        if (tb.wire.size() > 2 && tb.wire.back() == J && tb.wire[tb.wire.size() - 2] == SE0) break;
    }
    double eop_j = double(tb.wire.size() - 1);
    std::vector<uint8_t> ans = {0xC3, 0x00, 0x00};
    tb.waves = {make_wave(packet_symbols(ans), eop_j + 2 * N_BIT, N_BIT, 1.0, 0.0)};
    nrx = tb.rx.size();
    uint64_t t0 = tb.timeouts;
    tb.run(uint64_t(tb.waves[0].end - double(tb.cyc)) + 40 * uint64_t(N_BIT));
    CHECK(tb.rx.size() == nrx + 1 && tb.rx.back().ok() && tb.rx.back().bytes == ans,
          "answer 2 bit times after the host's EOP not received");
    CHECK(tb.timeouts == t0 + 1, "the answer's own EOP gives one timeout: %llu", (unsigned long long)(tb.timeouts - t0));
    std::printf("rx: a device answering 2 bit times after the host's EOP received\n");
}

// ---- 4. an underrun: the packet invalid for the receiver, its rest flushed ----
static void test_underrun()
{
    Tb tb;
    tb.run(20);
    uint64_t from = tb.wire.size();
    tb.q.push_back({0xC3, false});
    tb.q.push_back({0x01, false});
    tb.run(uint64_t(30 * N_BIT));          // the source stops after two bytes
    CHECK(tb.underruns == 1, "underrun not flagged: %llu", (unsigned long long)tb.underruns);
    CHECK(!tb.t->tx_idle, "idle before the flush");
    tb.q.push_back({0x02, false});
    tb.q.push_back({0x03, true});
    tb.run_tx();
    tb.run(40);
    // the wire: the two bytes, then at least seven bit times without a transition, then SE0
    uint64_t s = from;
    while (tb.wire[s] == Z) s++;
    uint64_t e = s;
    while (tb.wire[e] != SE0) e++;
    uint64_t run = 0;
    while (tb.wire[e - 1 - run] == tb.wire[e - 1]) run++;
    CHECK(double(run) >= 7 * N_BIT - 1, "the level before the EOP lasted only %.2f bits", double(run) / N_BIT);
    CHECK(tb.rx.size() == 1 && tb.rx[0].stuff, "the receiver did not flag the aborted packet");
    // the flushed bytes did not start a packet
    tb.run(200);
    uint64_t pkts = 0;
    for (uint64_t c = s + 1; c < tb.wire.size(); c++) pkts += tb.wire[c] != Z && tb.wire[c - 1] == Z;
    CHECK(pkts == 0 && tb.t->tx_idle, "the rest of the packet was sent after the underrun");
    std::printf("tx: underrun flagged, %.1f bit times without a transition before the EOP (receiver: "
                "bit-stuff error), the packet's rest flushed\n", double(run) / N_BIT);
}

int main(int argc, char **argv)
{
    Verilated::commandArgs(argc, argv);
    rng.seed(argc > 1 ? std::strtoul(argv[1], nullptr, 0) : 1);
    std::printf("line_tb: SYS_HZ %llu (a bit %.4f clocks, %llu/%llu)\n", (unsigned long long)SYS_HZ, N_BIT,
                (unsigned long long)NUM, (unsigned long long)DEN);
    test_tx_loopback(440);
    test_tx_eop_and_reset();
    double skew = 200.0 / NS_PER_CLK;   // D- against D+: an SE0 or SE1 of up to 200 ns (TLST 210 ns)
    rx_run("nominal rate, 1-clock jitter, D- skewed up to 200 ns", 1.0, 1.0, skew, 220);
    rx_run("+1.5 % rate, 1-clock jitter, D- skewed up to 200 ns", 1.015, 1.0, skew, 220);
    rx_run("-1.5 % rate, 1-clock jitter, D- skewed up to 200 ns", 0.985, 1.0, skew, 220);
    double j70 = 70.0 / NS_PER_CLK;
    rx_run("+1.5 % rate, +-70 ns jitter", 1.015, j70, 0.0, 110);
    rx_run("-1.5 % rate, +-70 ns jitter", 0.985, j70, 0.0, 110);
    test_rx_errors();
    test_timeout_and_gate();
    test_underrun();
    std::printf("line_tb: %ld checks, %ld failed\n", checks, failures);
    return failures ? 1 : 0;
}
