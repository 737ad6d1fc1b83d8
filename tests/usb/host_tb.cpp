// host_tb: the USB low-speed host (soc_rtl/usb/usb_ls_host.v and its layers), Verilated at 50 MHz,
// against the keyboard model at the pins (cosim/usb/usb_kbd_device.cpp, which checks every packet,
// bit time, CRC, toggle, keep-alive and timing rule the host must keep). The bench steps the model
// at every change of the host's drive, every clock while the model is busy() and every microsecond
// otherwise (its calling convention), and gives the host the lines bus() resolves.
// Cases (each ends with the model's violations at 0 and the host's counters asserted):
//   attach -> enumeration -> running, text typed through the model's type_text arriving as the
//   press/release usages its reports imply; bad CRC16s (retried), no answer 3 times (retried), no
//   answer 4 times (the transfer fails: a reset and a new enumeration), a STALLed poll
//   (CLEAR_FEATURE(ENDPOINT_HALT)), a 7-byte report (counted, ignored), a 9-byte data packet (a
//   corrupted packet: retried), a disconnect in the middle of a report (detach), re-attach, a
//   detach and a second keyboard whose SET_PROTOCOL and SET_IDLE STALL, babble (the port disabled
//   until a detach), and a re-attach after it; the endpoint halted (CLEAR_FEATURE), the host's ACK
//   lost (a repeat acknowledged and dropped), ErrorRollOver, a full event FIFO, enable low.
//     host_tb [-v]
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "Vusb_ls_host.h"
#include "verilated.h"

#include "usb_kbd_device.h"

#define TB_NAME "host_tb"
#include "host_tb_common.h"

static const char *kStateName[] = {"detached", "attached", "resetting", "enumerating", "running",
                                   "no boot keyboard", "babble", "?"};

struct Bench {
    std::unique_ptr<Vusb_ls_host> h{new Vusb_ls_host};
    std::unique_ptr<UsbKbdDevice> dev;
    uint64_t cyc = 0;
    UsbHostDrive last_host;
    UsbDeviceDrive ddrive;
    std::vector<Event> events;
    uint64_t steps = 0;
    uint64_t allowed_violations = 0;   // a case that breaks a rule on purpose (the lost ACK)
    // The host's silent gaps: from its release of the bus to its next drive, the device silent in
    // between, in clocks (a turnaround timeout's retry: 16..18 bit times plus the synchroniser).
    uint64_t released_cyc = 0;
    bool host_released = false, device_spoke = false;
    uint64_t gaps_timeout = 0, gaps_bad = 0;
    // hide the host's next handshake from the model (an ACK lost on the wire)
    bool hide_ack = false, hiding = false;
    uint64_t device_end_cyc = 0;
    bool device_was = false;
    bool last_hidden = false;

    uint64_t t() const { return cyc * kClkPs; }
    double ms() const { return double(t()) * 1e-9; }

    Bench() {
        h->clk = 0;
        h->rst = 1;
        h->enable = 1;
        h->ev_ready = 1;
        h->usb_dp_in = 0;
        h->usb_dn_in = 0;
        for (int i = 0; i < 4; ++i) clock();
        h->rst = 0;
    }

    void clock() {
        UsbHostDrive hd;
        hd.oe = h->usb_oe;
        hd.dp = h->usb_dp_out;
        hd.dm = h->usb_dn_out;
        if (hd.oe && !last_host.oe) {
            if (host_released && !device_spoke && hd.dp) {   // a packet (its SYNC's K), not a keep-alive's SE0
                double bits = double(cyc - released_cyc) / (50e6 / 1.5e6);
                if (bits >= 16.0 && bits < 19.0) ++gaps_timeout;
                else if (bits >= 19.0 && bits < 300.0) {
                    ++gaps_bad;
                    if (verbose) std::printf("  a silent gap of %.2f bit times at %.3f ms\n", bits, ms());
                }
            }
            // a host packet within 10 bit times of the device's: the handshake of its DATA
            if (hide_ack && device_end_cyc != 0 && cyc - device_end_cyc < 333) {
                hide_ack = false;
                hiding = true;
            }
        }
        if (!hd.oe && last_host.oe) {
            host_released = true;
            device_spoke = false;
            released_cyc = cyc;
            hiding = false;
        }
        if (ddrive.oe) device_spoke = true;
        if (device_was && !ddrive.oe) device_end_cyc = cyc;
        device_was = ddrive.oe;
        if (dev) {
            UsbHostDrive seen = hiding ? UsbHostDrive() : hd;
            UsbHostDrive last_seen = last_hidden ? UsbHostDrive() : last_host;
            bool changed = seen.oe != last_seen.oe || seen.dp != last_seen.dp || seen.dm != last_seen.dm;
            if (changed || dev->busy() || cyc % 50 == 0) {
                ddrive = dev->step(t(), seen);
                ++steps;
            }
            last_hidden = hiding;
        } else {
            ddrive = UsbDeviceDrive();
        }
        last_host = hd;
        UsbLines l = UsbKbdDevice::bus(hd, ddrive);
        h->usb_dp_in = l.dp;
        h->usb_dn_in = l.dm;
        if (h->ev_valid && h->ev_ready) events.push_back({bool(h->ev_press), uint8_t(h->ev_usage)});
        h->clk = 1;
        h->eval();
        h->clk = 0;
        h->eval();
        ++cyc;
    }

    template <class P>
    bool run_until(P pred, double max_ms) {
        uint64_t end = cyc + uint64_t(max_ms * 50000.0);
        while (cyc < end) {
            if (pred()) return true;
            clock();
        }
        return pred();
    }
    void run_ms(double n) {
        uint64_t end = cyc + uint64_t(n * 50000.0);
        while (cyc < end) clock();
    }

    void plug(const UsbKbdConfig &cfg) {
        dev.reset(new UsbKbdDevice(cfg));
        allowed_violations = 0;
        dev->attach(t());
        ddrive = dev->step(t(), last_host);
    }
    int state() const { return h->state; }

    bool enumerate(const char *what) {
        bool ok = run_until([&] { return state() == S_RUNNING; }, 400);
        CHECK(ok, "%s: not running %.1f ms after attach (state %s)", what, ms(), kStateName[state()]);
        return ok;
    }

    // Types text and waits for every report to be delivered, then 12 ms more.
    std::vector<Event> type(const std::string &text) {
        events.clear();
        dev->type_text(text, t());
        run_until([&] { return dev->reports_queued() == 0; }, 40.0 * double(text.size() * 2 + 4));
        run_ms(12);   // the last report's events (it was acknowledged: they are out within a clock)
        return events;
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

    void no_violations(const char *what) {
        CHECK(dev->error_count() == allowed_violations, "%s: the model reports %llu violations", what,
              (unsigned long long)dev->error_count());
        if (dev->error_count() != allowed_violations)
            for (size_t i = 0; i < dev->errors().size() && i < 10; ++i) std::printf("  %s\n", dev->errors()[i].c_str());
    }
};

struct Counters {
    unsigned crc, timeout, retry, nak, stall, attach, detach, wrong_len, overflow, reenum, rollover;
};
static Counters counters(const Vusb_ls_host &h) {
    return {h.cnt_crc, h.cnt_timeout, h.cnt_retry, h.cnt_nak, h.cnt_stall, h.cnt_attach, h.cnt_detach,
            h.cnt_wrong_len, h.cnt_overflow, h.cnt_reenum, h.cnt_rollover};
}
static void print_counters(const char *what, const Vusb_ls_host &h) {
    if (!verbose) return;
    Counters c = counters(h);
    std::printf("  %s: crc %u timeout %u retry %u nak %u stall %u attach %u detach %u wrong_len %u overflow %u "
                "reenum %u rollover %u\n",
                what, c.crc, c.timeout, c.retry, c.nak, c.stall, c.attach, c.detach, c.wrong_len, c.overflow,
                c.reenum, c.rollover);
}

int main(int argc, char **argv) {
    Verilated::commandArgs(argc, argv);
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "-v")) verbose = true;
    Bench b;
    Vusb_ls_host &h = *b.h;

    // ---- nothing attached: the host waits, drives nothing ----
    b.run_ms(2);
    CHECK(b.state() == S_DETACHED && !h.usb_oe, "detached at start: state %d oe %d", b.state(), h.usb_oe);

    // ---- 1. attach, enumeration, typing ----
    UsbKbdConfig cfg;
    b.plug(cfg);
    b.run_ms(50);
    CHECK(b.state() == S_ATTACHED, "50 ms after attach: debouncing (state %s)", kStateName[b.state()]);
    double t_attach = b.ms() - 50;
    if (b.enumerate("enumeration")) {
        std::printf("host_tb: enumerated %.1f ms after attach: address %d, endpoint %02x, bInterval %d ms\n",
                    b.ms() - t_attach, h.dev_addr, h.kbd_ep, h.kbd_interval);
    }
    CHECK(b.dev->configured() && b.dev->address() == 1 && h.dev_addr == 1, "configured at address 1");
    CHECK(b.dev->protocol() == 0 && b.dev->idle_rate() == 0, "boot protocol (%d), idle 0 (%d)", b.dev->protocol(),
          b.dev->idle_rate());
    CHECK(h.kbd_ep == 0x81 && h.kbd_interval == 10 && h.kbd_mps == 8, "endpoint 0x81, 8 bytes, 10 ms");
    CHECK(h.cnt_attach == 1 && h.cnt_stall == 0 && h.cnt_crc == 0 && h.cnt_timeout == 0 && h.cnt_reenum == 0,
          "clean enumeration counters");
    b.expect_typed("Hi, 1{F1}\n", "typed");
    CHECK(h.cnt_nak > 0, "NAKs counted when nothing is typed");
    b.no_violations("enumeration and typing");
    print_counters("after typing", h);

    // ---- 2. two bad CRC16s: no ACK, retried ----
    Counters c0 = counters(h);
    b.dev->corrupt_crc_next(2);
    b.expect_typed("ab", "bad CRC16 x2");
    Counters c1 = counters(h);
    CHECK(c1.crc == c0.crc + 2 && c1.retry == c0.retry + 2 && c1.reenum == c0.reenum,
          "bad CRC: crc +%u retry +%u reenum +%u", c1.crc - c0.crc, c1.retry - c0.retry, c1.reenum - c0.reenum);
    b.no_violations("bad CRC16");

    // ---- 3. no answer 3 times: retried, no re-enumeration ----
    c0 = counters(h);
    b.dev->no_answer_next(3);
    b.expect_typed("c", "no answer x3");
    c1 = counters(h);
    CHECK(b.gaps_timeout >= 3 && b.gaps_bad == 0, "no answer x3: %llu retries 16..19 bit times after the EOP, %llu later",
          (unsigned long long)b.gaps_timeout, (unsigned long long)b.gaps_bad);
    CHECK(c1.timeout == c0.timeout + 3 && c1.retry == c0.retry + 3 && c1.reenum == c0.reenum,
          "no answer x3: timeout +%u retry +%u reenum +%u", c1.timeout - c0.timeout, c1.retry - c0.retry,
          c1.reenum - c0.reenum);
    b.no_violations("no answer x3");

    // ---- 4. no answer 4 times: the transfer fails, reset, enumeration again ----
    c0 = counters(h);
    uint64_t resets0 = b.dev->counters().resets;
    b.dev->no_answer_next(4);
    b.run_until([&] { return counters(h).reenum != c0.reenum; }, 50);
    b.enumerate("re-enumeration after a failed poll");
    c1 = counters(h);
    CHECK(c1.timeout == c0.timeout + 4 && c1.retry == c0.retry + 3 && c1.reenum == c0.reenum + 1 &&
              b.dev->counters().resets == resets0 + 1,
          "no answer x4: timeout +%u retry +%u reenum +%u resets +%llu", c1.timeout - c0.timeout,
          c1.retry - c0.retry, c1.reenum - c0.reenum, (unsigned long long)(b.dev->counters().resets - resets0));
    b.expect_typed("d", "after re-enumeration");
    b.no_violations("no answer x4");

    // ---- 5. a STALLed poll: CLEAR_FEATURE(ENDPOINT_HALT), the toggle from DATA0 ----
    c0 = counters(h);
    b.dev->stall_next(1);
    b.expect_typed("e", "after a STALL");
    c1 = counters(h);
    CHECK(c1.stall == c0.stall + 1 && c1.reenum == c0.reenum, "STALL: stall +%u reenum +%u", c1.stall - c0.stall,
          c1.reenum - c0.reenum);
    b.no_violations("STALL");

    // ---- 5b. the endpoint halted (STALL until CLEAR_FEATURE), twice: once at each toggle ----
    c0 = counters(h);
    {
        UsbKbdReport x, up;
        x.keys[0] = 0x1b;  // 'x'
        b.events.clear();
        b.dev->set_endpoint_halt(true);
        b.dev->queue_report(x, b.t());   // one report: the toggle's parity changes
        b.run_until([&] { return b.dev->reports_queued() == 0; }, 60);
        b.run_ms(12);
        b.dev->set_endpoint_halt(true);
        b.dev->queue_report(up, b.t());
        b.run_until([&] { return b.dev->reports_queued() == 0; }, 60);
        b.run_ms(12);
        std::vector<Event> want = {{true, 0x1b}, {false, 0x1b}};
        CHECK(b.events == want && !b.dev->endpoint_halted(), "halt: %zu events, halted %d", b.events.size(),
              b.dev->endpoint_halted());
    }
    c1 = counters(h);
    CHECK(c1.stall == c0.stall + 2 && c1.reenum == c0.reenum, "halt: stall +%u reenum +%u", c1.stall - c0.stall,
          c1.reenum - c0.reenum);
    b.no_violations("endpoint halt");

    // ---- 5c. the host's ACK lost on the wire: the device sends the report again with the same
    // PID; the host acknowledges the repeat and drops it (one 'handshake' violation: the model
    // saw no ACK, which is the point)
    {
        b.hide_ack = true;
        b.expect_typed("m", "a lost ACK");
        CHECK(!b.hide_ack && b.dev->counters().retransmissions >= 1, "lost ACK: a retransmission (%llu)",
              (unsigned long long)b.dev->counters().retransmissions);
        size_t handshake = 0;
        for (const UsbKbdViolation &v : b.dev->violations()) handshake += v.rule == "handshake";
        CHECK(handshake == 1 && b.dev->error_count() == 1, "lost ACK: %zu handshake violations of %llu", handshake,
              (unsigned long long)b.dev->error_count());
        b.allowed_violations = b.dev->error_count();
    }

    // ---- 6. a 7-byte report: counted, ignored (its release is no event either) ----
    c0 = counters(h);
    b.dev->wrong_length_next(1, 7);
    {
        std::vector<Event> got = b.type("f");
        CHECK(got.empty(), "7-byte report: %zu events", got.size());
    }
    c1 = counters(h);
    CHECK(c1.wrong_len == c0.wrong_len + 1, "wrong length +%u", c1.wrong_len - c0.wrong_len);
    b.expect_typed("g", "after a 7-byte report");
    b.no_violations("wrong length");

    // ---- 7. a 9-byte data packet (longer than low speed allows): corrupted, retried ----
    c0 = counters(h);
    b.dev->babble_next(UsbBabble::kLongPacket, 1);
    b.expect_typed("h", "after a 9-byte packet");
    c1 = counters(h);
    CHECK(c1.crc == c0.crc + 1 && c1.retry == c0.retry + 1 && b.state() == S_RUNNING,
          "9-byte packet: crc +%u retry +%u state %s", c1.crc - c0.crc, c1.retry - c0.retry, kStateName[b.state()]);
    b.no_violations("9-byte packet");

    // ---- 7b. ErrorRollOver: the phantom report ignored, no release storm ----
    c0 = counters(h);
    {
        UsbKbdReport a, roll, up;
        a.keys[0] = 0x04;
        roll.keys[0] = 0x04;
        for (int i = 1; i < 6; ++i) roll.keys[i] = 0x01;
        b.events.clear();
        b.dev->queue_report(a, b.t());
        b.dev->queue_report(roll, b.t());
        b.dev->queue_report(up, b.t());
        b.run_until([&] { return b.dev->reports_queued() == 0; }, 60);
        b.run_ms(20);
        std::vector<Event> want = {{true, 0x04}, {false, 0x04}};
        CHECK(b.events == want, "rollover: %zu events", b.events.size());
    }
    c1 = counters(h);
    CHECK(c1.rollover == c0.rollover + 1, "rollover +%u", c1.rollover - c0.rollover);
    b.no_violations("rollover");

    // ---- 7c. a consumer not ready: the FIFO fills, the overflow counted ----
    c0 = counters(h);
    h.ev_ready = 0;
    {
        const std::string text = "ABCDE";   // 20 events, 16 fit
        b.events.clear();
        b.dev->type_text(text, b.t());
        b.run_until([&] { return b.dev->reports_queued() == 0; }, 150);
        b.run_ms(20);
        h.ev_ready = 1;
        b.run_ms(1);
        std::vector<Event> want = expected_for(text);
        c1 = counters(h);
        CHECK(b.events.size() == 16 && c1.overflow == c0.overflow + want.size() - 16 &&
                  std::equal(b.events.begin(), b.events.end(), want.begin()),
              "overflow: %zu events kept, overflow +%u", b.events.size(), c1.overflow - c0.overflow);
    }
    b.no_violations("overflow");

    // ---- 8. disconnect in the middle of a report: detach; re-attach ----
    c0 = counters(h);
    {
        UsbKbdReport q;
        q.keys[0] = 0x14;  // 'q', held
        b.events.clear();
        b.dev->queue_report(q, b.t());
        b.run_until([&] { return b.dev->reports_queued() == 0; }, 40);
        b.run_ms(2);
    }
    b.dev->disconnect_during_next_data(12);
    b.dev->queue_report(UsbKbdReport(), b.t());   // its release: cut by the disconnect
    bool det = b.run_until([&] { return b.state() == S_DETACHED; }, 60);
    CHECK(det && counters(h).detach == c0.detach + 1, "disconnect: detached (%d), detach +%u", det,
          counters(h).detach - c0.detach);
    CHECK(!h.usb_oe, "detached: nothing driven");
    b.run_ms(5);
    CHECK(b.state() == S_DETACHED && !h.usb_oe, "still detached, no keep-alive");
    {
        std::vector<Event> want = {{true, 0x14}, {false, 0x14}};
        CHECK(b.events == want, "the held 'q' released by the detach itself: %zu events", b.events.size());
    }
    b.dev->attach(b.t());
    b.enumerate("re-attach after a disconnect");
    b.run_ms(40);
    {
        // the held key released by the detach, and nothing else (the release report, sent again
        // after the re-attach or not, changes nothing)
        std::vector<Event> want = {{true, 0x14}, {false, 0x14}};
        CHECK(b.events == want, "disconnect with 'q' held: %zu events", b.events.size());
    }
    c1 = counters(h);
    CHECK(c1.attach == c0.attach + 1, "re-attach counted");
    b.expect_typed("j", "after re-attach");
    b.no_violations("disconnect and re-attach");

    // ---- 9. detach; a keyboard that STALLs SET_PROTOCOL and SET_IDLE ----
    c0 = counters(h);
    b.dev->detach(b.t());
    det = b.run_until([&] { return b.state() == S_DETACHED; }, 2);
    CHECK(det && counters(h).detach == c0.detach + 1, "detach seen");
    b.no_violations("detach");
    b.run_ms(20);
    UsbKbdConfig cfg2;
    cfg2.stall_set_idle = true;
    cfg2.stall_set_protocol = true;
    cfg2.two_interfaces = false;
    cfg2.allow_suspend = true;   // the babble case below disables the port (no keep-alives)
    b.plug(cfg2);
    b.enumerate("second keyboard (STALLs)");
    c1 = counters(h);
    CHECK(c1.stall == c0.stall + 2 && c1.reenum == c0.reenum && c1.attach == c0.attach + 1,
          "STALLed SET_PROTOCOL/SET_IDLE: stall +%u reenum +%u", c1.stall - c0.stall, c1.reenum - c0.reenum);
    CHECK(b.dev->configured() && b.dev->protocol() == 1, "configured, report protocol kept (%d)", b.dev->protocol());
    b.expect_typed("OK!", "second keyboard");
    b.no_violations("second keyboard");

    // ---- 10. babble: the port disabled until a detach ----
    c0 = counters(h);
    b.dev->babble_next(UsbBabble::kNoEop, 200);
    b.events.clear();
    b.dev->type_text("k", b.t());
    bool bab = b.run_until([&] { return b.state() == S_BABBLE; }, 60);
    CHECK(bab, "babble: state %s", kStateName[b.state()]);
    uint64_t oe_clocks = 0;
    for (int i = 0; i < 5 * 50000; ++i) {
        b.clock();
        oe_clocks += h.usb_oe;
    }
    CHECK(oe_clocks == 0 && b.state() == S_BABBLE, "babble: %llu clocks driven in 5 ms", (unsigned long long)oe_clocks);
    CHECK(b.events.empty(), "babble: %zu events", b.events.size());
    b.dev->detach(b.t());
    det = b.run_until([&] { return b.state() == S_DETACHED; }, 2);
    CHECK(det, "babble then detach: detached");
    b.run_ms(10);
    b.dev->attach(b.t());
    b.enumerate("re-attach after babble");
    b.run_ms(30);
    b.events.clear();
    b.expect_typed("z", "after babble");
    b.no_violations("babble");
    // ---- 11. enable low: nothing driven, detached; high again: a new attach ----
    c0 = counters(h);
    h.enable = 0;
    oe_clocks = 0;
    for (int i = 0; i < 3 * 50000; ++i) {
        b.clock();
        oe_clocks += h.usb_oe;
    }
    CHECK(oe_clocks == 0 && b.state() == S_DETACHED, "enable low: %llu clocks driven, state %s",
          (unsigned long long)oe_clocks, kStateName[b.state()]);
    h.enable = 1;
    b.enumerate("enable again");
    c1 = counters(h);
    CHECK(c1.attach == c0.attach + 1 && c1.crc == c0.crc, "enable again: attach +%u", c1.attach - c0.attach);
    b.expect_typed("y", "after enable");
    b.no_violations("enable");
    print_counters("at the end", h);
    CHECK(b.gaps_bad == 0 && b.gaps_timeout == 6, "over the run: %llu retries right after a timeout (6 expected), "
          "%llu host packets 19..300 bit times after its own EOP with the device silent",
          (unsigned long long)b.gaps_timeout, (unsigned long long)b.gaps_bad);

    std::printf("host_tb: %.0f ms simulated, %llu model steps\n", b.ms(), (unsigned long long)b.steps);
    if (failures) {
        std::printf("host_tb: %ld of %ld checks failed\n", failures, checks);
        return 1;
    }
    std::printf("host_tb: ok %ld checks\n", checks);
    return 0;
}
