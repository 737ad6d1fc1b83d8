// device_model_test — the USB keyboard model (cosim/usb/usb_kbd_device.h) against a low-speed host written
// here, no Verilator. The host is this file's own: its bit stuffing, NRZI, CRCs (polynomial long division
// over the bits as sent, the method of the white paper "Cyclic Redundancy Checks in USB") and its decoder
// of the device's answers share nothing with the model.
//
//   device_model_test [-v]      -v: a line per case, with the violation it expected as the model words it
//
// The bench steps the model at every change of the host's drive, every 20 ns clock while the device
// answers, and at least every 20 us otherwise (one case steps it at every clock, as socsim does). The
// host's edges sit on a 50 MHz grid (a host dividing 50 MHz by 33 1/3) unless a case says otherwise.
//
// Known values: CRC5 of the white paper's token examples, CRC-16/USB's catalogue check value, the
// GET_DESCRIPTOR packet seen in public bus captures, a SETUP token's bytes. Legal sequences (a full
// enumeration, typed text read back report by report, STALLed SET_IDLE/SET_PROTOCOL, halt and
// CLEAR_FEATURE, reset, detach) must leave no violation; every check of the model then gets a sequence
// that breaks exactly it, and every fault switch is shown doing what it says. Exit 0 and a last line
// `device_model: ok N cases` when every case passed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "usb_kbd_device.h"

namespace {

constexpr double kBit = 1e12 / 1.5e6;  // one low-speed bit, ps
constexpr uint64_t kClk = 20000;       // 50 MHz, socsim's default
constexpr uint64_t kUs = 1000000ull;
constexpr uint64_t kMs = 1000000000ull;
constexpr uint64_t kCoarse = 20 * kUs;

// PIDs (USB 2.0 Table 8-1).
constexpr uint8_t kOut = 0x1, kIn = 0x9, kSof = 0x5, kSetup = 0xD, kData0 = 0x3, kData1 = 0xB, kAck = 0x2,
                  kNak = 0xA, kStall = 0xE;

std::string why;       // the failing check of the current case
std::string reported;  // the violation a case expected, as the model worded it (shown by -v)

#define CHECK(cond)                                                               \
    do {                                                                          \
        if (!(cond)) {                                                            \
            why = std::string("line ") + std::to_string(__LINE__) + ": " + #cond; \
            return false;                                                         \
        }                                                                         \
    } while (0)

// ---- the test's CRCs: long division of the bits as sent (first sent = highest power) ----

// The remainder of msg times x^w by poly, complemented; the first w bits of msg times x^w complemented
// first: the preset to ones (for a message shorter than w, some of them are the appended zeros).
std::vector<int> crc_divide(std::vector<int> msg, const std::vector<int> &poly) {
    const size_t w = poly.size() - 1;
    msg.insert(msg.end(), w, 0);
    for (size_t i = 0; i < w; ++i) msg[i] ^= 1;
    for (size_t i = 0; i + w < msg.size(); ++i) {
        if (msg[i]) {
            for (size_t j = 0; j <= w; ++j) msg[i + j] ^= poly[j];
        }
    }
    std::vector<int> rem(msg.end() - static_cast<long>(w), msg.end());
    for (int &b : rem) b ^= 1;
    return rem;  // in sending order
}

const std::vector<int> kPoly5 = {1, 0, 0, 1, 0, 1};                                     // x^5 + x^2 + 1
const std::vector<int> kPoly16 = {1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1};  // x^16 + x^15 + x^2 + 1

std::vector<int> lsb_bits(const std::vector<uint8_t> &bytes) {
    std::vector<int> bits;
    for (uint8_t b : bytes) {
        for (int i = 0; i < 8; ++i) bits.push_back((b >> i) & 1);
    }
    return bits;
}

// CRC5 of bits as sent, as the white paper writes it: the first CRC bit sent is bit 4.
uint8_t test_crc5(const std::vector<int> &bits) {
    uint8_t v = 0;
    for (int b : crc_divide(bits, kPoly5)) v = static_cast<uint8_t>((v << 1) | b);
    return v;
}

// CRC16 of bytes, as the 16-bit value whose bit 0 is sent first (so: low byte first on the wire).
uint16_t test_crc16(const std::vector<uint8_t> &data) {
    const std::vector<int> r = crc_divide(lsb_bits(data), kPoly16);
    uint16_t v = 0;
    for (int i = 0; i < 16; ++i) v = static_cast<uint16_t>(v | (r[static_cast<size_t>(i)] << i));
    return v;
}

uint8_t pid_byte(uint8_t pid) { return static_cast<uint8_t>(pid | ((~pid & 0xF) << 4)); }

std::vector<uint8_t> token(uint8_t pid, uint8_t addr, uint8_t ep) {
    std::vector<int> bits;
    for (int i = 0; i < 7; ++i) bits.push_back((addr >> i) & 1);
    for (int i = 0; i < 4; ++i) bits.push_back((ep >> i) & 1);
    const uint8_t c = test_crc5(bits);
    for (int i = 4; i >= 0; --i) bits.push_back((c >> i) & 1);
    uint16_t f = 0;
    for (int i = 0; i < 16; ++i) f = static_cast<uint16_t>(f | (bits[static_cast<size_t>(i)] << i));
    return {pid_byte(pid), static_cast<uint8_t>(f & 0xFF), static_cast<uint8_t>(f >> 8)};
}

std::vector<uint8_t> data_packet(uint8_t pid, const std::vector<uint8_t> &payload) {
    std::vector<uint8_t> p = {pid_byte(pid)};
    p.insert(p.end(), payload.begin(), payload.end());
    const uint16_t c = test_crc16(payload);
    p.push_back(static_cast<uint8_t>(c & 0xFF));
    p.push_back(static_cast<uint8_t>(c >> 8));
    return p;
}

std::vector<uint8_t> handshake(uint8_t pid) { return {pid_byte(pid)}; }

std::vector<uint8_t> request(uint8_t bm, uint8_t req, uint16_t value, uint16_t index, uint16_t length) {
    return {bm,
            req,
            static_cast<uint8_t>(value & 0xFF),
            static_cast<uint8_t>(value >> 8),
            static_cast<uint8_t>(index & 0xFF),
            static_cast<uint8_t>(index >> 8),
            static_cast<uint8_t>(length & 0xFF),
            static_cast<uint8_t>(length >> 8)};
}

// ---- the host's encoder: bytes to line events ----

struct TxOpt {
    double bit_ps = kBit;
    uint64_t quantum = kClk;          // edges on this grid (a host clocked at it); 0: exact times
    double eop_bits = 2;              // the SE0 of the EOP
    int64_t se0_shift = 0;            // the EOP (SE0 and its end) moved by this much
    bool stuff = true;
    std::vector<int> sync = {0, 0, 0, 0, 0, 0, 0, 1};  // KJKJKJKK
    std::map<size_t, int64_t> shift;  // transition number (0 = SOP) -> ps added after quantising
    bool drop_last_bit = false;       // leave out the last stuffed 0
};

std::vector<int> raw_bits(const std::vector<uint8_t> &bytes, const TxOpt &o) {
    std::vector<int> data = o.sync;
    const std::vector<int> b = lsb_bits(bytes);
    data.insert(data.end(), b.begin(), b.end());
    if (!o.stuff) return data;
    std::vector<int> out;
    int ones = 0;
    for (int bit : data) {
        out.push_back(bit);
        ones = bit ? ones + 1 : 0;
        if (ones == 6) {
            out.push_back(0);
            ones = 0;
        }
    }
    return out;
}

// ---- the bench: steps the model, keeps the device's drive ----

struct LogEntry {
    uint64_t t;
    UsbDeviceDrive d;
};

class Bench {
public:
    explicit Bench(const UsbKbdConfig &c = UsbKbdConfig()) : dev(c) {
        dev.attach(0);
        step(0);
    }

    void at(uint64_t t, bool oe, bool dp, bool dm) {
        UsbHostDrive h;
        h.oe = oe;
        h.dp = dp;
        h.dm = dm;
        pending.push_back({t, h});
    }

    void run_until(uint64_t end) {
        for (;;) {
            bool changed = apply();
            if (changed) step(now);
            if (now >= end) return;
            uint64_t t = end;
            if (!pending.empty()) t = std::min(t, pending.front().first);
            const bool fine = every_clock || dev.busy() || last.oe;
            t = std::min(t, fine ? (now / kClk + 1) * kClk : now + kCoarse);
            now = t;
            apply();
            step(now);
        }
    }

    UsbLines lines() const { return UsbKbdDevice::bus(host, last); }

    UsbKbdDevice dev;
    UsbHostDrive host;
    bool every_clock = false;  // step at every 20 ns clock, as socsim does (else coarsely when idle)
    uint64_t now = 0;
    std::vector<LogEntry> log;  // the device's drive, at each change
    UsbDeviceDrive last;

private:
    bool apply() {
        bool changed = false;
        while (!pending.empty() && pending.front().first <= now) {
            host = pending.front().second;
            pending.pop_front();
            changed = true;
        }
        return changed;
    }
    void step(uint64_t t) {
        const UsbDeviceDrive d = dev.step(t, host);
        if (d.oe != last.oe || d.dp != last.dp || d.dm != last.dm || d.attached != last.attached) {
            log.push_back({t, d});
            last = d;
        }
    }

    std::deque<std::pair<uint64_t, UsbHostDrive>> pending;
};

// ---- the host's decoder of the device's packets ----

struct DevPacket {
    bool seen = false;      // the device drove the bus
    bool complete = false;  // ... up to its EOP
    bool ok = false;        // SYNC, stuffing, whole bytes, PID check, CRC16 of data
    bool timeout = false;
    bool detached = false;
    uint8_t pid = 0;
    std::vector<uint8_t> data;  // a data packet's payload
    uint64_t sop = 0, eop_end = 0;
    std::string why;
};

bool is_data(uint8_t pid) { return pid == kData0 || pid == kData1; }

DevPacket decode(const std::vector<LogEntry> &log, size_t from) {
    DevPacket p;
    size_t i = from;
    while (i < log.size() && !log[i].d.oe) {
        if (!log[i].d.attached) p.detached = true;
        ++i;
    }
    if (i == log.size()) return p;
    p.seen = true;
    p.sop = log[i].t;
    auto level = [](const UsbDeviceDrive &d) { return !d.oe ? 'R' : d.dp && !d.dm ? 'K' : !d.dp && d.dm ? 'J' : 'S'; };
    if (level(log[i].d) != 'K') {
        p.why = "the device's packet does not start with K";
        return p;
    }
    std::vector<int> raw = {0};
    uint64_t last_tr = p.sop;
    char prev = 'K';
    bool in_se0 = false;
    for (size_t j = i + 1; j < log.size(); ++j) {
        const char l = level(log[j].d);
        const uint64_t t = log[j].t;
        if (!log[j].d.attached) {
            p.detached = true;
            p.why = "the device detached in its packet";
            return p;
        }
        if (in_se0) {
            if (l != 'S') {
                p.eop_end = t;
                p.complete = true;
                break;
            }
            continue;
        }
        if (l == 'R') {
            p.why = "the device let go of the bus without an EOP";
            return p;
        }
        const int n = static_cast<int>(std::lround(static_cast<double>(t - last_tr) / kBit));
        if (l == 'S') {
            for (int k = 1; k < n; ++k) raw.push_back(1);
            in_se0 = true;
            continue;
        }
        if (l != prev) {
            for (int k = 1; k < n; ++k) raw.push_back(1);
            raw.push_back(0);
            last_tr = t;
            prev = l;
        }
    }
    if (!p.complete) {
        p.why = "no EOP yet";
        return p;
    }
    static const int kSync[8] = {0, 0, 0, 0, 0, 0, 0, 1};
    if (raw.size() < 8 || !std::equal(kSync, kSync + 8, raw.begin())) {
        p.why = "bad SYNC";
        return p;
    }
    std::vector<int> bits;
    int ones = 0;
    for (size_t k = 0; k < raw.size(); ++k) {
        if (ones == 6) {
            if (raw[k]) {
                p.why = "stuffing error";
                return p;
            }
            ones = 0;
            continue;
        }
        ones = raw[k] ? ones + 1 : 0;
        if (k >= 8) bits.push_back(raw[k]);
    }
    if (bits.size() % 8 != 0 || bits.empty()) {
        p.why = "not whole bytes: " + std::to_string(bits.size()) + " bits";
        return p;
    }
    std::vector<uint8_t> bytes(bits.size() / 8, 0);
    for (size_t k = 0; k < bits.size(); ++k) bytes[k / 8] = static_cast<uint8_t>(bytes[k / 8] | (bits[k] << (k % 8)));
    p.pid = bytes[0] & 0xF;
    if ((bytes[0] >> 4) != (~p.pid & 0xF)) {
        p.why = "bad PID check";
        return p;
    }
    if (is_data(p.pid)) {
        if (bytes.size() < 3) {
            p.why = "data packet too short";
            return p;
        }
        p.data.assign(bytes.begin() + 1, bytes.end() - 2);
        const uint16_t crc = static_cast<uint16_t>(bytes[bytes.size() - 2] | (bytes.back() << 8));
        if (crc != test_crc16(p.data)) {
            p.why = "bad CRC16";
            return p;
        }
        if (p.data.size() > 8) {
            p.why = "babble: " + std::to_string(p.data.size()) + " bytes";
            return p;
        }
    } else if (bytes.size() != 1) {
        p.why = "handshake of " + std::to_string(bytes.size()) + " bytes";
        return p;
    }
    p.ok = true;
    return p;
}

// ---- the host: packets, transactions, frames ----

class Host {
public:
    explicit Host(Bench &b) : b_(b) {}

    // A packet, at least `gap` bit times after the last EOP on the bus; returns its EOP's end.
    uint64_t tx(const std::vector<uint8_t> &bytes, const TxOpt &o, double gap) {
        uint64_t sop = std::max(b_.now, last_eop + static_cast<uint64_t>(gap * kBit));
        sop = (sop + kClk - 1) / kClk * kClk;
        std::vector<int> raw = raw_bits(bytes, o);
        if (o.drop_last_bit) raw.pop_back();
        auto edge = [&](double bits) -> uint64_t {
            const double ps = bits * o.bit_ps;
            const uint64_t off = o.quantum ? static_cast<uint64_t>(ps / static_cast<double>(o.quantum)) * o.quantum
                                           : static_cast<uint64_t>(ps + 0.5);
            return sop + off;
        };
        bool k = false;  // the level: J before the SYNC
        size_t tr = 0;
        for (size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] != 0) continue;
            k = !k;
            const auto s = o.shift.find(tr++);
            const int64_t add = s == o.shift.end() ? 0 : s->second;
            b_.at(static_cast<uint64_t>(static_cast<int64_t>(edge(static_cast<double>(i))) + add), true, k, !k);
        }
        const uint64_t se0 =
            static_cast<uint64_t>(static_cast<int64_t>(edge(static_cast<double>(raw.size()))) + o.se0_shift);
        const uint64_t eop_end = static_cast<uint64_t>(
            static_cast<int64_t>(edge(static_cast<double>(raw.size()) + o.eop_bits)) + o.se0_shift);
        b_.at(se0, true, false, false);
        b_.at(eop_end, true, false, true);
        b_.at(eop_end + static_cast<uint64_t>(kBit), false, false, false);
        b_.run_until(eop_end + static_cast<uint64_t>(kBit));
        last_eop = eop_end;
        mark = b_.log.size();
        return eop_end;
    }
    uint64_t tx(const std::vector<uint8_t> &bytes) { return tx(bytes, opt, gap_bits); }

    // The device's answer: waits up to `timeout` bit times after the last EOP for its SOP.
    DevPacket rx(double timeout = 16) {
        const uint64_t deadline = last_eop + static_cast<uint64_t>(timeout * kBit);
        for (;;) {
            b_.run_until(b_.now + static_cast<uint64_t>(kBit));
            DevPacket p = decode(b_.log, mark);
            if (p.complete || p.detached) {
                if (p.complete) last_eop = p.eop_end;
                mark = b_.log.size();
                return p;
            }
            if (!p.seen && b_.now > deadline) {
                p.timeout = true;
                p.why = "no answer";
                return p;
            }
            if (b_.now > deadline + static_cast<uint64_t>(300 * kBit)) {
                p.why = "the device's packet does not end";
                return p;
            }
        }
    }

    // Keep-alives at every frame start once the port is enabled (after the first reset).
    void keep_alive(uint64_t t) {
        const uint64_t end = t + static_cast<uint64_t>(std::floor(2 * kBit / kClk) * kClk);
        b_.at(t, true, false, false);
        b_.at(end, true, false, true);
        b_.at(end + static_cast<uint64_t>(kBit), false, false, false);
        b_.run_until(end + static_cast<uint64_t>(kBit));
        last_eop = end;
    }
    void idle(uint64_t until) {
        while (frames && next_frame <= until) {
            b_.run_until(next_frame);
            keep_alive(next_frame);
            next_frame += frame_ps;
        }
        b_.run_until(until);
    }
    void frame_guard() {  // no transaction across a frame start: the keep-alive goes first
        if (frames && b_.now + 400 * kUs >= next_frame) idle(next_frame);
    }
    void reset(uint64_t duration) {
        const uint64_t t0 = (b_.now + kClk - 1) / kClk * kClk;
        b_.at(t0, true, false, false);
        b_.at(t0 + duration, true, false, true);
        b_.at(t0 + duration + static_cast<uint64_t>(kBit), false, false, false);
        b_.run_until(t0 + duration + static_cast<uint64_t>(kBit));
        last_eop = t0 + duration;
        frames = true;
        next_frame = t0 + duration + 500 * kUs;
    }

    // Transactions (8.5): the host's side, as simple as a host can be.
    DevPacket in(uint8_t addr, uint8_t ep, bool ack = true) {
        frame_guard();
        tx(token(kIn, addr, ep), opt, 20);
        DevPacket p = rx();
        if (ack && p.ok && is_data(p.pid)) tx(handshake(kAck));
        return p;
    }
    DevPacket setup(uint8_t addr, const std::vector<uint8_t> &req) {
        frame_guard();
        tx(token(kSetup, addr, 0), opt, 20);
        tx(data_packet(kData0, req));
        return rx();
    }
    DevPacket out(uint8_t addr, uint8_t pid, const std::vector<uint8_t> &payload) {
        frame_guard();
        tx(token(kOut, addr, 0), opt, 20);
        tx(data_packet(pid, payload));
        return rx();
    }

    struct Ctl {
        bool ok = false;
        bool stalled = false;
        std::vector<uint8_t> data;
        std::string why;
    };
    Ctl control_read(uint8_t addr, const std::vector<uint8_t> &req) {
        Ctl c;
        const DevPacket h = setup(addr, req);
        if (!h.ok || h.pid != kAck) return fail(c, "SETUP not ACKed: " + h.why);
        const size_t wlen = static_cast<size_t>(req[6] | (req[7] << 8));
        int toggle = 1;
        for (int guard = 0; guard < 64; ++guard) {
            const DevPacket p = in(addr, 0, false);
            if (p.ok && p.pid == kNak) continue;
            if (p.ok && p.pid == kStall) {
                c.stalled = true;
                return c;
            }
            if (!p.ok || !is_data(p.pid)) return fail(c, "data stage: " + p.why);
            if ((p.pid == kData1) != (toggle == 1)) return fail(c, "data stage toggle");
            tx(handshake(kAck));
            toggle ^= 1;
            c.data.insert(c.data.end(), p.data.begin(), p.data.end());
            if (p.data.size() < 8 || c.data.size() >= wlen) break;
        }
        const DevPacket s = out(addr, kData1, {});
        if (!s.ok || s.pid != kAck) return fail(c, "status stage not ACKed: " + s.why);
        c.ok = true;
        return c;
    }
    Ctl control_nodata(uint8_t addr, const std::vector<uint8_t> &req) {
        Ctl c;
        const DevPacket h = setup(addr, req);
        if (!h.ok || h.pid != kAck) return fail(c, "SETUP not ACKed: " + h.why);
        return status_in(addr, c);
    }
    Ctl control_write(uint8_t addr, const std::vector<uint8_t> &req, const std::vector<uint8_t> &payload) {
        Ctl c;
        const DevPacket h = setup(addr, req);
        if (!h.ok || h.pid != kAck) return fail(c, "SETUP not ACKed: " + h.why);
        const DevPacket d = out(addr, kData1, payload);
        if (!d.ok || d.pid != kAck) return fail(c, "OUT data not ACKed: " + d.why);
        return status_in(addr, c);
    }

    TxOpt opt;
    double gap_bits = 3;  // between the packets of a transaction (TIPD is 2)
    uint64_t last_eop = 0;
    size_t mark = 0;      // the log entry from which the device's answer is read
    bool frames = false;
    uint64_t next_frame = 0;
    uint64_t frame_ps = kMs;

private:
    static Ctl fail(Ctl c, const std::string &w) {
        c.why = w;
        return c;
    }
    Ctl status_in(uint8_t addr, Ctl c) {
        for (int guard = 0; guard < 64; ++guard) {
            const DevPacket p = in(addr, 0, false);
            if (p.ok && p.pid == kNak) continue;
            if (p.ok && p.pid == kStall) {
                c.stalled = true;
                return c;
            }
            if (!p.ok || p.pid != kData1 || !p.data.empty()) return fail(c, "status stage: not a zero-length DATA1");
            tx(handshake(kAck));
            c.ok = true;
            return c;
        }
        return fail(c, "status stage: NAKed for ever");
    }

    Bench &b_;
};

// ---- checks on the model's violations ----

std::string all_errors(const UsbKbdDevice &d) {
    std::string s;
    for (const auto &e : d.errors()) s += "\n    " + e;
    return s;
}

bool clean(const UsbKbdDevice &d) {
    if (d.error_count() == 0) return true;
    why = "unexpected violations:" + all_errors(d);
    return false;
}

// Exactly these violations (by rule), in any order.
bool only(const UsbKbdDevice &d, std::vector<std::string> rules) {
    std::vector<std::string> got;
    for (const auto &v : d.violations()) got.push_back(v.rule);
    std::sort(got.begin(), got.end());
    std::sort(rules.begin(), rules.end());
    if (got == rules) {
        reported.clear();
        for (const auto &e : d.errors()) reported += (reported.empty() ? "" : "\n    ") + e;
        return true;
    }
    why = "expected violations";
    for (const auto &r : rules) why += " '" + r + "'";
    why += ", got " + std::to_string(d.error_count()) + ":" + all_errors(d);
    return false;
}

// ---- shared sequences ----

constexpr uint8_t kAddr = 5;

// Attach (at 0), debounce, reset, recovery, SET_ADDRESS 5, the 2 ms, SET_CONFIGURATION 1.
bool bring_up(Bench &b, Host &h, bool configure = true) {
    h.idle(101 * kMs);
    h.reset(10 * kMs + 100 * kUs);
    h.idle(b.now + 10 * kMs + 100 * kUs);
    Host::Ctl c = h.control_nodata(0, request(0x00, 5, kAddr, 0, 0));
    if (!c.ok) {
        why = "SET_ADDRESS: " + c.why + all_errors(b.dev);
        return false;
    }
    h.idle(b.now + 2 * kMs + 100 * kUs);
    if (!configure) return true;
    c = h.control_nodata(kAddr, request(0x00, 9, 1, 0, 0));
    if (!c.ok || !b.dev.configured()) {
        why = "SET_CONFIGURATION: " + c.why + all_errors(b.dev);
        return false;
    }
    return true;
}

UsbKbdReport key(uint8_t usage, uint8_t mods = 0) {
    UsbKbdReport r;
    r.modifiers = mods;
    r.keys[0] = usage;
    return r;
}

// ---- known values ----

// The white paper's CRC5 examples, as quoted with Ron Hemphill's port of its Perl program (the 11 token
// bits written first-sent-first): 0x547 -> 0x17 (address 0x15, endpoint 0xe), 0x2e5 -> 0x1c (0x3a, 0xa),
// 0x072 -> 0x0e (0x70, 0x4), 0x400 -> 0x17 (address 1, endpoint 0).
bool crc5_case() {
    const struct {
        uint32_t msb_first, crc;
    } ex[] = {{0x547, 0x17}, {0x2e5, 0x1c}, {0x072, 0x0e}, {0x400, 0x17}};
    for (const auto &e : ex) {
        std::vector<int> bits;
        uint32_t lsb_first = 0;
        for (int i = 10; i >= 0; --i) {
            const int b = (e.msb_first >> i) & 1;
            lsb_first |= static_cast<uint32_t>(b) << bits.size();
            bits.push_back(b);
        }
        CHECK(test_crc5(bits) == e.crc);
        CHECK(UsbKbdDevice::crc5(lsb_first, 11) == e.crc);
    }
    // Address 0x15 endpoint 0xe, written as fields: the same 0x17.
    CHECK(UsbKbdDevice::token_field(0x15, 0xe) == (0x15 | (0xe << 7) | (0x1d << 11)));  // 0x17 sent x^4 first
    return true;
}

// CRC-16/USB: the catalogue's check value over "123456789" is 0xb4c8 (crc-catalog); a GET_DESCRIPTOR
// (device, 64) request's DATA0 is C3 80 06 00 01 00 00 40 00 DD 94 in public bus captures.
bool crc16_case() {
    const std::string s = "123456789";
    const std::vector<uint8_t> digits(s.begin(), s.end());
    CHECK(test_crc16(digits) == 0xB4C8);
    CHECK(UsbKbdDevice::crc16(digits.data(), digits.size()) == 0xB4C8);
    const std::vector<uint8_t> gd = {0x80, 0x06, 0x00, 0x01, 0x00, 0x00, 0x40, 0x00};
    const std::vector<uint8_t> want = {0xC3, 0x80, 0x06, 0x00, 0x01, 0x00, 0x00, 0x40, 0x00, 0xDD, 0x94};
    CHECK(data_packet(kData0, gd) == want);
    CHECK(UsbKbdDevice::crc16(gd.data(), gd.size()) == 0x94DD);
    return true;
}

// A SETUP to address 0 is 2D 00 10 (captures); a token to address 9 endpoint 2 carries 09 B1 (A. Cruse's
// worked CRC5 example).
bool token_bytes_case() {
    CHECK(token(kSetup, 0, 0) == std::vector<uint8_t>({0x2D, 0x00, 0x10}));
    CHECK(token(kIn, 9, 2) == std::vector<uint8_t>({0x69, 0x09, 0xB1}));
    CHECK(UsbKbdDevice::token_field(0, 0) == 0x1000);
    CHECK(UsbKbdDevice::token_field(9, 2) == 0xB109);
    return true;
}

// Typed text to reports (HID Usage Tables 1.12 section 10): a press and an all-up release per key.
bool text_case() {
    const auto r = UsbKbdDevice::reports_for_text("aZ1!\n{UP}{F12}{{ ");
    CHECK(r.size() == 18);
    CHECK(r[0] == key(0x04));
    CHECK(r[1] == UsbKbdReport());
    CHECK(r[2] == key(0x1D, 0x02));  // Z: left Shift
    CHECK(r[4] == key(0x1E));
    CHECK(r[6] == key(0x1E, 0x02));  // !: Shift 1
    CHECK(r[8] == key(0x28));        // Enter
    CHECK(r[10] == key(0x52));       // Up arrow
    CHECK(r[12] == key(0x45));       // F12
    CHECK(r[14] == key(0x2F, 0x02)); // {
    bool threw = false;
    try {
        UsbKbdDevice::reports_for_text("{NOPE}");
    } catch (const std::invalid_argument &) {
        threw = true;
    }
    CHECK(threw);
    return true;
}

// ---- legal sequences ----

// A host's whole enumeration, then typed text read back poll by poll; stepped coarsely when idle, or at
// every clock as socsim steps it.
bool enumeration_case(bool every_clock) {
    Bench b;
    b.every_clock = every_clock;
    Host h(b);
    CHECK(b.dev.state() == UsbKbdState::kPowered);
    CHECK(b.lines().dm && !b.lines().dp);  // J: the pull-up on D-
    h.idle(101 * kMs);
    h.reset(10 * kMs + 100 * kUs);
    CHECK(b.dev.state() == UsbKbdState::kDefault);
    h.idle(b.now + 10 * kMs + 100 * kUs);
    // The device descriptor at address 0, as hosts ask for it first: wLength 64, 18 come in 8 + 8 + 2.
    Host::Ctl c = h.control_read(0, request(0x80, 6, 0x0100, 0, 64));
    if (!c.ok) why = c.why + all_errors(b.dev);
    CHECK(c.ok);
    const std::vector<uint8_t> dev = {18, 1, 0x10, 0x01, 0, 0, 0, 8, 0x3C, 0x41, 0x10, 0x20, 0x00, 0x02, 1, 3, 0, 1};
    CHECK(c.data == dev);  // the Dell's: bcdUSB 1.10, 8-byte endpoint 0, 413c:2010, bcdDevice 2.00, strings 1 and 3
    c = h.control_nodata(0, request(0x00, 5, kAddr, 0, 0));
    CHECK(c.ok);
    CHECK(b.dev.address() == kAddr);
    CHECK(b.dev.state() == UsbKbdState::kAddress);
    h.idle(b.now + 2 * kMs + 100 * kUs);
    c = h.control_read(kAddr, request(0x80, 6, 0x0100, 0, 18));
    CHECK(c.ok && c.data == dev);
    c = h.control_read(kAddr, request(0x80, 6, 0x0200, 0, 9));
    CHECK(c.ok && c.data.size() == 9);
    const uint16_t total = static_cast<uint16_t>(c.data[2] | (c.data[3] << 8));
    CHECK(total == 59);                                // the Dell's wTotalLength
    CHECK(c.data[4] == 2 && c.data[5] == 1 && c.data[6] == 3 && c.data[7] == 0xA0 && c.data[8] == 25);  // 50 mA
    c = h.control_read(kAddr, request(0x80, 6, 0x0200, 0, total));
    CHECK(c.ok && c.data.size() == 59);
    const std::vector<uint8_t> if0(c.data.begin() + 9, c.data.begin() + 18);
    CHECK(if0 == std::vector<uint8_t>({9, 4, 0, 0, 1, 3, 1, 1, 3}));  // HID, boot subclass, keyboard
    CHECK(c.data[18] == 9 && c.data[19] == 0x21 && c.data[24] == 0x22 && c.data[25] == 46);  // HID: 46-byte report
    CHECK(c.data[27] == 7 && c.data[29] == 0x81 && c.data[30] == 3 && c.data[31] == 8 && c.data[33] == 10);
    c = h.control_read(kAddr, request(0x80, 6, 0x0300, 0, 255));
    CHECK(c.ok && c.data == std::vector<uint8_t>({4, 3, 0x09, 0x04}));
    c = h.control_read(kAddr, request(0x80, 6, 0x0301, 0x0409, 255));
    CHECK(c.ok && c.data == std::vector<uint8_t>({10, 3, 'D', 0, 'e', 0, 'l', 0, 'l', 0}));
    c = h.control_read(kAddr, request(0x80, 6, 0x0303, 0x0409, 255));
    CHECK(c.ok && c.data.size() == 36 && c.data[2] == 'D' && c.data[34] == 'd');  // "Dell USB Keyboard"
    c = h.control_nodata(kAddr, request(0x00, 9, 1, 0, 0));
    CHECK(c.ok && b.dev.configured());
    c = h.control_nodata(kAddr, request(0x21, 0x0A, 0, 0, 0));  // SET_IDLE 0: reports on change only
    CHECK(c.ok && b.dev.idle_rate() == 0);
    c = h.control_nodata(kAddr, request(0x21, 0x0B, 0, 0, 0));  // SET_PROTOCOL boot
    CHECK(c.ok && b.dev.protocol() == 0);
    c = h.control_read(kAddr, request(0x81, 6, 0x2200, 0, 46 + 64));
    const std::vector<uint8_t> boot = {0x05, 0x01, 0x09, 0x06, 0xA1, 0x01, 0x75, 0x01, 0x95, 0x08, 0x05, 0x07,
                                       0x19, 0xE0, 0x29, 0xE7, 0x15, 0x00, 0x25, 0x01, 0x81, 0x02, 0x95, 0x01,
                                       0x75, 0x08, 0x81, 0x01, 0x95, 0x06, 0x75, 0x08, 0x15, 0x00, 0x26, 0xFF,
                                       0x00, 0x05, 0x07, 0x19, 0x00, 0x29, 0xFF, 0x81, 0x00, 0xC0};
    CHECK(c.ok && c.data == boot);  // HID 1.11 Appendix B.1
    c = h.control_write(kAddr, request(0x21, 0x09, 0x0200, 0, 1), {0x02});  // SET_REPORT: Caps Lock LED
    CHECK(c.ok && b.dev.leds() == 0x02);

    b.dev.type_text("Hi!\n");
    const std::vector<UsbKbdReport> want = {key(0x0B, 0x02), {}, key(0x0C), {}, key(0x1E, 0x02), {}, key(0x28), {}};
    std::vector<UsbKbdReport> got;
    int toggle = 0, naks = 0;
    for (int poll = 0; poll < 12; ++poll) {
        h.idle(b.now + 10 * kMs - 200 * kUs);
        const DevPacket p = h.in(kAddr, 1);
        CHECK(p.ok);
        if (p.pid == kNak) {
            ++naks;
            continue;
        }
        CHECK(is_data(p.pid));
        CHECK((p.pid == kData1) == (toggle == 1));  // DATA0, DATA1, ... (8.6)
        toggle ^= 1;
        CHECK(p.data.size() == 8);
        UsbKbdReport r;
        r.modifiers = p.data[0];
        r.reserved = p.data[1];
        std::copy(p.data.begin() + 2, p.data.end(), r.keys);
        got.push_back(r);
    }
    CHECK(got == want);
    CHECK(naks == 4);
    CHECK(b.dev.counters().reports_delivered == 8);
    CHECK(b.dev.counters().keep_alives > 100);
    CHECK(b.dev.counters().control_transfers == 13);
    return clean(b.dev);
}

// A host at +400 ppm with exact edges, and one at -400 ppm: inside TLDRATHS, no violation.
bool rate_inside_case() {
    for (double ppm : {400.0, -400.0}) {
        Bench b;
        Host h(b);
        if (!bring_up(b, h)) return false;
        h.opt.quantum = 0;
        h.opt.bit_ps = kBit * (1 + ppm / 1e6);
        b.dev.queue_report(key(0x04));
        const DevPacket p = h.in(kAddr, 1);
        CHECK(p.ok && is_data(p.pid));
        if (!clean(b.dev)) return false;
    }
    return true;
}

// Keyboards that STALL SET_IDLE and SET_PROTOCOL: the host goes on; the idle rate stays 500 ms, so the
// unchanged report comes again 500 ms after the last one.
bool stalled_requests_case() {
    UsbKbdConfig cfg;
    cfg.stall_set_idle = true;
    cfg.stall_set_protocol = true;
    Bench b(cfg);
    Host h(b);
    if (!bring_up(b, h)) return false;
    Host::Ctl c = h.control_nodata(kAddr, request(0x21, 0x0A, 0, 0, 0));
    CHECK(c.stalled);
    c = h.control_nodata(kAddr, request(0x21, 0x0B, 0, 0, 0));
    CHECK(c.stalled);
    CHECK(b.dev.idle_rate() == 125 && b.dev.protocol() == 1);
    c = h.control_read(kAddr, request(0x80, 0, 0, 0, 2));  // GET_STATUS: the pipe works after the STALLs
    CHECK(c.ok && c.data == std::vector<uint8_t>({0, 0}));
    b.dev.type_text("a");
    int reports = 0;
    uint64_t second = 0;
    for (int poll = 0; poll < 60; ++poll) {
        h.idle(b.now + 10 * kMs - 200 * kUs);
        const DevPacket p = h.in(kAddr, 1);
        CHECK(p.ok);
        if (is_data(p.pid)) {
            if (++reports == 2) second = b.now;
            if (reports == 3) {
                CHECK(p.data == std::vector<uint8_t>(8, 0));
                CHECK(b.now - second > 500 * kMs - 20 * kMs);
            }
        }
    }
    CHECK(reports == 3);
    CHECK(b.dev.counters().idle_repeats == 1);
    CHECK(b.dev.counters().requests_stalled == 2);
    return clean(b.dev);
}

// Endpoint 1 halted: STALL until CLEAR_FEATURE(ENDPOINT_HALT), which restarts the toggle at DATA0.
bool halt_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    DevPacket p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0);
    b.dev.set_endpoint_halt(true);
    b.dev.queue_report(key(0x05));
    h.idle(b.now + 10 * kMs);
    p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kStall);
    Host::Ctl c = h.control_read(kAddr, request(0x82, 0, 0, 0x81, 2));
    CHECK(c.ok && c.data == std::vector<uint8_t>({1, 0}));
    c = h.control_nodata(kAddr, request(0x02, 1, 0, 0x81, 0));
    CHECK(c.ok && !b.dev.endpoint_halted());
    h.idle(b.now + 10 * kMs);
    p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0 && p.data[2] == 0x05);
    return clean(b.dev);
}

// A second reset takes the device back to address 0, unconfigured; a detach leaves SE0 for the host,
// and a new attach a fresh device.
bool reset_detach_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.idle(b.now + 3 * kMs);
    h.reset(10 * kMs + 100 * kUs);
    CHECK(b.dev.counters().resets == 2);
    CHECK(b.dev.state() == UsbKbdState::kDefault && b.dev.address() == 0 && !b.dev.configured());
    h.idle(b.now + 11 * kMs);
    Host::Ctl c = h.control_nodata(0, request(0x00, 5, 7, 0, 0));
    CHECK(c.ok && b.dev.address() == 7);
    h.idle(b.now + 3 * kMs);
    b.dev.detach(b.now);
    b.run_until(b.now + kUs);
    CHECK(!b.lines().dp && !b.lines().dm);  // SE0: the host's pull-downs alone
    CHECK(!b.dev.attached());
    h.frames = false;
    b.dev.attach(b.now);
    b.run_until(b.now + kUs);
    CHECK(b.lines().dm && b.dev.state() == UsbKbdState::kPowered);
    CHECK(b.dev.counters().attaches == 2 && b.dev.counters().detaches == 1);
    return clean(b.dev);
}

// ---- each check, broken once ----

// A configured keyboard, then one poll of endpoint 1 sent with `o` (or the packet `bytes` instead).
bool poll_with(const TxOpt &o, std::vector<std::string> rules, bool expect_answer = true) {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    h.tx(token(kIn, kAddr, 1), o, 20);
    const DevPacket p = h.rx();
    CHECK(p.ok == expect_answer);
    if (expect_answer) CHECK(p.pid == kNak);
    return only(b.dev, rules);
}

bool bad_packet(const std::vector<uint8_t> &bytes, const char *rule) {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    h.tx(bytes, h.opt, 20);
    const DevPacket p = h.rx();
    CHECK(p.timeout);  // ignored: no answer
    return only(b.dev, {rule});
}

bool crc5_bad_case() {
    std::vector<uint8_t> t = token(kIn, kAddr, 1);
    t[2] ^= 0x80;  // one CRC5 bit
    return bad_packet(t, "CRC5");
}

bool pid_bad_case() {
    std::vector<uint8_t> t = token(kIn, kAddr, 1);
    t[0] = 0x79;  // IN with a check nibble of 7
    return bad_packet(t, "PID");
}

bool sof_case() { return bad_packet(token(kSof, 0x10, 0x3), "SOF"); }  // frame 0x190, its CRC5 as a token's

// SETUP's DATA0 with a wrong CRC16: ignored, no ACK.
bool crc16_bad_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    h.tx(token(kSetup, kAddr, 0), h.opt, 20);
    std::vector<uint8_t> d = data_packet(kData0, request(0x80, 6, 0x0100, 0, 18));
    d.back() ^= 0x10;
    h.tx(d);
    const DevPacket p = h.rx();
    CHECK(p.timeout);
    return only(b.dev, {"CRC16"});
}

// Seven 1s: address 127 needs a stuffed 0 the host leaves out.
bool stuffing_case() {
    TxOpt o;
    o.stuff = false;
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    h.tx(token(kIn, 127, 1), o, 20);
    CHECK(h.rx().timeout);
    return only(b.dev, {"bit stuffing"});
}

// Six 1s right before the EOP and no stuffed 0: a token whose last six bits are 1s.
bool stuffing_at_eop_case() {
    for (int addr = 0; addr < 128; ++addr) {
        for (int ep = 0; ep < 16; ++ep) {
            const auto t = token(kIn, static_cast<uint8_t>(addr), static_cast<uint8_t>(ep));
            if (((t[2] >> 1) & 0x7F) != 0x7E) continue;  // a 0, then six 1s to the end: a stuffed 0 follows
            TxOpt o;
            o.drop_last_bit = true;
            Bench b;
            Host h(b);
            if (!bring_up(b, h)) return false;
            h.frame_guard();
            h.tx(t, o, 20);
            CHECK(h.rx().timeout);
            return only(b.dev, {"bit stuffing"});
        }
    }
    why = "no token ends in six 1s";
    return false;
}

bool rate_case() {  // 33 clocks a bit at 50 MHz: 1.515 Mb/s, +1 %
    TxOpt o;
    o.bit_ps = 33 * kClk;
    return poll_with(o, {"bit rate"});
}

bool jitter_case() {  // one edge 30 ns late: TDDJ1 is 25
    TxOpt o;
    o.quantum = 0;
    o.shift[9] = 30000;
    return poll_with(o, {"jitter"});
}

bool paired_jitter_case() {  // one edge 20 ns late: inside TDDJ1, outside TDDJ2 (14 ns)
    TxOpt o;
    o.quantum = 0;
    o.shift[9] = 20000;
    return poll_with(o, {"jitter"});
}

bool sync_case() {  // KJKJKK: two bits short
    TxOpt o;
    o.sync = {0, 0, 0, 0, 0, 1};
    return poll_with(o, {"SYNC"}, false);
}

bool eop_long_case() {  // an EOP of 3 bit times (2 us): outside TLEOPT, not yet a reset
    TxOpt o;
    o.eop_bits = 3;
    return poll_with(o, {"EOP"});
}

bool eop_skew_case() {  // the EOP 150 ns late after the last transition: TLDEOP is +100 ns
    TxOpt o;
    o.se0_shift = 150000;
    return poll_with(o, {"EOP"});
}

bool se0_glitch_case() {  // 300 ns of SE0 on the idle bus
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    const uint64_t t = b.now + 10 * kUs;
    b.at(t, true, false, false);
    b.at(t + 300000, false, false, false);
    b.run_until(t + kUs);
    return only(b.dev, {"SE0"});
}

bool se1_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    const uint64_t t = b.now + 10 * kUs;
    b.at(t, true, true, true);
    b.at(t + 2 * kUs, false, false, false);
    b.run_until(t + 20 * kUs);
    return only(b.dev, {"SE1"});
}

// No keep-alive for 4 ms after enumeration: the device suspends; the next keep-alive wakes it.
bool suspend_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    // One suspend and resume already: the powered device, idle before its reset.
    const uint64_t suspends = b.dev.counters().suspends, resumes = b.dev.counters().resumes;
    h.frames = false;
    h.idle(b.now + 4 * kMs);
    CHECK(b.dev.suspended());
    CHECK(b.dev.counters().suspends == suspends + 1);
    h.keep_alive(b.now);
    CHECK(!b.dev.suspended() && b.dev.counters().resumes == resumes + 1);
    return only(b.dev, {"suspend"});
}

// A host suspending on purpose (allow_suspend): no violation.
bool suspend_allowed_case() {
    UsbKbdConfig cfg;
    cfg.allow_suspend = true;
    Bench b(cfg);
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frames = false;
    h.idle(b.now + 5 * kMs);
    CHECK(b.dev.suspended());
    return clean(b.dev);
}

// A host that suspends the bus on purpose (allow_suspend) and resumes it: K for 20 ms, then a low-speed
// EOP (7.1.7.7); the keyboard answers the next poll.
bool resume_case() {
    UsbKbdConfig cfg;
    cfg.allow_suspend = true;
    Bench b(cfg);
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frames = false;
    h.idle(b.now + 5 * kMs);
    CHECK(b.dev.suspended());
    const uint64_t t = b.now;
    const uint64_t eop = t + 20 * kMs;
    const uint64_t j = eop + 1340000;
    b.at(t, true, true, false);
    b.at(eop, true, false, false);
    b.at(j, true, false, true);
    b.at(j + static_cast<uint64_t>(kBit), false, false, false);
    b.run_until(j + 2 * static_cast<uint64_t>(kBit));
    CHECK(!b.dev.suspended());
    h.last_eop = j;
    h.frames = true;
    h.next_frame = b.now + 100 * kUs;
    h.idle(b.now + kMs);
    b.dev.queue_report(key(0x04));
    const DevPacket p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0);
    return clean(b.dev);
}

bool keep_alive_period_case() {  // frames of 1.2 ms
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.idle(b.now + 2 * kMs);
    h.frame_ps = 1200 * kUs;
    h.idle(h.next_frame + 1300 * kUs);  // keep-alives 1 ms, then 1.2 ms after the previous one
    return only(b.dev, {"keep-alive"});
}

// The host drives K for a bit while the device sends its report, then reads it and ACKs.
bool contention_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    h.frame_guard();
    const uint64_t eop = h.tx(token(kIn, kAddr, 1), h.opt, 20);
    const uint64_t t = (eop + static_cast<uint64_t>(6 * kBit)) / kClk * kClk;
    b.at(t, true, true, false);
    b.at(t + static_cast<uint64_t>(kBit), false, false, false);
    const DevPacket p = h.rx();
    CHECK(p.ok && is_data(p.pid));
    h.tx(handshake(kAck));
    CHECK(b.dev.counters().reports_delivered == 1);
    return only(b.dev, {"bus contention"});
}

bool reset_short_case() {  // 5 ms of reset
    Bench b;
    Host h(b);
    h.idle(101 * kMs);
    h.reset(5 * kMs);
    CHECK(b.dev.state() == UsbKbdState::kDefault);
    h.idle(b.now + 11 * kMs);
    return only(b.dev, {"reset"});
}

bool reset_recovery_case() {  // SET_ADDRESS 2 ms after the reset: TRSTRCY is 10 ms
    Bench b;
    Host h(b);
    h.idle(101 * kMs);
    h.reset(10 * kMs + 100 * kUs);
    h.idle(b.now + 2 * kMs);
    CHECK(h.control_nodata(0, request(0x00, 5, kAddr, 0, 0)).ok);
    return only(b.dev, {"reset recovery"});
}

bool debounce_case() {  // a reset 20 ms after attach: TATTDB is 100 ms
    Bench b;
    Host h(b);
    h.idle(20 * kMs);
    h.reset(10 * kMs + 100 * kUs);
    h.idle(b.now + 11 * kMs);
    return only(b.dev, {"attach debounce"});
}

bool before_reset_case() {  // a token to the attached device before any reset
    Bench b;
    Host h(b);
    h.idle(101 * kMs);
    h.tx(token(kSetup, 0, 0), h.opt, 20);
    h.tx(data_packet(kData0, request(0x80, 6, 0x0100, 0, 64)));
    CHECK(h.rx().timeout);
    return only(b.dev, {"state", "control sequence"});  // the DATA then has no token the device took
}

bool set_address_recovery_case() {  // the new address used 0.5 ms after SET_ADDRESS
    Bench b;
    Host h(b);
    h.idle(101 * kMs);
    h.reset(10 * kMs + 100 * kUs);
    h.idle(b.now + 10 * kMs + 100 * kUs);
    CHECK(h.control_nodata(0, request(0x00, 5, kAddr, 0, 0)).ok);
    h.idle(b.now + 500 * kUs);
    CHECK(h.control_read(kAddr, request(0x80, 6, 0x0100, 0, 18)).ok);
    return only(b.dev, {"set address recovery"});
}

bool address_case() {  // a token to address 6
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    h.tx(token(kIn, 6, 1), h.opt, 20);
    CHECK(h.rx().timeout);
    return only(b.dev, {"address"});
}

// The host does not ACK a good report: the device sends it again, same PID, at the next poll.
bool no_ack_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    DevPacket p = h.in(kAddr, 1, false);
    CHECK(p.ok && p.pid == kData0);
    h.idle(b.now + 10 * kMs);
    p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0 && p.data[2] == 0x04);
    CHECK(b.dev.counters().retransmissions == 1 && b.dev.counters().reports_delivered == 1);
    return only(b.dev, {"handshake"});
}

// The host answers a report with NAK (a host only ACKs): the device sends it again.
bool host_nak_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    DevPacket p = h.in(kAddr, 1, false);
    CHECK(p.ok && p.pid == kData0);
    h.tx(handshake(kNak));
    h.idle(b.now + 10 * kMs);
    p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0 && p.data[2] == 0x04);
    CHECK(b.dev.counters().reports_delivered == 1);
    return only(b.dev, {"handshake"});
}

// The host sends its next token 2.5 bit times after an IN, before the device's answer (due at 3).
bool turnaround_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    h.tx(token(kIn, kAddr, 1), h.opt, 20);
    h.tx(token(kIn, kAddr, 1), h.opt, 2.5);
    const DevPacket p = h.rx();
    CHECK(p.ok && p.pid == kNak);
    return only(b.dev, {"turnaround"});
}

bool inter_packet_case() {  // SETUP's DATA0 one bit time after the token
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    h.frame_guard();
    h.tx(token(kSetup, kAddr, 0), h.opt, 20);
    h.tx(data_packet(kData0, request(0x80, 0, 0, 0, 2)), h.opt, 1);
    const DevPacket p = h.rx();
    CHECK(p.ok && p.pid == kAck);
    return only(b.dev, {"inter-packet delay"});
}

bool toggle_case() {  // a status stage sent as DATA0
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    CHECK(h.setup(kAddr, request(0x80, 0, 0, 0, 2)).pid == kAck);
    DevPacket p = h.in(kAddr, 0);
    CHECK(p.ok && p.pid == kData1 && p.data.size() == 2);
    p = h.out(kAddr, kData0, {});
    CHECK(p.ok && p.pid == kAck);
    return only(b.dev, {"toggle"});
}

bool request_case() {  // SET_ADDRESS 200: answered with STALL
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    const Host::Ctl c = h.control_nodata(kAddr, request(0x00, 5, 200, 0, 0));
    CHECK(c.stalled);
    return only(b.dev, {"request"});
}

bool poll_interval_case() {  // endpoint 1 polled 25 ms apart, bInterval 10
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    CHECK(h.in(kAddr, 1).pid == kNak);
    h.idle(b.now + 25 * kMs);
    CHECK(h.in(kAddr, 1).pid == kNak);
    return only(b.dev, {"poll interval"});
}

bool unconfigured_case() {  // endpoint 1 before SET_CONFIGURATION: no answer
    Bench b;
    Host h(b);
    if (!bring_up(b, h, false)) return false;
    CHECK(h.in(kAddr, 1).timeout);
    return only(b.dev, {"state"});
}

bool long_data_case() {  // 9 bytes of SETUP data: endpoint 0 takes 8
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    std::vector<uint8_t> r = request(0x80, 0, 0, 0, 2);
    r.push_back(0);
    h.frame_guard();
    h.tx(token(kSetup, kAddr, 0), h.opt, 20);
    h.tx(data_packet(kData0, r));
    CHECK(h.rx().timeout);
    return only(b.dev, {"packet length"});
}

// ---- fault switches ----

bool fault_crc_case() {  // a report with a bad CRC16: the host ignores it, gets it again
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    b.dev.corrupt_crc_next(1);
    DevPacket p = h.in(kAddr, 1);
    CHECK(p.complete && !p.ok && p.why == "bad CRC16");
    h.idle(b.now + 10 * kMs);
    p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0 && p.data[2] == 0x04);
    CHECK(b.dev.counters().faults_crc == 1 && b.dev.counters().reports_delivered == 1);
    return clean(b.dev);
}

bool fault_crc_acked_case() {  // a host that ACKs it anyway is caught
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    b.dev.corrupt_crc_next(1);
    const DevPacket p = h.in(kAddr, 1, false);
    CHECK(p.complete && !p.ok);
    h.tx(handshake(kAck));
    return only(b.dev, {"handshake"});
}

bool fault_silent_case() {  // no answer once: the host times out, the report comes at the next poll
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    b.dev.no_answer_next(1);
    CHECK(h.in(kAddr, 1).timeout);
    h.idle(b.now + 10 * kMs);
    const DevPacket p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0);
    CHECK(b.dev.counters().faults_silent == 1);
    return clean(b.dev);
}

bool fault_stall_case() {
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    b.dev.stall_next(1);
    CHECK(h.in(kAddr, 1).pid == kStall);
    h.idle(b.now + 10 * kMs);
    CHECK(h.in(kAddr, 1).pid == kData0);
    return clean(b.dev);
}

bool fault_disconnect_case() {  // unplugged 12 bits into a report: the host sees SE0 from then on
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    b.dev.disconnect_during_next_data(12);
    const DevPacket p = h.in(kAddr, 1);
    CHECK(p.detached && !p.complete);
    b.run_until(b.now + 10 * kUs);
    CHECK(!b.dev.attached() && !b.lines().dp && !b.lines().dm);
    CHECK(b.dev.counters().faults_disconnect == 1);
    return clean(b.dev);
}

bool fault_babble_case() {  // 16 bytes where 8 fit, then a packet that goes on where its EOP belongs
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    b.dev.babble_next(UsbBabble::kLongPacket, 8);
    DevPacket p = h.in(kAddr, 1);
    CHECK(p.complete && !p.ok && p.why == "babble: 16 bytes");
    h.idle(b.now + 10 * kMs);
    b.dev.babble_next(UsbBabble::kNoEop, 21);
    p = h.in(kAddr, 1);
    CHECK(p.complete && !p.ok);
    h.idle(b.now + 10 * kMs);
    p = h.in(kAddr, 1);
    CHECK(p.ok && p.pid == kData0 && p.data.size() == 8);
    CHECK(b.dev.counters().faults_babble == 2);
    return clean(b.dev);
}

bool fault_length_case() {  // a 7-byte report
    Bench b;
    Host h(b);
    if (!bring_up(b, h)) return false;
    b.dev.queue_report(key(0x04));
    b.dev.wrong_length_next(1, 7);
    const DevPacket p = h.in(kAddr, 1);
    CHECK(p.ok && p.data.size() == 7);
    CHECK(b.dev.counters().faults_length == 1);
    return clean(b.dev);
}

struct Case {
    std::string name;
    std::function<bool()> run;
};

}  // namespace

int main(int argc, char **argv) {
    const bool verbose = argc > 1 && std::strcmp(argv[1], "-v") == 0;
    const std::vector<Case> cases = {
        {"CRC5: the white paper's examples", crc5_case},
        {"CRC16: catalogue check value, GET_DESCRIPTOR packet", crc16_case},
        {"token bytes", token_bytes_case},
        {"typed text to reports", text_case},
        {"enumeration, descriptors, typed text", [] { return enumeration_case(false); }},
        {"the same, stepped at every 50 MHz clock", [] { return enumeration_case(true); }},
        {"host rate +-400 ppm", rate_inside_case},
        {"STALLed SET_IDLE/SET_PROTOCOL, idle repeat", stalled_requests_case},
        {"endpoint halt and CLEAR_FEATURE", halt_case},
        {"second reset, detach, attach", reset_detach_case},
        {"bad CRC5", crc5_bad_case},
        {"bad CRC16", crc16_bad_case},
        {"bad PID check nibble", pid_bad_case},
        {"SOF to a low-speed device", sof_case},
        {"seven 1s", stuffing_case},
        {"no stuffed 0 before EOP", stuffing_at_eop_case},
        {"bit rate +1 %", rate_case},
        {"jitter 30 ns (TDDJ1)", jitter_case},
        {"jitter 20 ns (TDDJ2)", paired_jitter_case},
        {"short SYNC", sync_case},
        {"EOP of 3 bits", eop_long_case},
        {"EOP 150 ns late (TLDEOP)", eop_skew_case},
        {"SE0 glitch", se0_glitch_case},
        {"SE1", se1_case},
        {"no keep-alive: suspend", suspend_case},
        {"suspend allowed", suspend_allowed_case},
        {"suspend and resume", resume_case},
        {"keep-alive every 1.2 ms", keep_alive_period_case},
        {"bus contention", contention_case},
        {"reset of 5 ms", reset_short_case},
        {"reset recovery", reset_recovery_case},
        {"attach debounce", debounce_case},
        {"token before reset", before_reset_case},
        {"set address recovery", set_address_recovery_case},
        {"wrong address", address_case},
        {"no ACK for a report", no_ack_case},
        {"host answers NAK", host_nak_case},
        {"host does not wait for the answer", turnaround_case},
        {"inter-packet delay of 1 bit", inter_packet_case},
        {"status stage DATA0", toggle_case},
        {"SET_ADDRESS 200", request_case},
        {"poll interval 25 ms", poll_interval_case},
        {"endpoint 1 before SET_CONFIGURATION", unconfigured_case},
        {"9 bytes of SETUP data", long_data_case},
        {"fault: bad CRC16", fault_crc_case},
        {"fault: bad CRC16 acknowledged", fault_crc_acked_case},
        {"fault: no answer", fault_silent_case},
        {"fault: STALL", fault_stall_case},
        {"fault: disconnect mid-packet", fault_disconnect_case},
        {"fault: babble", fault_babble_case},
        {"fault: report of 7 bytes", fault_length_case},
    };
    int failed = 0;
    for (const Case &c : cases) {
        why.clear();
        reported.clear();
        if (!c.run()) {
            ++failed;
            std::printf("device_model: FAILED %s: %s\n", c.name.c_str(), why.c_str());
        } else if (verbose) {
            std::printf("device_model: ok %s%s%s\n", c.name.c_str(), reported.empty() ? "" : "\n    ",
                        reported.c_str());
        }
    }
    if (failed != 0) {
        std::printf("device_model: FAILED %d of %zu cases\n", failed, cases.size());
        return 1;
    }
    std::printf("device_model: ok %zu cases\n", cases.size());
    return 0;
}
