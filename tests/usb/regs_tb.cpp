// regs_tb: the USB host's register block (soc_rtl/usb/soc_usb.v over usb_ls_host), Verilated at
// 50 MHz with the keyboard model at its pins (cosim/usb/usb_kbd_device.cpp, stepped as in
// tests/usb/host_tb.cpp) and a Wishbone B4 classic master here: every access goes through the bus,
// with the offsets and fields of contract/soc_map.h, and must be answered in the next clock.
// Cases: after reset CTRL is 0 and the port is left alone (nothing driven with a keyboard plugged);
// a CTRL write without ENABLE's byte lane is ignored; ENABLE set, STATUS polled until running
// (ADDR 1; KBD: endpoint 0x81, 8 bytes, 10 ms); KEY reads 0 when empty; text typed through the model
// read back as KEY events, one popped per read, in the order usb_hid_keys gives them; two bad CRC16s
// (CRC_ERRORS and RETRIES +2); events left unread past the FIFO's 16 (OVERFLOWS, then the 16 held
// drained and 0); every counter readable; unnamed offsets answer err (reads and writes), a write to
// a read-only register is acked and ignored; ENABLE cleared: nothing driven, STATE detached, the
// counters kept, the keyboard suspended by the idle bus (the model's one expected [suspend] report).
//     regs_tb [-v]
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "Vsoc_usb.h"
#include "verilated.h"

#include "soc_map.h"
#include "usb_kbd_device.h"

#define TB_NAME "regs_tb"
#include "host_tb_common.h"

static uint32_t field(uint32_t word, uint32_t lsb, uint32_t mask) { return (word & mask) >> lsb; }

enum class Resp { kAck, kErr, kNone };

struct Bench {
    std::unique_ptr<Vsoc_usb> h{new Vsoc_usb};
    std::unique_ptr<UsbKbdDevice> dev;
    uint64_t cyc = 0, steps = 0, oe_clocks = 0;
    UsbHostDrive last_host;
    UsbDeviceDrive ddrive;

    uint64_t t() const { return cyc * kClkPs; }
    double ms() const { return double(t()) * 1e-9; }

    Bench() {
        h->clk = 0;
        h->rst = 1;
        h->wb_cyc = 0;
        h->wb_stb = 0;
        h->usb_dp_in = 0;
        h->usb_dn_in = 0;
        for (int i = 0; i < 4; ++i) clock();
        h->rst = 0;
        h->eval();
    }

    // One clock: the model stepped at every change of the host's drive, every clock while it is
    // busy, else every microsecond; the host given the resolved lines; then the edge.
    void clock() {
        UsbHostDrive hd;
        hd.oe = h->usb_oe;
        hd.dp = h->usb_dp_out;
        hd.dm = h->usb_dn_out;
        oe_clocks += hd.oe;
        if (dev) {
            bool changed = hd.oe != last_host.oe || hd.dp != last_host.dp || hd.dm != last_host.dm;
            if (changed || dev->busy() || cyc % 50 == 0) {
                ddrive = dev->step(t(), hd);
                ++steps;
            }
        }
        last_host = hd;
        UsbLines l = UsbKbdDevice::bus(hd, ddrive);
        h->usb_dp_in = l.dp;
        h->usb_dn_in = l.dm;
        h->clk = 1;
        h->eval();
        h->clk = 0;
        h->eval();
        ++cyc;
    }
    void run_ms(double n) {
        uint64_t end = cyc + uint64_t(n * 50000.0);
        while (cyc < end) clock();
    }

    // One Wishbone classic access: the request for one clock, the answer (ack or err, exactly one)
    // expected right after it; then the request withdrawn for a clock (the master's idle clock).
    Resp access(bool we, uint32_t off, uint32_t wdata, uint8_t sel, uint32_t *rdata) {
        h->wb_cyc = 1;
        h->wb_stb = 1;
        h->wb_we = we;
        h->wb_adr = (off >> 2) & 0x3F;
        h->wb_dat_w = wdata;
        h->wb_sel = sel;
        h->eval();
        CHECK(!h->wb_ack && !h->wb_err, "offset 0x%02x: answered in the request's first clock", off);
        clock();
        Resp r = h->wb_ack && !h->wb_err ? Resp::kAck : h->wb_err && !h->wb_ack ? Resp::kErr : Resp::kNone;
        CHECK(r != Resp::kNone, "offset 0x%02x: ack %d err %d in the clock after the request", off, h->wb_ack,
              h->wb_err);
        if (rdata) *rdata = h->wb_dat_r;
        clock();   // the answer's clock ends; the request is withdrawn after it
        h->wb_cyc = 0;
        h->wb_stb = 0;
        h->wb_we = 0;
        h->eval();
        CHECK(!h->wb_ack && !h->wb_err, "offset 0x%02x: answered after the request", off);
        clock();
        return r;
    }
    uint32_t rd(uint32_t off) {
        uint32_t v = 0;
        Resp r = access(false, off, 0, 0xF, &v);
        CHECK(r == Resp::kAck, "read 0x%02x: not acked", off);
        return v;
    }
    void wr(uint32_t off, uint32_t v, uint8_t sel = 0xF) {
        Resp r = access(true, off, v, sel, nullptr);
        CHECK(r == Resp::kAck, "write 0x%02x: not acked", off);
    }
    unsigned state() { return field(rd(SOC_USB_REG_STATUS), SOC_USB_STATUS_STATE_LSB, SOC_USB_STATUS_STATE_MASK); }

    // KEY reads until one returns 0 (VALID clear), every event appended; returns how many.
    size_t drain(std::vector<Event> *out) {
        size_t n = 0;
        for (;;) {
            uint32_t k = rd(SOC_USB_REG_KEY);
            if (!(k & SOC_USB_KEY_VALID)) {
                CHECK(k == 0, "KEY empty reads 0x%08x", k);
                return n;
            }
            CHECK((k & ~(SOC_USB_KEY_VALID | SOC_USB_KEY_PRESS | SOC_USB_KEY_USAGE_MASK)) == 0, "KEY 0x%08x", k);
            out->push_back({bool(k & SOC_USB_KEY_PRESS), uint8_t(field(k, SOC_USB_KEY_USAGE_LSB, SOC_USB_KEY_USAGE_MASK))});
            ++n;
        }
    }

    // Types text, reading KEY every 0.5 ms, until the model has sent every report and 12 ms more.
    std::vector<Event> type(const std::string &text) {
        std::vector<Event> got;
        dev->type_text(text, t());
        uint64_t end = cyc + uint64_t(40.0 * double(text.size() * 2 + 4) * 50000.0);
        uint64_t quiet = 0;
        while (cyc < end) {
            run_ms(0.5);
            drain(&got);
            if (dev->reports_queued() == 0 && quiet == 0) quiet = cyc + 12 * 50000;
            if (quiet && cyc >= quiet) break;
        }
        drain(&got);
        return got;
    }
    void expect_typed(const std::string &text, const char *what) {
        std::vector<Event> got = type(text), want = expected_for(text);
        CHECK(got == want, "%s: %zu events for '%s', %zu expected", what, got.size(), text.c_str(), want.size());
        if (verbose || got != want) {
            std::printf("  %s:", what);
            for (const Event &e : got) std::printf(" %c%02x", e.press ? '+' : '-', e.usage);
            std::printf("\n");
        }
    }
};

struct Counter {
    const char *name;
    uint32_t off;
};
static const Counter kCounters[] = {
    {"CRC_ERRORS", SOC_USB_REG_CRC_ERRORS}, {"TIMEOUTS", SOC_USB_REG_TIMEOUTS}, {"RETRIES", SOC_USB_REG_RETRIES},
    {"NAKS", SOC_USB_REG_NAKS},             {"STALLS", SOC_USB_REG_STALLS},     {"ATTACHES", SOC_USB_REG_ATTACHES},
    {"DETACHES", SOC_USB_REG_DETACHES},     {"WRONG_LEN", SOC_USB_REG_WRONG_LEN}, {"OVERFLOWS", SOC_USB_REG_OVERFLOWS},
    {"REENUMS", SOC_USB_REG_REENUMS},       {"ROLLOVERS", SOC_USB_REG_ROLLOVERS},
};

int main(int argc, char **argv) {
    Verilated::commandArgs(argc, argv);
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "-v")) verbose = true;
    Bench b;
    Vsoc_usb &h = *b.h;

    // ---- after reset: off, nothing driven, with a keyboard plugged ----
    b.dev.reset(new UsbKbdDevice(UsbKbdConfig()));
    b.dev->attach(b.t());
    b.ddrive = b.dev->step(b.t(), b.last_host);
    CHECK(b.rd(SOC_USB_REG_CTRL) == 0, "CTRL 0 after reset");
    b.run_ms(150);
    CHECK(b.oe_clocks == 0 && b.state() == S_DETACHED, "off: %llu clocks driven in 150 ms, state %u",
          (unsigned long long)b.oe_clocks, b.state());
    // a write without ENABLE's byte lane: ignored
    b.wr(SOC_USB_REG_CTRL, SOC_USB_CTRL_ENABLE, uint8_t(0xF & ~(1u << (SOC_USB_CTRL_ENABLE_LSB / 8))));
    CHECK(b.rd(SOC_USB_REG_CTRL) == 0, "CTRL write without ENABLE's lane ignored");
    CHECK(b.rd(SOC_USB_REG_KEY) == 0, "KEY 0 before any key");

    // ---- ENABLE: attach, enumeration, STATUS polled until running ----
    b.wr(SOC_USB_REG_CTRL, SOC_USB_CTRL_ENABLE);
    CHECK(b.rd(SOC_USB_REG_CTRL) == SOC_USB_CTRL_ENABLE, "CTRL reads ENABLE back");
    double t_on = b.ms();
    unsigned st = S_DETACHED, polls = 0;
    while (st != S_RUNNING && b.ms() - t_on < 400) {
        b.run_ms(1);
        st = b.state();
        ++polls;
    }
    uint32_t status = b.rd(SOC_USB_REG_STATUS), kbd = b.rd(SOC_USB_REG_KBD);
    unsigned addr = field(status, SOC_USB_STATUS_ADDR_LSB, SOC_USB_STATUS_ADDR_MASK);
    CHECK(st == S_RUNNING, "not running 400 ms after ENABLE (state %u)", st);
    std::printf("regs_tb: running %.1f ms after ENABLE (%u STATUS polls): STATUS 0x%08x, KBD 0x%08x\n",
                b.ms() - t_on, polls, status, kbd);
    CHECK(addr == 1 && b.dev->address() == 1 && b.dev->configured(), "ADDR %u, configured at 1", addr);
    CHECK(field(kbd, SOC_USB_KBD_EP_LSB, SOC_USB_KBD_EP_MASK) == 0x81 &&
              field(kbd, SOC_USB_KBD_MPS_LSB, SOC_USB_KBD_MPS_MASK) == 8 &&
              field(kbd, SOC_USB_KBD_INTERVAL_LSB, SOC_USB_KBD_INTERVAL_MASK) == 10,
          "KBD 0x%08x: endpoint 0x81, 8 bytes, 10 ms", kbd);
    CHECK(b.rd(SOC_USB_REG_KEY) == 0, "KEY 0 when empty");

    // ---- typing: each KEY read pops one event ----
    b.expect_typed("Hi, 1\n", "typed");
    CHECK(b.rd(SOC_USB_REG_KEY) == 0 && b.rd(SOC_USB_REG_KEY) == 0, "KEY 0 after the last event, twice");

    // ---- two bad CRC16s: CRC_ERRORS and RETRIES ----
    uint32_t crc0 = b.rd(SOC_USB_REG_CRC_ERRORS), retry0 = b.rd(SOC_USB_REG_RETRIES);
    b.dev->corrupt_crc_next(2);
    b.expect_typed("ab", "bad CRC16 x2");
    uint32_t crc1 = b.rd(SOC_USB_REG_CRC_ERRORS), retry1 = b.rd(SOC_USB_REG_RETRIES);
    CHECK(crc1 == crc0 + 2 && retry1 == retry0 + 2, "bad CRC16 x2: CRC_ERRORS %u -> %u, RETRIES %u -> %u", crc0, crc1,
          retry0, retry1);

    // ---- events left unread: the FIFO's 16 kept, the rest counted in OVERFLOWS ----
    const std::string many = "cdefghijk";   // 18 events
    std::vector<Event> want = expected_for(many);
    uint32_t ovf0 = b.rd(SOC_USB_REG_OVERFLOWS);
    b.dev->type_text(many, b.t());
    for (int i = 0; i < 400 && b.dev->reports_queued() != 0; ++i) b.run_ms(1);
    b.run_ms(12);
    uint32_t ovf1 = b.rd(SOC_USB_REG_OVERFLOWS);
    std::vector<Event> got;
    size_t held = b.drain(&got);
    CHECK(held == 16 && ovf1 == ovf0 + uint32_t(want.size() - 16) &&
              std::vector<Event>(want.begin(), want.begin() + 16) == got,
          "unread: %zu events held (16), OVERFLOWS %u -> %u (+%zu expected)", held, ovf0, ovf1, want.size() - 16);

    // ---- every counter readable, 16 bits ----
    uint32_t cnt[sizeof kCounters / sizeof kCounters[0]];
    for (size_t i = 0; i < sizeof kCounters / sizeof kCounters[0]; ++i) {
        cnt[i] = b.rd(kCounters[i].off);
        CHECK(cnt[i] <= 0xFFFF, "%s 0x%08x", kCounters[i].name, cnt[i]);
        if (verbose) std::printf("  %s %u\n", kCounters[i].name, cnt[i]);
    }
    CHECK(b.rd(SOC_USB_REG_ATTACHES) == 1 && b.rd(SOC_USB_REG_NAKS) > 0 && b.rd(SOC_USB_REG_STALLS) == 0 &&
              b.rd(SOC_USB_REG_REENUMS) == 0 && b.rd(SOC_USB_REG_TIMEOUTS) == 0 && b.rd(SOC_USB_REG_DETACHES) == 0,
          "counters: ATTACHES 1, NAKS > 0, no STALL, re-enumeration, timeout or detach");

    // ---- refused offsets (err), and a write to a read-only register (acked, ignored) ----
    for (uint32_t off : {0x3Cu, 0x40u, 0x80u, 0xFCu}) {
        uint32_t v = 0xDEAD;
        CHECK(b.access(false, off, 0, 0xF, &v) == Resp::kErr, "read 0x%02x: err", off);
        CHECK(b.access(true, off, 1, 0xF, nullptr) == Resp::kErr, "write 0x%02x: err", off);
    }
    uint32_t s0 = b.rd(SOC_USB_REG_STATUS);
    b.wr(SOC_USB_REG_STATUS, 0);
    b.wr(SOC_USB_REG_ATTACHES, 0);
    CHECK(b.rd(SOC_USB_REG_STATUS) == s0 && b.rd(SOC_USB_REG_ATTACHES) == 1, "writes to STATUS and ATTACHES ignored");
    CHECK(b.rd(SOC_USB_REG_CTRL) == SOC_USB_CTRL_ENABLE, "CTRL still ENABLE");

    CHECK(b.dev->error_count() == 0, "the model reports %llu violations while on", (unsigned long long)b.dev->error_count());

    // ---- ENABLE cleared: nothing driven, detached, the counters kept (the idle bus suspends the
    // keyboard after 3 ms: the model's one [suspend] report, expected here) ----
    b.wr(SOC_USB_REG_CTRL, 0);
    b.run_ms(0.01);
    uint64_t oe0 = b.oe_clocks;
    b.run_ms(5);
    CHECK(b.oe_clocks == oe0 && !h.usb_oe && b.state() == S_DETACHED, "off again: %llu clocks driven in 5 ms, state %u",
          (unsigned long long)(b.oe_clocks - oe0), b.state());
    CHECK(b.rd(SOC_USB_REG_ATTACHES) == 1 && b.rd(SOC_USB_REG_CRC_ERRORS) == crc1, "counters kept when off");
    CHECK(field(b.rd(SOC_USB_REG_STATUS), SOC_USB_STATUS_ADDR_LSB, SOC_USB_STATUS_ADDR_MASK) == 0, "ADDR 0 when off");
    std::vector<Event> rest;
    b.drain(&rest);
    CHECK(rest.empty(), "no key held when turned off: %zu events", rest.size());

    size_t other = 0;
    for (const UsbKbdViolation &v : b.dev->violations())
        if (v.rule != "suspend") ++other;
    CHECK(b.dev->error_count() == 1 && other == 0 && b.dev->counters().suspends == 2,
          "the model reports %llu violations (%zu not the suspend of the port turned off), %llu suspends (2: off at the start, off at the end)",
          (unsigned long long)b.dev->error_count(), other, (unsigned long long)b.dev->counters().suspends);
    for (size_t i = 0; i < b.dev->errors().size() && i < 10; ++i)
        if (verbose || other) std::printf("  %s\n", b.dev->errors()[i].c_str());

    std::printf("regs_tb: %.0f ms simulated, %llu model steps\n", b.ms(), (unsigned long long)b.steps);
    if (failures) {
        std::printf("regs_tb: %ld of %ld checks failed\n", failures, checks);
        return 1;
    }
    std::printf("regs_tb: ok %ld checks\n", checks);
    return 0;
}
