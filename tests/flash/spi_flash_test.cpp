// spi_flash_test — the SPI NOR flash model (cosim/flash/spi_flash.h) against a bit-banging SPI master,
// no Verilator: each case drives CS#, SCK and MOSI edge by edge at a chosen SCK period, as socsim does
// every half clock, samples MISO at its rising SCK edges and checks what the flash answered and which
// violations it reported.
//
//   spi_flash_test [-v]      -v: a line per case, with the violation it expected as the model words it
//
// Legal sequences must leave no violation: RDID, READ at several addresses, across pages and sectors and
// wrapping at the end of the array, READ at exactly 50 MHz, FAST READ with its 8 dummy clocks at 100 MHz,
// SPI mode 3, RDSR and the write enable latch, deep power-down and the release from it, the RES form of
// 0xAB, page program (1 -> 0 only, wrapping within the page, WIP then clear), sector erase and a software
// reset. Every check of the model then gets a sequence that breaks exactly it, and the case passes only
// if exactly that violation (by rule name) is reported.
//
// The master knows the data sheet's numbers (ISSI IS25LP128; see spi_flash.h for their sources), not
// the model's insides. Exit 0 and a last line `spi_flash: ok N cases` when every case passed.
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "spi_flash.h"

namespace {

constexpr uint64_t kNs = 1000;     // ps
constexpr uint64_t kUs = 1000000;  // ps

// IS25LP128 (spi_flash.h's table).
constexpr uint64_t kRes1 = 3 * kUs;
constexpr uint64_t kDp = 3 * kUs;
constexpr uint64_t kPp = 200 * kUs;
constexpr uint64_t kSe = 70000 * kUs;
constexpr uint64_t kRst = 100 * kUs;

std::string why;       // the failing check of the current case
std::string reported;  // the violation a case expected, as the model worded it (shown by -v)

#define CHECK(cond)                                                                \
    do {                                                                           \
        if (!(cond)) {                                                             \
            why = std::string("line ") + std::to_string(__LINE__) + ": " + #cond; \
            return false;                                                          \
        }                                                                          \
    } while (0)

using Bytes = std::vector<uint8_t>;

// A SPI master at the flash's pins. It owns the time and the levels of CS#, SCK and MOSI and calls the
// flash at every change. One bit: SCK falls and MOSI changes (mode 0's first bit: SCK is already low),
// half a period later SCK rises and the master takes MISO as it was just before the edge.
class Master {
public:
    Master(SpiFlash &flash, uint64_t period_ps, bool mode3 = false)
        : flash_(flash), half_(period_ps / 2), mode3_(mode3), sck_(mode3) {
        step();
    }

    uint64_t gap_ps = 50 * kNs;    // CS# high before each command
    uint64_t setup_ps = 10 * kNs;  // CS# low to the first SCK edge (mode 3: the falling one)
    uint64_t hold_ps = 10 * kNs;   // the last rising SCK edge to CS# high, at least

    uint64_t now() const { return t_; }
    void wait(uint64_t ps) {  // pins unchanged
        t_ += ps;
        step();
    }

    struct Result {
        Bytes in;                  // the bytes read after `out`
        bool in_driven = true;     // every bit of `in` was driven by the flash
        bool out_driven = false;   // some bit during `out` was driven
        bool reading = false;      // read_in_progress() was true during `in`
    };

    // One command: CS# low, the bytes `out`, `in_bytes` bytes read with MOSI low, `extra_bits` more
    // clocks with MOSI high, CS# high.
    Result xfer(const Bytes &out, size_t in_bytes = 0, unsigned extra_bits = 0) {
        Result r;
        t_ += gap_ps;
        cs_n_ = false;
        step();
        t_ += setup_ps;
        for (uint8_t b : out) {
            for (int i = 7; i >= 0; --i) r.out_driven |= bit((b >> i) & 1).oe;
        }
        for (size_t k = 0; k < in_bytes; ++k) {
            uint8_t v = 0;
            for (int i = 0; i < 8; ++i) {
                const SpiFlashOut o = bit(false);
                v = static_cast<uint8_t>((v << 1) | (o.miso ? 1 : 0));
                r.in_driven &= o.oe;
                r.reading |= flash_.read_in_progress();
            }
            r.in.push_back(v);
        }
        for (unsigned i = 0; i < extra_bits; ++i) bit(true);
        if (!mode3_) {  // mode 0 leaves SCK low
            sck_ = false;
            step();
        }
        if (t_ < last_rise_ + hold_ps) t_ = last_rise_ + hold_ps;
        cs_n_ = true;
        step();
        return r;
    }

private:
    SpiFlashOut bit(bool b) {
        sck_ = false;
        mosi_ = b;
        step();
        const SpiFlashOut before = out_;
        t_ += half_;
        sck_ = true;
        step();
        last_rise_ = t_;
        t_ += half_;
        return before;
    }
    void step() { out_ = flash_.step(t_, cs_n_, sck_, mosi_); }

    SpiFlash &flash_;
    uint64_t half_;
    bool mode3_;
    uint64_t t_ = 0, last_rise_ = 0;
    bool cs_n_ = true, sck_, mosi_ = false;
    SpiFlashOut out_{false, false};
};

Bytes with_address(uint8_t op, uint32_t addr, const Bytes &tail = {}) {
    Bytes b = {op, static_cast<uint8_t>(addr >> 16), static_cast<uint8_t>(addr >> 8), static_cast<uint8_t>(addr)};
    b.insert(b.end(), tail.begin(), tail.end());
    return b;
}

uint8_t pattern(uint32_t a) { return static_cast<uint8_t>(a * 7 + (a >> 8) * 13 + (a >> 16) * 29 + 1); }

void load_pattern(SpiFlash &f, uint32_t from, uint32_t n) {
    Bytes b(n);
    for (uint32_t i = 0; i < n; ++i) b[i] = pattern(from + i);
    f.load(from, b);
}

Bytes expected(uint32_t from, uint32_t n, uint32_t size = 16u << 20) {
    Bytes b(n);
    for (uint32_t i = 0; i < n; ++i) b[i] = pattern((from + i) & (size - 1));
    return b;
}

SpiFlashConfig config(bool in_power_down = false) {
    SpiFlashConfig c;
    c.start_in_deep_power_down = in_power_down;
    return c;
}

std::string all_errors(const SpiFlash &f) {
    std::string s;
    for (const std::string &e : f.errors()) s += "\n    " + e;
    return s;
}

bool clean(const SpiFlash &f) {
    if (f.error_count() == 0) return true;
    why = "unexpected violations:" + all_errors(f);
    return false;
}

// Exactly one violation, of rule `rule`.
bool only(const SpiFlash &f, const char *rule) {
    if (f.error_count() == 1 && f.violations()[0].rule == rule) {
        reported = f.errors()[0];
        return true;
    }
    why = std::string("expected exactly one '") + rule + "' violation, got " + std::to_string(f.error_count()) + ":" +
          all_errors(f);
    return false;
}

bool read_is(Master &m, uint32_t addr, const Bytes &want, bool fast = false) {
    const Master::Result r =
        fast ? m.xfer(with_address(0x0B, addr, {0x00}), want.size()) : m.xfer(with_address(0x03, addr), want.size());
    if (r.out_driven) {
        why = "MISO driven during the command and address";
        return false;
    }
    if (!r.in_driven) {
        why = "MISO not driven during the data";
        return false;
    }
    for (size_t i = 0; i < want.size(); ++i) {
        if (r.in[i] != want[i]) {
            char buf[128];
            std::snprintf(buf, sizeof buf, "%s at 0x%06X: byte %zu is 0x%02X, expected 0x%02X",
                          fast ? "FAST READ" : "READ", addr, i, r.in[i], want[i]);
            why = buf;
            return false;
        }
    }
    return true;
}

uint8_t rdsr(Master &m) { return m.xfer({0x05}, 1).in[0]; }

// Poll RDSR every `every` until WIP clears; the polls that saw WIP set.
int wait_ready(Master &m, uint64_t every, int limit = 1000) {
    int polls = 0;
    while ((rdsr(m) & 1) != 0 && polls < limit) {
        ++polls;
        m.wait(every);
    }
    return polls;
}

// ---- legal sequences ----

bool rdid_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    const Master::Result r = m.xfer({0x9F}, 3);
    CHECK(!r.out_driven && r.in_driven);
    CHECK(r.in == Bytes({0x9D, 0x60, 0x18}));
    CHECK(f.counters().commands[0x9F] == 1);
    return clean(f);
}

bool read_case() {
    SpiFlash f;
    load_pattern(f, 0x000000, 64);
    load_pattern(f, 0x123400, 256);
    Master m(f, 40 * kNs);
    if (!read_is(m, 0x000000, expected(0x000000, 16))) return false;
    if (!read_is(m, 0x12345A, expected(0x12345A, 16))) return false;
    if (!read_is(m, 0xABCDE0, Bytes(16, 0xFF))) return false;  // never written: erased
    CHECK(f.counters().bytes_read == 48 && f.counters().commands[0x03] == 3);
    CHECK(!f.read_in_progress());
    CHECK(f.stats().find("READ (0x03) 3") != std::string::npos);
    return clean(f);
}

bool read_wrap_case() {
    SpiFlash f;
    load_pattern(f, 0xFFFF00, 256);
    load_pattern(f, 0x000000, 16);
    Master m(f, 40 * kNs);
    if (!read_is(m, 0xFFFFFC, expected(0xFFFFFC, 12))) return false;  // 4 at the end, then 0x000000 on
    return clean(f);
}

bool read_stream_case() {
    SpiFlash f;
    load_pattern(f, 0x00F00, 0x600);
    Master m(f, 40 * kNs);
    if (!read_is(m, 0x00F80, expected(0x00F80, 1024))) return false;  // 4 pages and a sector boundary
    CHECK(f.counters().bytes_read == 1024);
    CHECK(!f.read_in_progress());
    CHECK(m.xfer(with_address(0x03, 0x000000), 2).reading && !m.xfer({0x9F}, 2).reading);
    return clean(f);
}

bool read_50mhz_case() {
    SpiFlash f;
    load_pattern(f, 0x4000, 64);
    Master m(f, 20 * kNs);  // exactly fC
    if (!read_is(m, 0x4010, expected(0x4010, 32))) return false;
    CHECK(f.counters().min_sck_period_ps == 20 * kNs);
    return clean(f);
}

bool fast_read_case() {
    SpiFlash f;
    load_pattern(f, 0x123400, 256);
    Master m(f, 10 * kNs);  // 100 MHz: FAST READ only
    if (!read_is(m, 0x123450, expected(0x123450, 32), true)) return false;
    CHECK(f.counters().bytes_read == 32);
    return clean(f);
}

bool mode3_case() {
    SpiFlash f;
    load_pattern(f, 0x2000, 256);
    Master m(f, 40 * kNs, true);
    const Master::Result r = m.xfer({0x9F}, 3);
    CHECK(r.in == Bytes({0x9D, 0x60, 0x18}) && r.in_driven);
    if (!read_is(m, 0x2010, expected(0x2010, 16))) return false;
    if (!read_is(m, 0x20F0, expected(0x20F0, 16), true)) return false;
    CHECK(f.counters().mode3_selections == 3 && f.counters().selections == 3);
    return clean(f);
}

bool status_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    CHECK(rdsr(m) == 0x00);
    m.xfer({0x06});
    const Master::Result r = m.xfer({0x05}, 3);  // the status register, repeated
    CHECK(r.in == Bytes({0x02, 0x02, 0x02}));
    m.xfer({0x04});
    CHECK(rdsr(m) == 0x00);
    return clean(f);
}

bool release_case() {
    SpiFlash f(config(true));
    Master m(f, 40 * kNs);
    CHECK(f.deep_power_down());
    m.xfer({0xAB});
    CHECK(!f.deep_power_down());
    m.wait(kRes1);
    const Master::Result r = m.xfer({0x9F}, 3);
    CHECK(r.in == Bytes({0x9D, 0x60, 0x18}));
    return clean(f);
}

bool power_down_and_back_case() {
    SpiFlash f;
    load_pattern(f, 0x8000, 64);
    Master m(f, 40 * kNs);
    m.xfer({0xB9});
    CHECK(f.deep_power_down());
    m.wait(kDp);
    m.xfer({0xAB});
    m.wait(kRes1);
    if (!read_is(m, 0x8000, expected(0x8000, 16))) return false;
    return clean(f);
}

bool res_id_case() {
    SpiFlash f(config(true));
    Master m(f, 40 * kNs);
    const Master::Result r = m.xfer({0xAB, 0x00, 0x00, 0x00}, 2);  // RES: 3 dummy bytes, then the ID
    CHECK(r.in == Bytes({0x17, 0x17}) && r.in_driven && !r.out_driven);
    CHECK(!f.deep_power_down());
    m.wait(kRes1);
    CHECK(rdsr(m) == 0x00);
    return clean(f);
}

bool program_case() {
    SpiFlash f;
    f.load(0x000100, Bytes(8, 0xF0));
    Master m(f, 40 * kNs);
    m.xfer({0x06});
    m.xfer(with_address(0x02, 0x000100, {0x3C, 0xFF, 0x00, 0xAA}));
    CHECK(rdsr(m) == 0x03);  // WIP and WEL
    CHECK(f.busy());
    m.wait(kPp);
    CHECK(rdsr(m) == 0x00);  // both clear when the program is over
    if (!read_is(m, 0x000100, {0x30, 0xF0, 0x00, 0xA0, 0xF0})) return false;  // 1 -> 0 only
    CHECK(f.counters().pages_programmed == 1 && f.counters().bytes_programmed == 4);
    return clean(f);
}

bool program_wrap_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x06});
    m.xfer(with_address(0x02, 0x0002FE, {0x01, 0x02, 0x03, 0x04}));
    CHECK(wait_ready(m, 20 * kUs) >= 1);
    if (!read_is(m, 0x000200, {0x03, 0x04, 0xFF})) return false;  // wrapped to the page's start
    if (!read_is(m, 0x0002FE, {0x01, 0x02, 0xFF})) return false;  // 0x300: the next page, untouched
    return clean(f);
}

bool erase_case() {
    SpiFlash f;
    load_pattern(f, 0x1000, 0x2000);
    Master m(f, 40 * kNs);
    m.xfer({0x06});
    m.xfer(with_address(0x20, 0x001234));
    const int polls = wait_ready(m, 1000 * kUs, 200);
    CHECK(polls >= 69 && polls <= 71);  // 70 ms
    CHECK(f.read_backdoor(0x1000, 0x1000) == Bytes(0x1000, 0xFF));
    Bytes want(32, 0xFF);
    const Bytes next = expected(0x2000, 32);
    want.insert(want.end(), next.begin(), next.end());
    if (!read_is(m, 0x1FE0, want)) return false;  // the sector erased, the next one not
    CHECK(f.counters().sectors_erased == 1);
    return clean(f);
}

bool reset_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x06});
    m.xfer({0x66});
    m.xfer({0x99});
    m.wait(kRst);
    CHECK(rdsr(m) == 0x00);  // WEL cleared
    return clean(f);
}

bool backdoor_case() {
    SpiFlash f;
    CHECK(f.peek(0x765432) == 0xFF);
    f.load(0xFFFFFE, {0x12, 0x34});
    CHECK(f.read_backdoor(0xFFFFFE, 2) == Bytes({0x12, 0x34}));
    bool threw = false;
    try {
        f.load(0xFFFFFF, {0x00, 0x00});
    } catch (const std::out_of_range &) {
        threw = true;
    }
    CHECK(threw);
    std::string error;
    CHECK(!f.load_file(0, "/nonexistent/firmware.bin", &error) && !error.empty());
    threw = false;
    f.step(100, true, false, false);
    try {
        f.step(99, true, false, false);
    } catch (const std::invalid_argument &) {
        threw = true;
    }
    CHECK(threw);
    return clean(f);
}

// ---- each violation ----

bool fsck_read_case() {
    SpiFlash f;
    Master m(f, 15 * kNs);  // 66.7 MHz: above fC
    m.xfer(with_address(0x03, 0x000000), 4);
    return only(f, "fSCK");
}

bool fsck_fast_read_accepted_case() {
    SpiFlash f;
    load_pattern(f, 0x0000, 64);
    Master m(f, 15 * kNs);  // the same 66.7 MHz: within fCT
    if (!read_is(m, 0x000000, expected(0, 4), true)) return false;
    return clean(f);
}

bool fsck_fast_read_case() {
    SpiFlash f;
    Master m(f, 7 * kNs);  // 143 MHz: above fCT
    m.xfer(with_address(0x0B, 0x000000, {0x00}), 4);
    return only(f, "fSCK");
}

bool tceh_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x9F}, 3);
    m.gap_ps = 5 * kNs;  // tCEH is 7 ns
    m.xfer({0x9F}, 3);
    return only(f, "tCEH");
}

bool tcs_case() {
    SpiFlash f;
    Master m(f, 8 * kNs);
    m.setup_ps = 0;  // the first rising edge half a period (4 ns) after CS# falls; tCS is 6 ns
    m.xfer({0x9F}, 3);
    return only(f, "tCS");
}

bool tch_case() {
    SpiFlash f;
    Master m(f, 8 * kNs, true);
    m.hold_ps = 0;  // mode 3: CS# rises half a period (4 ns) after the last rising edge; tCH is 6 ns
    m.xfer({0x9F}, 3);
    return only(f, "tCH");
}

bool command_in_power_down_case() {
    SpiFlash f(config(true));
    Master m(f, 40 * kNs);
    const Master::Result r = m.xfer(with_address(0x03, 0x000000), 4);
    CHECK(!r.in_driven);
    return only(f, "deep power-down");
}

bool tres1_case() {
    SpiFlash f(config(true));
    Master m(f, 40 * kNs);
    m.xfer({0xAB});
    m.wait(1 * kUs);  // tRES1 is 3 us
    m.xfer({0x9F}, 3);
    return only(f, "tRES1");
}

bool tdp_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0xB9});
    m.wait(1 * kUs);  // tDP is 3 us
    m.xfer({0xAB});
    return only(f, "tDP");
}

bool program_without_wren_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer(with_address(0x02, 0x000000, {0x00, 0x00}));
    CHECK(!f.busy());
    CHECK(f.read_backdoor(0, 2) == Bytes({0xFF, 0xFF}));  // ignored
    return only(f, "WEL");
}

bool erase_without_wren_case() {
    SpiFlash f;
    f.load(0x3000, {0x00});
    Master m(f, 40 * kNs);
    m.xfer(with_address(0x20, 0x003000));
    CHECK(f.peek(0x3000) == 0x00);
    return only(f, "WEL");
}

bool command_while_busy_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x06});
    m.xfer(with_address(0x02, 0x000000, {0x55}));
    CHECK((rdsr(m) & 1) == 1);  // RDSR is taken while busy
    const Master::Result r = m.xfer(with_address(0x03, 0x000000), 1);
    CHECK(!r.in_driven);
    return only(f, "busy");
}

bool unknown_opcode_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    const Master::Result r = m.xfer(with_address(0x3B, 0x000000, {0x00}), 2);  // dual output read
    CHECK(!r.in_driven);
    CHECK(only(f, "opcode"));
    CHECK(f.errors()[0].find("0x3B") != std::string::npos);
    return true;
}

bool partial_program_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x06});
    m.xfer(with_address(0x02, 0x000000, {0x00}), 0, 3);  // a data byte and 3 bits
    CHECK(f.peek(0) == 0xFF && !f.busy());
    CHECK(rdsr(m) == 0x02);  // ignored: WEL still set
    return only(f, "byte boundary");
}

bool partial_opcode_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({}, 0, 5);
    return only(f, "byte boundary");
}

bool erase_length_case() {
    SpiFlash f;
    f.load(0x5000, {0x00});
    Master m(f, 40 * kNs);
    m.xfer({0x06});
    m.xfer({0x20, 0x00, 0x50});  // two address bytes
    CHECK(f.peek(0x5000) == 0x00);
    return only(f, "length");
}

bool wren_length_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x06, 0x00});  // a byte too many
    CHECK(rdsr(m) == 0x00);  // ignored
    return only(f, "length");
}

bool reset_without_enable_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x99});
    return only(f, "reset enable");
}

bool trst_case() {
    SpiFlash f;
    Master m(f, 40 * kNs);
    m.xfer({0x66});
    m.xfer({0x99});
    m.wait(10 * kUs);
    rdsr(m);
    return only(f, "tRST");
}

bool fail_fast_case() {
    SpiFlashConfig c;
    c.fail_fast = true;
    SpiFlash f(c);
    CHECK(f.describe() == "no violations");
    Master m(f, 40 * kNs);
    m.xfer({0xC7});  // chip erase: not carried
    CHECK(f.failed());
    CHECK(f.describe() == f.errors()[0] && f.describe().find("[opcode]") != std::string::npos);
    return only(f, "opcode");
}

struct Case {
    const char *name;
    std::function<bool()> run;
};

}  // namespace

int main(int argc, char **argv) {
    const bool verbose = argc > 1 && std::strcmp(argv[1], "-v") == 0;
    const std::vector<Case> cases = {
        {"RDID: the JEDEC ID", rdid_case},
        {"READ at three addresses", read_case},
        {"READ wraps at the end of the array", read_wrap_case},
        {"READ streams 1 KiB across pages and a sector", read_stream_case},
        {"READ at exactly 50 MHz", read_50mhz_case},
        {"FAST READ with 8 dummy clocks at 100 MHz", fast_read_case},
        {"SPI mode 3", mode3_case},
        {"RDSR and the write enable latch", status_case},
        {"release from deep power-down, then RDID", release_case},
        {"deep power-down and back, then READ", power_down_and_back_case},
        {"RES: release reading the electronic ID", res_id_case},
        {"page program: 1 -> 0 only, WIP, read back", program_case},
        {"page program wraps within the page", program_wrap_case},
        {"sector erase to 0xFF", erase_case},
        {"software reset clears WEL", reset_case},
        {"backdoor load / read and time order", backdoor_case},
        {"READ at 66.7 MHz", fsck_read_case},
        {"FAST READ at 66.7 MHz is fine", fsck_fast_read_accepted_case},
        {"FAST READ at 143 MHz", fsck_fast_read_case},
        {"CS# high 5 ns", tceh_case},
        {"CS# setup 4 ns", tcs_case},
        {"CS# hold 4 ns", tch_case},
        {"READ in deep power-down", command_in_power_down_case},
        {"RDID 1 us after the release", tres1_case},
        {"RELEASE 1 us after DEEP POWER-DOWN", tdp_case},
        {"PAGE PROGRAM without WREN", program_without_wren_case},
        {"SECTOR ERASE without WREN", erase_without_wren_case},
        {"READ while programming", command_while_busy_case},
        {"unknown opcode 0x3B", unknown_opcode_case},
        {"PAGE PROGRAM ending within a byte", partial_program_case},
        {"CS# rising within the opcode", partial_opcode_case},
        {"SECTOR ERASE with a 2-byte address", erase_length_case},
        {"WREN with a second byte", wren_length_case},
        {"RESET without RESET ENABLE", reset_without_enable_case},
        {"RDSR 10 us after RESET", trst_case},
        {"fail fast and describe()", fail_fast_case},
    };

    int failed = 0;
    for (const Case &c : cases) {
        why.clear();
        reported.clear();
        if (!c.run()) {
            ++failed;
            std::printf("spi_flash: FAILED %s: %s\n", c.name, why.c_str());
        } else if (verbose) {
            std::printf("spi_flash: ok %s%s%s\n", c.name, reported.empty() ? "" : "\n    ", reported.c_str());
        }
    }
    if (failed != 0) {
        std::printf("spi_flash: FAILED %d of %zu cases\n", failed, cases.size());
        return 1;
    }
    std::printf("spi_flash: ok %zu cases\n", cases.size());
    return 0;
}
