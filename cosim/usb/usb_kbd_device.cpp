// UsbKbdDevice: see usb_kbd_device.h. Written from the USB 2.0 specification's low-speed rules (which
// are USB 1.1's) and HID 1.11; shares no code with the host it checks.
#include "usb_kbd_device.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

namespace {

// PIDs (USB 2.0 Table 8-1): the 4-bit code; the byte on the wire has its complement in the high nibble.
constexpr uint8_t kOut = 0x1, kIn = 0x9, kSof = 0x5, kSetup = 0xD;
constexpr uint8_t kData0 = 0x3, kData1 = 0xB;
constexpr uint8_t kAck = 0x2, kNak = 0xA, kStall = 0xE;
constexpr uint8_t kMaxPacket = 8;  // endpoint 0 of a low-speed device, and endpoint 1 (5.5.3, 5.7.3)

// Standard requests (Table 9-4), descriptor types (Table 9-5), HID class requests (HID 7.2).
enum : uint8_t {
    kGetStatus = 0, kClearFeature = 1, kSetFeature = 3, kSetAddress = 5, kGetDescriptor = 6,
    kSetDescriptor = 7, kGetConfiguration = 8, kSetConfiguration = 9, kGetInterface = 10,
    kSetInterface = 11, kSynchFrame = 12,
};
enum : uint8_t { kDescDevice = 1, kDescConfig = 2, kDescString = 3, kDescHid = 0x21, kDescReport = 0x22 };
enum : uint8_t {
    kHidGetReport = 1, kHidGetIdle = 2, kHidGetProtocol = 3, kHidSetReport = 9, kHidSetIdle = 10,
    kHidSetProtocol = 11,
};

std::string hex(uint32_t v, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%0*x", digits, v);
    return buf;
}

std::string num(double v, int decimals = 1) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

uint8_t reverse5(uint8_t v) {
    uint8_t r = 0;
    for (int i = 0; i < 5; ++i) r = static_cast<uint8_t>(r | (((v >> i) & 1) << (4 - i)));
    return r;
}

// A UTF-16LE string descriptor (9.6.7).
std::vector<uint8_t> string_desc(const std::string &s) {
    std::vector<uint8_t> d = {static_cast<uint8_t>(2 + 2 * s.size()), kDescString};
    for (char c : s) {
        d.push_back(static_cast<uint8_t>(c));
        d.push_back(0);
    }
    return d;
}

std::string bytes_text(const std::vector<uint8_t> &b, size_t max = 12) {
    std::string s;
    for (size_t i = 0; i < b.size() && i < max; ++i) {
        char buf[4];
        std::snprintf(buf, sizeof buf, "%s%02x", i ? " " : "", b[i]);
        s += buf;
    }
    if (b.size() > max) s += " ...";
    return s;
}

}  // namespace

bool UsbKbdReport::operator==(const UsbKbdReport &o) const {
    return bytes() == o.bytes();
}

std::vector<uint8_t> UsbKbdReport::bytes() const {
    return {modifiers, reserved, keys[0], keys[1], keys[2], keys[3], keys[4], keys[5]};
}

// ---- CRCs (USB 2.0 8.3.5): the shift register of the specification's Figure, in transmission order ----

uint8_t UsbKbdDevice::crc5(uint32_t bits, int nbits) {
    uint8_t reg = 0x1F;  // preset to all ones
    for (int i = 0; i < nbits; ++i) {
        const uint8_t in = static_cast<uint8_t>((bits >> i) & 1);
        const uint8_t top = static_cast<uint8_t>((reg >> 4) & 1);
        reg = static_cast<uint8_t>((reg << 1) & 0x1F);
        if (top ^ in) reg ^= 0x05;  // x^5 + x^2 + 1
    }
    return static_cast<uint8_t>(reg ^ 0x1F);  // the complement is sent, x^4 first
}

uint16_t UsbKbdDevice::crc16(const uint8_t *data, size_t n) {
    // x^16 + x^15 + x^2 + 1 with the register kept bit-reversed, so that the bits go in LSB first and the
    // result comes out in the order it is sent (low byte first, each LSB first).
    uint16_t reg = 0xFFFF;
    for (size_t i = 0; i < n; ++i) {
        for (int b = 0; b < 8; ++b) {
            const bool in = (data[i] >> b) & 1;
            const bool out = reg & 1;
            reg = static_cast<uint16_t>(reg >> 1);
            if (in != out) reg ^= 0xA001;
        }
    }
    return static_cast<uint16_t>(~reg);
}

uint16_t UsbKbdDevice::token_field(uint8_t address, uint8_t endpoint) {
    const uint32_t bits = (address & 0x7Fu) | ((endpoint & 0xFu) << 7);
    return static_cast<uint16_t>(bits | (static_cast<uint32_t>(reverse5(crc5(bits, 11))) << 11));
}

// ---- construction, descriptors ----

UsbKbdDevice::UsbKbdDevice(const UsbKbdConfig &cfg) : cfg_(cfg) {
    if (cfg_.response_delay_bits < 0 || cfg_.timeout_bits <= 0 || cfg_.interval_ms == 0 ||
        cfg_.device_rate_ppm <= -1e6) {
        throw std::invalid_argument("UsbKbdConfig: response delay >= 0, a time-out, bInterval >= 1 ms");
    }
    dev_bit_ps_ = kBitPs / (1.0 + cfg_.device_rate_ppm / 1e6);
    build_descriptors();
    reset_device_state();
}

void UsbKbdDevice::build_descriptors() {
    // Interface 0's report: HID 1.11 Appendix B.1, the boot keyboard (46 bytes).
    report_desc_[0] = {0x05, 0x01,        // Usage Page (Generic Desktop)
                       0x09, 0x06,        // Usage (Keyboard)
                       0xA1, 0x01,        // Collection (Application)
                       0x75, 0x01,        //   Report Size (1)
                       0x95, 0x08,        //   Report Count (8)
                       0x05, 0x07,        //   Usage Page (Key Codes)
                       0x19, 0xE0,        //   Usage Minimum (224)
                       0x29, 0xE7,        //   Usage Maximum (231)
                       0x15, 0x00,        //   Logical Minimum (0)
                       0x25, 0x01,        //   Logical Maximum (1)
                       0x81, 0x02,        //   Input (Data, Variable, Absolute): modifier byte
                       0x95, 0x01,        //   Report Count (1)
                       0x75, 0x08,        //   Report Size (8)
                       0x81, 0x01,        //   Input (Constant): reserved byte
                       0x95, 0x06,        //   Report Count (6)
                       0x75, 0x08,        //   Report Size (8)
                       0x15, 0x00,        //   Logical Minimum (0)
                       0x26, 0xFF, 0x00,  //   Logical Maximum (255): two bytes, the value is signed
                       0x05, 0x07,        //   Usage Page (Key Codes)
                       0x19, 0x00,        //   Usage Minimum (0)
                       0x29, 0xFF,        //   Usage Maximum (255)
                       0x81, 0x00,        //   Input (Data, Array): 6 key usages
                       0xC0};             // End Collection
    // Interface 1's report: ASSUMED (the dump does not show it): one consumer-control usage, 16 bits.
    report_desc_[1] = {0x05, 0x0C, 0x09, 0x01, 0xA1, 0x01, 0x15, 0x00, 0x26, 0xFF, 0x03, 0x19, 0x00,
                       0x2A, 0xFF, 0x03, 0x75, 0x10, 0x95, 0x01, 0x81, 0x00, 0xC0};

    // Device descriptor (9.6.1): the Dell's, as lsusb shows it (raspberrypi/linux #273).
    dev_desc_ = {18,   kDescDevice,
                 0x10, 0x01,   // bcdUSB 1.10
                 0x00, 0x00, 0x00,  // class/subclass/protocol at interface level
                 8,            // bMaxPacketSize0
                 0x3C, 0x41,   // idVendor 0x413c (Dell)
                 0x10, 0x20,   // idProduct 0x2010
                 0x00, 0x02,   // bcdDevice 2.00
                 1, 3, 0,      // iManufacturer "Dell", iProduct "Dell USB Keyboard", no serial
                 1};           // bNumConfigurations

    auto hid = [](size_t report_len) {  // HID descriptor (HID 6.2.1): bcdHID 1.10 ASSUMED, no country
        return std::vector<uint8_t>{9, kDescHid, 0x10, 0x01, 0, 1, kDescReport,
                                    static_cast<uint8_t>(report_len & 0xFF), static_cast<uint8_t>(report_len >> 8)};
    };
    const uint8_t interfaces = cfg_.two_interfaces ? 2 : 1;
    std::vector<uint8_t> body;
    // Interface 0 (9.6.5): HID, boot subclass, keyboard, iInterface 3 — the dump's.
    body.insert(body.end(), {9, 4, 0, 0, 1, 3, 1, 1, 3});
    auto h0 = hid(report_desc_[0].size());
    body.insert(body.end(), h0.begin(), h0.end());
    // Endpoint 1 IN, interrupt, 8 bytes, bInterval (9.6.6): ASSUMED.
    body.insert(body.end(), {7, 5, 0x81, 0x03, kMaxPacket, 0, cfg_.interval_ms});
    if (cfg_.two_interfaces) {
        // Interface 1: HID, no subclass, no protocol, endpoint 2 IN: ASSUMED (a keyboard's hot keys).
        body.insert(body.end(), {9, 4, 1, 0, 1, 3, 0, 0, 3});
        auto h1 = hid(report_desc_[1].size());
        body.insert(body.end(), h1.begin(), h1.end());
        body.insert(body.end(), {7, 5, 0x82, 0x03, kMaxPacket, 0, cfg_.interval_ms});
    }
    const size_t total = 9 + body.size();  // 59 with two interfaces, as the Dell's wTotalLength
    // Configuration (9.6.3): value 1, iConfiguration 3, bus powered with remote wake-up, 50 mA.
    cfg_desc_ = {9, kDescConfig, static_cast<uint8_t>(total & 0xFF), static_cast<uint8_t>(total >> 8),
                 interfaces, 1, 3, 0xA0, 25};
    cfg_desc_.insert(cfg_desc_.end(), body.begin(), body.end());

    strings_.assign(4, {});
    strings_[0] = {4, kDescString, 0x09, 0x04};  // LANGID 0x0409, English (US): ASSUMED
    strings_[1] = string_desc("Dell");
    strings_[3] = string_desc("Dell USB Keyboard");
}

std::vector<uint8_t> UsbKbdDevice::string_descriptor(uint8_t index) const {
    return index < strings_.size() ? strings_[index] : std::vector<uint8_t>();
}

void UsbKbdDevice::reset_device_state() {
    address_ = 0;
    address_change_pending_ = false;
    address_recovering_ = false;
    configuration_ = 0;
    remote_wakeup_ = false;
    protocol_ = 1;                        // HID 7.2.6: report protocol after reset
    idle_4ms_ = cfg_.default_idle_4ms;    // HID 7.2.4
    leds_ = 0;
    stage_ = Stage::kIdle;
    status_stall_ = false;
    on_status_ = Action::kNone;
    ep0_toggle_ = 1;
    ep1_halted_ = false;
    ep1_toggle_ = 0;
    if (ep1_pending_ && ep1_new_) queue_.push_front({ep1_report_, 0});  // sent, never acknowledged: not lost
    ep1_pending_ = false;
    have_poll_ = false;
    expect_ = Expect::kNothing;
    late_ = Expect::kNothing;
    awaiting_ack_ = SentKind::kNone;
    tx_ = Tx();
    rx_ = Rx();
    discard_ = false;
}

// ---- messages ----

std::string UsbKbdDevice::time_text(uint64_t ps) {
    char buf[40];
    if (ps < 1000000000ull) {
        std::snprintf(buf, sizeof buf, "%.3f us", static_cast<double>(ps) / 1e6);
    } else {
        std::snprintf(buf, sizeof buf, "%.6f ms", static_cast<double>(ps) / 1e9);
    }
    return buf;
}

const char *UsbKbdDevice::pid_name(uint8_t pid) {
    static const char *const kNames[16] = {"reserved PID 0", "OUT", "ACK",   "DATA0", "PING",  "SOF",
                                           "NYET",           "DATA2", "SPLIT", "IN",   "NAK",   "DATA1",
                                           "PRE",            "SETUP", "STALL", "MDATA"};
    return kNames[pid & 0xF];
}

void UsbKbdDevice::violation(uint64_t t, const char *rule, const std::string &what) {
    ++error_count_;
    const std::string text = "usbkbd: " + time_text(t) + ": " + what + " [" + rule + "]";
    if (cfg_.fail_fast && error_count_ == 1) std::fprintf(stderr, "%s\n", text.c_str());
    if (errors_.size() < cfg_.max_messages) {
        errors_.push_back(text);
        violations_.push_back({t, rule, text});
    }
    trace(t, "VIOLATION " + what + " [" + rule + "]");
}

void UsbKbdDevice::trace(uint64_t t, const std::string &what) const {
    if (cfg_.trace) std::fprintf(stderr, "usbkbd: %s: %s\n", time_text(t).c_str(), what.c_str());
}

std::string UsbKbdDevice::stats() const {
    const UsbKbdCounters &c = counters_;
    static const char *const kState[] = {"detached", "powered", "default", "address", "configured"};
    return std::string("usbkbd: ") + kState[static_cast<int>(state_)] + ", address " + std::to_string(address_) +
           ", " + std::to_string(c.resets) + " resets, " + std::to_string(c.keep_alives) + " keep-alives, " +
           std::to_string(c.packets_received) + " packets in, " + std::to_string(c.packets_sent) + " out, " +
           std::to_string(c.control_transfers) + " control transfers, " + std::to_string(c.polls) + " polls, " +
           std::to_string(c.reports_delivered) + " reports delivered, " + std::to_string(c.naks_sent) + " NAKs, " +
           std::to_string(error_count_) + " violations";
}

// ---- attach, detach, the pins ----

void UsbKbdDevice::attach(uint64_t t) {
    if (started_ && t < t_) throw std::invalid_argument("UsbKbdDevice::attach: time went backwards");
    ++counters_.attaches;
    state_ = UsbKbdState::kPowered;  // 9.1.1: attached and powered, not yet reset: it answers nothing
    attach_ps_ = t;
    line_ = Line::kJ;                // the pull-up takes the bus to J
    line_ps_ = t;
    last_activity_ps_ = t;
    suspended_ = false;
    ever_reset_ = false;
    reset_active_ = false;
    recovering_ = false;
    have_keep_alive_ = false;
    have_eop_ = false;
    contention_ = false;
    se1_ = false;
    current_ = UsbKbdReport();  // the typing script (queue_) stays: the user goes on typing
    reset_device_state();
}

void UsbKbdDevice::detach(uint64_t t) {
    if (state_ == UsbKbdState::kDetached) return;
    ++counters_.detaches;
    trace(t, "detached");
    state_ = UsbKbdState::kDetached;
    reset_device_state();
}

UsbLines UsbKbdDevice::bus(const UsbHostDrive &host, const UsbDeviceDrive &device) {
    if (host.oe) return {host.dp, host.dm};
    if (device.oe) return {device.dp, device.dm};
    if (device.attached) return {false, true};  // J: the device's pull-up on D- (7.1.5.1)
    return {false, false};                        // SE0: the host's pull-downs alone
}

UsbKbdDevice::Line UsbKbdDevice::host_line(const UsbHostDrive &h) const {
    if (h.dp && h.dm) return Line::kSE1;
    if (h.dp) return Line::kK;   // low speed: K = D+ high (Table 7-2)
    if (h.dm) return Line::kJ;
    return Line::kSE0;
}

UsbDeviceDrive UsbKbdDevice::step(uint64_t t, const UsbHostDrive &host) {
    if (started_ && t < t_) throw std::invalid_argument("UsbKbdDevice::step: time went backwards");
    started_ = true;
    t_ = t;
    if (state_ == UsbKbdState::kDetached) return {};

    UsbDeviceDrive d = drive(t);
    if (state_ == UsbKbdState::kDetached) return {};  // the disconnect fault pulled the plug
    if (host.oe && d.oe) {
        if (!contention_) {
            violation(t, "bus contention", "the host drives D+/D- while the device sends its " + tx_.what);
        }
        contention_ = true;
    } else {
        contention_ = false;
    }
    if (d.oe) {
        last_activity_ps_ = t;  // the device's own packet is bus traffic; its receiver is off (half duplex)
        return d;
    }
    const Line now = host.oe ? host_line(host) : Line::kJ;  // nobody driving: the pull-up's J
    rx_timers(t);
    if (now != line_) rx_line(t, now);
    return d;
}

// ---- receiver: line states to bits (NRZI, 7.1.8), packets at EOP ----

void UsbKbdDevice::activity(uint64_t t) {
    last_activity_ps_ = t;
    wake(t);
}

void UsbKbdDevice::wake(uint64_t t) {
    if (!suspended_) return;
    suspended_ = false;
    ++counters_.resumes;
    trace(t, "resumed");
}

void UsbKbdDevice::rx_line(uint64_t t, Line now) {
    const Line old = line_;
    const uint64_t since = line_ps_;
    const bool was_suspended = suspended_;  // a K that wakes the device may be the host's resume signalling
    line_ = now;
    line_ps_ = t;
    activity(t);
    if (old == Line::kSE0) rx_end_se0(t, since, now);
    if (now == Line::kSE1) {
        if (!se1_) violation(t, "SE1", "the host drives D+ and D- high together (SE1, no line state of USB)");
        se1_ = true;
        rx_abort();
        return;
    }
    se1_ = false;
    if (now == Line::kSE0) {
        if (rx_.active && !discard_) {
            // The EOP begins: the bits up to it are 1s (no transition) after the last transition.
            const double n = std::round(static_cast<double>(t - rx_.last_tr_ps) / kBitPs);
            for (int i = 1; i < static_cast<int>(n) && i < 16; ++i) rx_.raw.push_back(1);
            rx_.se0 = true;
            rx_.se0_ps = t;
        }
        return;
    }
    if (discard_) return;  // after an error: nothing until the bus is idle again
    if (old == Line::kSE0 || old == Line::kSE1) {
        if (now == Line::kK) on_sop(t, was_suspended);  // SE0 -> K was reported by rx_end_se0: a packet
        return;
    }
    if (rx_.active) {
        rx_transition(t);
    } else if (now == Line::kK) {
        on_sop(t, was_suspended);  // J -> K on an idle bus: the SYNC's first bit
    }
}

void UsbKbdDevice::rx_transition(uint64_t t) {
    // A transition is a 0 (NRZI); the bit times since the previous one, less one, were 1s.
    double n = std::round(static_cast<double>(t - rx_.last_tr_ps) / kBitPs);
    if (n < 1) n = 1;  // closer than half a bit: the jitter check reports it
    for (int i = 1; i < static_cast<int>(n); ++i) rx_.raw.push_back(1);
    rx_.raw.push_back(0);
    rx_.tr_ps.push_back(t);
    rx_.tr_bit.push_back(static_cast<uint32_t>(rx_.raw.size() - 1));
    rx_.last_tr_ps = t;
}

void UsbKbdDevice::rx_end_se0(uint64_t t, uint64_t since, Line next) {
    const uint64_t d = t - since;
    if (reset_active_) {
        reset_active_ = false;
        reset_end_ps_ = t;
        recovering_ = true;
        if (d < cfg_.reset_min_ps) {
            violation(t, "reset", "reset SE0 of " + time_text(d) + ": shorter than TDRST " +
                                      time_text(cfg_.reset_min_ps) + " (7.1.7.5)");
        }
        trace(t, "reset ends after " + time_text(d));
        return;
    }
    if (discard_) {
        discard_ = false;  // the SE0 ends whatever packet was being ignored
        return;
    }
    const std::string follow = next == Line::kJ ? "" : next == Line::kK ? "K" : "SE1";
    if (rx_.active) {
        if (d < cfg_.eop_receive_ps) {
            violation(t, "EOP", "SE0 of " + time_text(d) + " inside a packet: shorter than an EOP (TLEOPR " +
                                    time_text(cfg_.eop_receive_ps) + ")");
            rx_abort();
            discard_ = false;
            return;
        }
        if (d < cfg_.eop_min_ps || d > cfg_.eop_max_ps) {
            violation(t, "EOP", "the host's EOP has an SE0 of " + time_text(d) + ", outside TLEOPT " +
                                    time_text(cfg_.eop_min_ps) + " .. " + time_text(cfg_.eop_max_ps));
        }
        if (!follow.empty()) violation(t, "EOP", "the host's EOP SE0 is followed by " + follow + ", not J");
        rx_packet(t);
        return;
    }
    // An SE0 on the idle bus: a keep-alive (a bare low-speed EOP) or a glitch.
    if (d < cfg_.eop_receive_ps) {
        violation(t, "SE0", "SE0 of " + time_text(d) + " on the idle bus: neither an EOP (TLEOPR " +
                                time_text(cfg_.eop_receive_ps) + ") nor a reset");
        return;
    }
    if (d < cfg_.eop_min_ps || d > cfg_.eop_max_ps) {
        violation(t, "EOP", "keep-alive SE0 of " + time_text(d) + ", outside TLEOPT " + time_text(cfg_.eop_min_ps) +
                                " .. " + time_text(cfg_.eop_max_ps));
    }
    if (!follow.empty()) violation(t, "EOP", "the keep-alive's SE0 is followed by " + follow + ", not J");
    keep_alive(since, t);
}

void UsbKbdDevice::rx_abort() {
    if (rx_.active) drop_expectation();
    rx_ = Rx();
    discard_ = true;
}

void UsbKbdDevice::drop_expectation() {
    // The awaited packet came in time but was not usable: the transaction is over, reported already.
    if (expect_ == Expect::kNothing || !expect_met_) return;
    if (expect_ == Expect::kHandshake) ++counters_.handshake_timeouts;
    expect_ = Expect::kNothing;
}

void UsbKbdDevice::rx_timers(uint64_t t) {
    if (line_ == Line::kSE0 && !reset_active_ && t - line_ps_ >= cfg_.reset_detect_ps) {
        bus_reset(line_ps_ + cfg_.reset_detect_ps);
    }
    const uint64_t quiet = bits_ps(7.5);  // six 1s and a stuffed 0 make 7 bit times without a transition
    if (rx_.active && !rx_.se0 && (line_ == Line::kJ || line_ == Line::kK) && t - rx_.last_tr_ps > quiet) {
        if (rx_.resume && line_ == Line::kK) {
            trace(rx_.sop_ps, "resume signalling (K) from the host");
        } else {
            violation(rx_.last_tr_ps + quiet, "bit stuffing",
                      "no transition for more than 7 bit times inside a packet (" + num(bits(t - rx_.last_tr_ps)) +
                          " so far): seven 1s, a stuffing error (7.1.9)");
        }
        rx_abort();
    }
    if (discard_ && line_ == Line::kJ && t - line_ps_ >= bits_ps(8)) discard_ = false;
    if (expect_ != Expect::kNothing && !expect_met_ && t > expect_deadline_) {
        const Expect e = expect_;
        expect_ = Expect::kNothing;
        late_ = e;
        if (e == Expect::kHandshake) {
            handshake_timeout(expect_deadline_);
        } else {
            violation(expect_deadline_, "turnaround",
                      std::string("no DATA packet within ") + num(cfg_.timeout_bits, 0) + " bit times after the " +
                          (e == Expect::kSetupData ? "SETUP" : "OUT") +
                          " token: the device gives up (7.1.19.1)");
        }
    }
    if (line_ == Line::kJ && !rx_.active && !tx_.scheduled && !suspended_ && !reset_active_ &&
        t - last_activity_ps_ > cfg_.suspend_idle_ps) {
        suspended_ = true;
        ++counters_.suspends;
        have_keep_alive_ = false;
        const uint64_t at = last_activity_ps_ + cfg_.suspend_idle_ps;
        trace(at, "suspended");
        if (ever_reset_ && state_ != UsbKbdState::kPowered && !cfg_.allow_suspend) {
            violation(at, "suspend", "the bus has been idle for " + time_text(cfg_.suspend_idle_ps) +
                                         " (no packet, no keep-alive): the device suspends (7.1.7.6)");
        }
    }
}

void UsbKbdDevice::on_sop(uint64_t t, bool was_suspended) {
    if (have_eop_ && t - last_eop_end_ps_ < bits_ps(cfg_.min_gap_bits)) {
        violation(t, "inter-packet delay", "the host's packet starts " + num(bits(t - last_eop_end_ps_), 2) +
                                               " bit times after the previous EOP: less than TIPD " +
                                               num(cfg_.min_gap_bits, 0) + " (7.1.18.1)");
    }
    if (tx_.scheduled && !tx_.active) {
        violation(t, "turnaround", "the host starts a packet " + num(bits(t - last_eop_end_ps_), 2) +
                                       " bit times after its EOP, before the device's " + tx_.what +
                                       " (due at " + num(cfg_.response_delay_bits, 1) +
                                       "): a host waits up to its time-out for the answer (7.1.19.1)");
        tx_ = Tx();
    }
    if (expect_ != Expect::kNothing && t <= expect_deadline_) expect_met_ = true;
    rx_ = Rx();
    rx_.active = true;
    rx_.resume = was_suspended;
    rx_.sop_ps = t;
    rx_.last_tr_ps = t;
    rx_.tr_ps.push_back(t);
    rx_.tr_bit.push_back(0);
    rx_.raw.push_back(0);
}

void UsbKbdDevice::check_timing(const Rx &r) {
    const size_t n = r.tr_ps.size();
    if (n < 2) return;
    const double span = static_cast<double>(r.tr_ps[n - 1] - r.tr_ps[0]);
    const double nbits = r.tr_bit[n - 1] - r.tr_bit[0];
    if (nbits <= 0) return;
    const double ideal = nbits * kBitPs;
    const double allow = ideal * cfg_.host_rate_ppm / 1e6 + static_cast<double>(cfg_.rate_slack_ps);
    if (std::fabs(span - ideal) > allow) {
        violation(r.sop_ps, "bit rate",
                  "the host's packet: " + num(nbits, 0) + " bit times in " + time_text(static_cast<uint64_t>(span)) +
                      ", " + num((ideal / span - 1.0) * 1e6, 0) + " ppm off 1.5 Mb/s (a host: +-" +
                      num(cfg_.host_rate_ppm, 0) + " ppm, TLDRATHS, 7.1.11)");
        return;  // its transitions are all off the nominal grid: jitter says nothing more
    }
    // Jitter (Table 7-10): "the time between any set of data transitions is N x TPERIOD +- jitter", TPERIOD
    // the source's actual period. The host passes when one period within its rate tolerance fits every
    // interval: each interval bounds the period to [(dt - J) / n, (dt + J) / n]; the bounds must meet.
    // (A short packet's own mean period is no good estimate: a 50 MHz host's edges sit up to a clock off.)
    const double band_lo = kBitPs * (1.0 - cfg_.host_rate_ppm / 1e6);
    const double band_hi = kBitPs * (1.0 + cfg_.host_rate_ppm / 1e6);
    double lo1 = band_lo, hi1 = band_hi;
    for (size_t i = 1; i < n; ++i) {
        const double dt = static_cast<double>(r.tr_ps[i] - r.tr_ps[i - 1]), k = r.tr_bit[i] - r.tr_bit[i - 1];
        lo1 = std::max(lo1, (dt - static_cast<double>(cfg_.jitter_next_ps)) / k);
        hi1 = std::min(hi1, (dt + static_cast<double>(cfg_.jitter_next_ps)) / k);
    }
    double lo2 = lo1, hi2 = hi1;
    for (size_t i = 2; i < n; ++i) {
        const double dt = static_cast<double>(r.tr_ps[i] - r.tr_ps[i - 2]), k = r.tr_bit[i] - r.tr_bit[i - 2];
        lo2 = std::max(lo2, (dt - static_cast<double>(cfg_.jitter_paired_ps)) / k);
        hi2 = std::min(hi2, (dt + static_cast<double>(cfg_.jitter_paired_ps)) / k);
    }
    // The period the messages and the EOP check use: the packet's mean, kept within the tolerance.
    const double period = std::min(std::max(span / nbits, band_lo), band_hi);
    if (lo1 > hi1 || lo2 > hi2) {
        const bool paired = lo1 <= hi1;
        const size_t apart = paired ? 2 : 1;
        double worst = 0;
        size_t at = apart;
        for (size_t i = apart; i < n; ++i) {
            const double dev =
                static_cast<double>(r.tr_ps[i] - r.tr_ps[i - apart]) - (r.tr_bit[i] - r.tr_bit[i - apart]) * period;
            if (std::fabs(dev) > std::fabs(worst)) {
                worst = dev;
                at = i;
            }
        }
        violation(r.tr_ps[at], "jitter",
                  std::string("a host transition ") + num(worst / 1000.0) + " ns off its place after " +
                      (paired ? "its pair (TDDJ2 +-" + num(cfg_.jitter_paired_ps / 1000.0, 0)
                              : "the previous one (TDDJ1 +-" + num(cfg_.jitter_next_ps / 1000.0, 0)) +
                      " ns, Table 7-10): no bit period within the rate tolerance fits the packet's transitions");
    }
    if (r.se0) {
        const double d = static_cast<double>(r.se0_ps - r.tr_ps[n - 1]);
        const double skew = d - std::round(d / period) * period;
        if (skew < static_cast<double>(cfg_.eop_skew_min_ps) || skew > static_cast<double>(cfg_.eop_skew_max_ps)) {
            violation(r.se0_ps, "EOP", "the host's last transition to its EOP's SE0 is " + num(skew / 1000.0) +
                                           " ns off whole bits (TLDEOP " + num(cfg_.eop_skew_min_ps / 1000.0, 0) +
                                           " .. +" + num(cfg_.eop_skew_max_ps / 1000.0, 0) + " ns)");
        }
    }
}

void UsbKbdDevice::rx_packet(uint64_t eop_end) {
    Rx r = std::move(rx_);
    rx_ = Rx();
    ++counters_.packets_received;
    last_eop_end_ps_ = eop_end;
    have_eop_ = true;
    static const uint8_t kSync[8] = {0, 0, 0, 0, 0, 0, 0, 1};  // KJKJKJKK (7.1.10)
    if (r.raw.size() < 8 || !std::equal(kSync, kSync + 8, r.raw.begin())) {
        std::string got;
        for (size_t i = 0; i < r.raw.size() && i < 8; ++i) got += r.raw[i] ? '1' : '0';
        violation(r.sop_ps, "SYNC",
                  "the host's packet starts " + got + " (NRZI-decoded), not the SYNC 00000001 = KJKJKJKK");
        drop_expectation();
        return;
    }
    check_timing(r);
    // Unstuff (7.1.9): after six 1s (the SYNC's last 1 counts) a 0 follows and is dropped.
    std::vector<uint8_t> bits;
    int ones = 0;
    for (size_t i = 0; i < r.raw.size(); ++i) {
        if (ones == 6) {
            if (r.raw[i] != 0) {
                violation(r.sop_ps, "bit stuffing", "seven 1s in a row at bit " + std::to_string(i) +
                                                        " of the host's packet (7.1.9)");
                drop_expectation();
                return;
            }
            ones = 0;
            continue;
        }
        ones = r.raw[i] ? ones + 1 : 0;
        if (i >= 8) bits.push_back(r.raw[i]);
    }
    if (ones == 6) {
        violation(r.sop_ps, "bit stuffing", "six 1s right before the EOP without the stuffed 0 (7.1.9.1: stuffing is "
                                            "enforced up to the EOP)");
        drop_expectation();
        return;
    }
    if (bits.size() % 8 != 0) {
        violation(r.sop_ps, "packet length", "the host's packet has " + std::to_string(bits.size()) +
                                                 " bits after the SYNC: not whole bytes");
    }
    std::vector<uint8_t> bytes(bits.size() / 8, 0);
    for (size_t i = 0; i < bytes.size() * 8; ++i) {
        bytes[i / 8] = static_cast<uint8_t>(bytes[i / 8] | (bits[i] << (i % 8)));  // LSB first (8.1)
    }
    if (bytes.empty()) {
        violation(r.sop_ps, "packet length", "the host's packet has no PID");
        drop_expectation();
        return;
    }
    on_packet(r.sop_ps, eop_end, bytes);
}

// ---- bus events ----

void UsbKbdDevice::bus_reset(uint64_t t) {
    ++counters_.resets;
    trace(t, "bus reset");
    reset_active_ = true;
    if (line_ps_ < attach_ps_ + cfg_.attach_debounce_ps) {
        violation(line_ps_, "attach debounce", "reset " + time_text(line_ps_ - attach_ps_) +
                                                   " after attach: the host debounces the attach for TATTDB " +
                                                   time_text(cfg_.attach_debounce_ps) + " first (7.1.7.3)");
    }
    ever_reset_ = true;
    suspended_ = false;
    have_keep_alive_ = false;
    have_eop_ = false;
    rx_ = Rx();
    discard_ = false;
    reset_device_state();
    state_ = UsbKbdState::kDefault;
}

void UsbKbdDevice::keep_alive(uint64_t start, uint64_t end) {
    ++counters_.keep_alives;
    last_eop_end_ps_ = end;
    have_eop_ = true;
    if (cfg_.check_keep_alive && have_keep_alive_ && ever_reset_) {
        const double period = static_cast<double>(start - last_keep_alive_ps_);
        const double frame = static_cast<double>(cfg_.frame_ps);
        if (std::fabs(period - frame) > frame * cfg_.frame_ppm / 1e6) {
            violation(start, "keep-alive", "keep-alive " + time_text(start - last_keep_alive_ps_) +
                                               " after the previous one: one per frame, 1 ms +-" +
                                               num(cfg_.frame_ppm, 0) + " ppm (TFRAME, 11.8.4.1)");
        }
    }
    have_keep_alive_ = true;
    last_keep_alive_ps_ = start;
}

// ---- packets ----

void UsbKbdDevice::on_packet(uint64_t sop, uint64_t eop_end, const std::vector<uint8_t> &bytes) {
    const uint8_t pid = bytes[0] & 0xF;
    if ((bytes[0] >> 4) != (~pid & 0xF)) {
        violation(sop, "PID", "PID byte " + hex(bytes[0], 2) + ": the check nibble is not the complement of " +
                                  hex(pid, 1) + " (8.3.1)");
        drop_expectation();
        return;
    }
    trace(sop, std::string("host ") + pid_name(pid) + " " + bytes_text(bytes));
    const Expect late = late_;
    late_ = Expect::kNothing;
    const Expect awaited = expect_;
    const bool in_time = expect_met_;
    if (awaited != Expect::kNothing) {
        expect_ = Expect::kNothing;
        expect_met_ = false;
    }
    auto not_awaited = [&](const std::string &what) {
        // A different packet in place of the awaited one: the transaction is over.
        if (awaited == Expect::kHandshake && in_time) {
            ++counters_.handshake_timeouts;
            if (!awaiting_exempt_) {
                violation(sop, "handshake",
                          "the host sends " + what + " where the ACK of the device's data packet belongs (8.4.6)");
            }
        } else if ((awaited == Expect::kSetupData || awaited == Expect::kOutData) && in_time) {
            const char *token = awaited == Expect::kSetupData ? "SETUP" : "OUT";
            violation(sop, "control sequence",
                      "the host sends " + what + " where the DATA packet of the " + token + " token belongs");
        }
    };

    switch (pid) {
    case kSetup:
    case kIn:
    case kOut: {
        not_awaited(std::string(pid_name(pid)) + " token");
        if (bytes.size() != 3) {
            violation(sop, "packet length", std::string(pid_name(pid)) + " token of " + std::to_string(bytes.size()) +
                                                " bytes: a token is the PID and 2 bytes (8.4.1)");
            return;
        }
        const uint16_t field = static_cast<uint16_t>(bytes[1] | (bytes[2] << 8));
        const uint8_t addr = field & 0x7F, ep = (field >> 7) & 0xF;
        const uint8_t want = reverse5(crc5(field & 0x7FF, 11)), got = static_cast<uint8_t>(field >> 11);
        if (want != got) {
            violation(sop, "CRC5", std::string(pid_name(pid)) + " token to address " + std::to_string(addr) +
                                       " endpoint " + std::to_string(ep) + ": CRC5 field " + hex(got, 2) +
                                       ", expected " + hex(want, 2) + " (8.3.5.1)");
            return;
        }
        on_token(sop, eop_end, pid, addr, ep);
        return;
    }
    case kData0:
    case kData1: {
        if (bytes.size() < 3) {
            not_awaited(std::string("short ") + pid_name(pid) + " packet");
            violation(sop, "packet length", std::string(pid_name(pid)) + " packet of " + std::to_string(bytes.size()) +
                                                " bytes: no room for the CRC16 (8.4.4)");
            return;
        }
        const std::vector<uint8_t> payload(bytes.begin() + 1, bytes.end() - 2);
        const uint16_t got = static_cast<uint16_t>(bytes[bytes.size() - 2] | (bytes.back() << 8));
        const uint16_t want = crc16(payload.data(), payload.size());
        if (got != want) {
            violation(sop, "CRC16", std::string(pid_name(pid)) + " packet of " + std::to_string(payload.size()) +
                                        " bytes: CRC16 " + hex(got, 4) + ", expected " + hex(want, 4) + " (8.3.5.2)");
            if (awaited == Expect::kSetupData || awaited == Expect::kOutData) return;  // ignored: no handshake
            not_awaited(std::string(pid_name(pid)) + " packet with a bad CRC16");
            return;
        }
        ++counters_.data_received;
        if (awaited == Expect::kSetupData || awaited == Expect::kOutData) {
            if (!in_time) return;
            if (payload.size() > kMaxPacket) {
                violation(sop, "packet length",
                          std::string(pid_name(pid)) + " packet of " + std::to_string(payload.size()) +
                              " bytes: endpoint 0 takes 8 (5.5.3)");
                return;
            }
            on_data(sop, eop_end, pid, awaited == Expect::kSetupData, payload);
            return;
        }
        not_awaited(std::string(pid_name(pid)) + " packet");
        if (late == Expect::kSetupData || late == Expect::kOutData) return;  // its lateness was reported
        violation(sop, "control sequence", std::string(pid_name(pid)) + " packet with no SETUP or OUT token before it");
        return;
    }
    case kAck:
        if (bytes.size() != 1) {
            violation(sop, "packet length",
                      "ACK of " + std::to_string(bytes.size()) + " bytes: a handshake is the PID alone");
        }
        if (awaited == Expect::kHandshake && in_time) {
            on_ack(eop_end);
            return;
        }
        not_awaited("ACK");
        if (late == Expect::kHandshake) return;  // too late, reported at the time-out
        violation(sop, "handshake", "an ACK with no data packet of the device to acknowledge");
        return;
    case kNak:
    case kStall:
        if (awaited == Expect::kHandshake && in_time) {
            ++counters_.handshake_timeouts;  // not acknowledged: sent again at the next IN
        } else {
            not_awaited(pid_name(pid));
        }
        violation(sop, "handshake", std::string("the host sends ") + pid_name(pid) +
                                        ": a host acknowledges data with ACK or not at all (8.4.6)");
        return;
    case kSof:
        not_awaited("SOF token");
        violation(sop, "SOF", "a SOF token to a low-speed device: it gets keep-alives instead (11.8.4.1)");
        return;
    default:
        not_awaited(pid_name(pid));
        violation(sop, "PID", std::string(pid_name(pid)) + " (" + hex(pid, 1) + "): not a PID a low-speed host sends");
        return;
    }
}

void UsbKbdDevice::on_token(uint64_t sop, uint64_t eop_end, uint8_t pid, uint8_t addr, uint8_t ep) {
    const std::string token = std::string(pid_name(pid)) + " token to address " + std::to_string(addr) + " endpoint " +
                              std::to_string(ep);
    if (state_ == UsbKbdState::kPowered) {
        violation(sop, "state", token + " before the first bus reset after attach: the device answers nothing "
                                        "until it is reset (9.1.1)");
        return;
    }
    if (addr != address_) {
        violation(sop, "address", token + ": the device's address is " + std::to_string(address_));
        return;
    }
    if (recovering_) {
        recovering_ = false;
        if (sop < reset_end_ps_ + cfg_.reset_recovery_ps) {
            violation(sop, "reset recovery", token + " " + time_text(sop - reset_end_ps_) +
                                                 " after the reset ended: TRSTRCY is " +
                                                 time_text(cfg_.reset_recovery_ps) + " (9.2.6.2)");
        }
    }
    if (address_recovering_ && address_ != 0) {
        address_recovering_ = false;
        if (sop < address_set_ps_ + cfg_.set_address_recovery_ps) {
            violation(sop, "set address recovery", token + " " + time_text(sop - address_set_ps_) +
                                                       " after SET_ADDRESS's status stage: the device has " +
                                                       time_text(cfg_.set_address_recovery_ps) + " (9.2.6.3)");
        }
    }
    const uint8_t last_ep = cfg_.two_interfaces ? 2 : 1;
    if (ep > last_ep || ((pid == kSetup || pid == kOut) && ep != 0)) {
        violation(sop, "endpoint", token + ": the device has endpoint 0 (control) and " +
                                       (cfg_.two_interfaces ? "1, 2" : "1") + " (interrupt IN)");
        return;
    }
    if (pid == kSetup || pid == kOut) {
        if (pid == kSetup) ++counters_.tokens_setup;
        else ++counters_.tokens_out;
        expect_ = pid == kSetup ? Expect::kSetupData : Expect::kOutData;
        expect_deadline_ = eop_end + bits_ps(cfg_.timeout_bits);
        expect_met_ = false;
        token_ep_ = ep;
        return;
    }
    ++counters_.tokens_in;
    if (ep == 0) {
        answer_ep0_in(eop_end);
        return;
    }
    if (state_ != UsbKbdState::kConfigured) {
        violation(sop, "state", token + " before SET_CONFIGURATION: only endpoint 0 works in the " +
                                        (state_ == UsbKbdState::kDefault ? "default" : "address") + " state (9.1.1)");
        return;
    }
    if (ep == 2) {
        if (take_silent(eop_end, "NAK on endpoint 2")) return;
        send_handshake(eop_end, kNak, "NAK (endpoint 2: no hot key)");
        return;
    }
    answer_ep1_in(eop_end);
}

bool UsbKbdDevice::take_silent(uint64_t t, const std::string &what) {
    if (fault_silent_ == 0) return false;
    --fault_silent_;
    ++counters_.faults_silent;
    trace(t, "fault: silent instead of " + what);
    return true;
}

bool UsbKbdDevice::take_stall(uint64_t t) {
    if (fault_stall_ == 0) return false;
    --fault_stall_;
    ++counters_.faults_stall;
    send_handshake(t, kStall, "STALL (fault switch)");
    return true;
}

void UsbKbdDevice::answer_ep0_in(uint64_t t) {
    if (take_silent(t, "an answer to IN on endpoint 0")) return;
    if (take_stall(t)) {
        stage_ = Stage::kStalled;
        return;
    }
    switch (stage_) {
    case Stage::kDataIn: {
        if (status_stall_) break;
        const size_t chunk = std::min<size_t>(kMaxPacket, in_data_.size() - in_offset_);
        in_chunk_ = chunk;
        send(t, ep0_toggle_ ? kData1 : kData0,
             std::vector<uint8_t>(in_data_.begin() + static_cast<long>(in_offset_),
                                  in_data_.begin() + static_cast<long>(in_offset_ + chunk)),
             true, SentKind::kControlData, "data stage packet");
        return;
    }
    case Stage::kStatusIn:
        if (status_stall_) break;
        in_chunk_ = 0;
        send(t, kData1, {}, true, SentKind::kControlData, "status stage (zero-length DATA1)");
        return;
    case Stage::kStatusOut:
        violation(t, "control sequence", "IN on endpoint 0 after the data stage ended: the status stage is an OUT "
                                         "with zero-length DATA1 (8.5.3)");
        break;
    case Stage::kDataOut:
        violation(t, "control sequence", "IN on endpoint 0 during an OUT data stage (8.5.3)");
        break;
    case Stage::kIdle:
        violation(t, "control sequence", "IN on endpoint 0 without a SETUP before it (8.5.3)");
        break;
    case Stage::kStalled:
        break;
    }
    stage_ = Stage::kStalled;
    send_handshake(t, kStall, status_stall_ ? "STALL (request error)" : "STALL (endpoint 0)");
    if (status_stall_) ++counters_.requests_stalled;
    status_stall_ = false;
}

void UsbKbdDevice::answer_ep1_in(uint64_t t) {
    ++counters_.polls;
    if (cfg_.check_poll_interval && have_poll_) {
        const uint64_t limit = (cfg_.interval_ms + 1ull) * 1000000000ull;
        if (t - last_poll_ps_ > limit) {
            violation(t, "poll interval", "endpoint 1 polled " + time_text(t - last_poll_ps_) +
                                              " after the previous poll: bInterval is " +
                                              std::to_string(cfg_.interval_ms) + " ms (5.7.4)");
        }
    }
    have_poll_ = true;
    last_poll_ps_ = t;
    if (take_silent(t, "an answer to IN on endpoint 1")) return;
    if (ep1_halted_) {
        send_handshake(t, kStall, "STALL (endpoint 1 halted)");
        return;
    }
    if (take_stall(t)) return;
    if (!ep1_pending_) {
        if (!queue_.empty() && queue_.front().not_before <= t) {
            ep1_report_ = queue_.front().report;
            queue_.pop_front();
            ep1_new_ = true;
        } else if (idle_4ms_ != 0 && t - last_report_ps_ >= idle_4ms_ * 4000000000ull) {
            ep1_report_ = current_;  // the idle time is over: the unchanged report again (HID 7.2.4)
            ep1_new_ = false;
        } else {
            send_handshake(t, kNak, "NAK (no new report)");
            return;
        }
        ep1_data_ = ep1_report_.bytes();
        ep1_pending_ = true;
    } else {
        ++counters_.retransmissions;  // not acknowledged: the same data with the same PID (8.6.2)
    }
    std::vector<uint8_t> data = ep1_data_;
    bool odd_length = false;
    if (fault_length_ > 0) {
        --fault_length_;
        ++counters_.faults_length;
        data.resize(fault_length_bytes_, 0);
        odd_length = true;
    }
    ++counters_.reports_sent;
    send(t, ep1_toggle_ ? kData1 : kData0, data, true, SentKind::kReport,
         std::string(odd_length ? "report of " + std::to_string(data.size()) + " bytes" : "report"));
    if (odd_length) {
        tx_.exempt = true;
        if (data.size() > kMaxPacket) tx_.must_not_ack = true;
    }
}

void UsbKbdDevice::on_ack(uint64_t t) {
    ++counters_.acks_received;
    if (awaiting_must_not_ack_) {
        violation(t, "handshake", "the host acknowledges a data packet it must reject (a bad CRC16, or longer "
                                  "than the endpoint's 8 bytes)");
    }
    if (awaiting_ack_ == SentKind::kReport) {
        ep1_toggle_ ^= 1;  // the sender toggles on the ACK (8.6.2)
        ep1_pending_ = false;
        if (ep1_new_) {
            ++counters_.reports_delivered;
            current_ = ep1_report_;
        } else {
            ++counters_.idle_repeats;
        }
        last_report_ps_ = t;
        return;
    }
    if (awaiting_ack_ != SentKind::kControlData) return;
    if (stage_ == Stage::kDataIn) {
        in_offset_ += in_chunk_;
        ep0_toggle_ ^= 1;
        // The data stage ends with a short packet or when wLength bytes went (8.5.3.2).
        if (in_chunk_ < kMaxPacket || in_offset_ >= setup_.length) stage_ = Stage::kStatusOut;
    } else if (stage_ == Stage::kStatusIn) {
        complete_status(t);
    }
}

void UsbKbdDevice::handshake_timeout(uint64_t t) {
    ++counters_.handshake_timeouts;
    if (awaiting_exempt_) return;  // a packet the host rightly ignores
    violation(t, "handshake", "no ACK within " + num(cfg_.timeout_bits, 0) +
                                  " bit times for the device's good data packet (7.1.19.1, 8.4.6)");
}

void UsbKbdDevice::on_data(uint64_t sop, uint64_t t, uint8_t pid, bool setup, const std::vector<uint8_t> &payload) {
    if (setup) {
        if (pid != kData0) violation(sop, "toggle", "SETUP's data packet is DATA1: it is always DATA0 (8.5.3)");
        if (payload.size() != 8) {
            violation(sop, "packet length", "SETUP's data packet has " + std::to_string(payload.size()) +
                                                " bytes: a request is 8 (9.3)");
            return;
        }
        if (take_silent(t, "ACK of SETUP")) return;  // not ACKed: the request is not taken either
        send_handshake(t, kAck, "ACK (SETUP)");
        on_setup(t, payload);
        return;
    }
    if (take_silent(t, "a handshake of OUT")) return;
    if (take_stall(t)) {
        stage_ = Stage::kStalled;
        return;
    }
    const uint8_t toggle = pid == kData1 ? 1 : 0;
    switch (stage_) {
    case Stage::kDataIn:
    case Stage::kStatusOut:
        if (status_stall_) break;
        // The status stage of a control read (the host may end the data stage early: 8.5.3.2).
        if (!payload.empty()) {
            violation(sop, "control sequence", "the status stage's OUT carries " + std::to_string(payload.size()) +
                                                   " bytes: it is zero-length (8.5.3)");
        }
        if (toggle != 1) violation(sop, "toggle", "the status stage's OUT is DATA0: it is always DATA1 (8.5.3)");
        send_handshake(t, kAck, "ACK (status stage)");
        complete_status(t);
        return;
    case Stage::kDataOut: {
        if (status_stall_) break;
        if (toggle != ep0_toggle_) {
            violation(sop, "toggle", std::string(pid_name(pid)) + " in the OUT data stage, expected " +
                                         (ep0_toggle_ ? "DATA1" : "DATA0") + ": ACKed and ignored (8.6.4)");
            send_handshake(t, kAck, "ACK (repeated data ignored)");
            return;
        }
        out_data_.insert(out_data_.end(), payload.begin(), payload.end());
        ep0_toggle_ ^= 1;
        if (out_data_.size() > setup_.length) {
            violation(sop, "control sequence", "the OUT data stage carries " + std::to_string(out_data_.size()) +
                                                   " bytes for wLength " + std::to_string(setup_.length));
        }
        send_handshake(t, kAck, "ACK (OUT data)");
        if (out_data_.size() >= setup_.length || payload.size() < kMaxPacket) {
            // SET_REPORT is the only request with an OUT data stage here: the LED byte (HID 7.2.2).
            if (!out_data_.empty()) leds_ = out_data_[0];
            ++counters_.led_reports;
            stage_ = Stage::kStatusIn;
        }
        return;
    }
    case Stage::kStatusIn:
        violation(sop, "control sequence", "OUT on endpoint 0 where the status stage is an IN (8.5.3)");
        break;
    case Stage::kIdle:
        violation(sop, "control sequence", "OUT on endpoint 0 without a SETUP before it (8.5.3)");
        break;
    case Stage::kStalled:
        break;
    }
    stage_ = Stage::kStalled;
    if (status_stall_) ++counters_.requests_stalled;
    status_stall_ = false;
    send_handshake(t, kStall, "STALL (endpoint 0)");
}

void UsbKbdDevice::complete_status(uint64_t t) {
    ++counters_.control_transfers;
    stage_ = Stage::kIdle;
    if (on_status_ == Action::kSetAddress) {
        // The new address counts from the end of the status stage (9.4.6).
        address_ = pending_address_;
        state_ = address_ == 0 ? UsbKbdState::kDefault : UsbKbdState::kAddress;
        address_set_ps_ = t;
        address_recovering_ = true;
        trace(t, "address " + std::to_string(address_));
    }
    on_status_ = Action::kNone;
}

// ---- requests (chapter 9, HID 7) ----

void UsbKbdDevice::request_error(uint64_t t, const std::string &why, bool is_violation, const char *rule) {
    status_stall_ = true;  // the data or status stage answers STALL (9.2.7)
    trace(t, "request error: " + why);
    if (is_violation) violation(t, rule, why);
}

void UsbKbdDevice::on_setup(uint64_t t, const std::vector<uint8_t> &b) {
    ++counters_.setups;
    // A SETUP always starts a new control transfer, whatever came before (8.5.3).
    setup_.bm = b[0];
    setup_.request = b[1];
    setup_.value = static_cast<uint16_t>(b[2] | (b[3] << 8));
    setup_.index = static_cast<uint16_t>(b[4] | (b[5] << 8));
    setup_.length = static_cast<uint16_t>(b[6] | (b[7] << 8));
    const Setup &s = setup_;
    in_data_.clear();
    in_offset_ = 0;
    out_data_.clear();
    status_stall_ = false;
    on_status_ = Action::kNone;
    ep0_toggle_ = 1;  // the data stage starts with DATA1
    const bool dir_in = s.bm & 0x80;
    stage_ = s.length == 0 ? Stage::kStatusIn : dir_in ? Stage::kDataIn : Stage::kDataOut;

    char name[96];
    std::snprintf(name, sizeof name, "request %02x %02x wValue %04x wIndex %04x wLength %u", s.bm, s.request, s.value,
                  s.index, s.length);
    const std::string req = name;
    trace(t, req);
    const bool configured = state_ == UsbKbdState::kConfigured;
    const uint8_t interfaces = cfg_.two_interfaces ? 2 : 1;
    auto want_bm = [&](uint8_t bm) {
        if (s.bm == bm) return true;
        request_error(t, req + ": bmRequestType " + hex(bm, 2) + " for this request (9.4)", true);
        return false;
    };
    auto reply = [&](std::vector<uint8_t> data) {
        if (data.size() > s.length) data.resize(s.length);  // never more than wLength (9.3.5)
        in_data_ = std::move(data);
        if (!dir_in && s.length != 0) request_error(t, req + ": a read with an OUT data stage", true);
    };
    auto need_configured = [&]() {
        if (configured) return true;
        request_error(t, req + ": an interface request before SET_CONFIGURATION (9.4)", true, "state");
        return false;
    };
    auto need_interface = [&]() {
        if ((s.index & 0xFF) < interfaces && (s.index >> 8) == 0) return true;
        request_error(t, req + ": no interface " + std::to_string(s.index), true);
        return false;
    };

    const uint8_t type = (s.bm >> 5) & 3;
    if (type == 1) {  // HID class requests to an interface (HID 7.2)
        switch (s.request) {
        case kHidGetReport:
            if (!want_bm(0xA1) || !need_configured() || !need_interface()) return;
            if ((s.value >> 8) != 1) {  // only the input report is there to get
                request_error(t, req + ": GET_REPORT of report type " + std::to_string(s.value >> 8), false);
                return;
            }
            reply(current_.bytes());
            return;
        case kHidGetIdle:
            if (!want_bm(0xA1) || !need_configured() || !need_interface()) return;
            reply({idle_4ms_});
            return;
        case kHidGetProtocol:
            if (!want_bm(0xA1) || !need_configured() || !need_interface()) return;
            reply({protocol_});
            return;
        case kHidSetReport:
            if (!want_bm(0x21) || !need_configured() || !need_interface()) return;
            if ((s.value >> 8) != 2 || s.length == 0) {
                request_error(t, req + ": SET_REPORT takes the output report (the LEDs)", false);
            }
            return;
        case kHidSetIdle:
            if (!want_bm(0x21) || !need_configured() || !need_interface()) return;
            if (s.length != 0) {
                request_error(t, req + ": SET_IDLE has no data stage (HID 7.2.4)", true);
                return;
            }
            if (cfg_.stall_set_idle) {
                request_error(t, req + ": SET_IDLE answered with STALL (stall_set_idle)", false);
                return;
            }
            idle_4ms_ = static_cast<uint8_t>(s.value >> 8);
            last_report_ps_ = t;  // the idle time counts afresh
            return;
        case kHidSetProtocol:
            if (!want_bm(0x21) || !need_configured() || !need_interface()) return;
            if (s.length != 0 || s.value > 1) {
                request_error(t, req + ": SET_PROTOCOL takes 0 (boot) or 1 (report), no data (HID 7.2.6)", true);
                return;
            }
            if (cfg_.stall_set_protocol) {
                request_error(t, req + ": SET_PROTOCOL answered with STALL (stall_set_protocol)", false);
                return;
            }
            protocol_ = static_cast<uint8_t>(s.value);
            return;
        default:
            request_error(t, req + ": not a HID request", cfg_.strict_requests);
            return;
        }
    }
    if (type != 0) {
        request_error(t, req + ": a vendor or reserved request type", cfg_.strict_requests);
        return;
    }
    const uint8_t recipient = s.bm & 0x1F;
    switch (s.request) {
    case kGetStatus: {
        if (!dir_in || s.value != 0 || s.length != 2 || recipient > 2) {
            request_error(t, req + ": GET_STATUS is 80/81/82 with wValue 0, wLength 2 (9.4.5)", true);
            return;
        }
        if (recipient == 0) {
            reply({static_cast<uint8_t>(remote_wakeup_ ? 2 : 0), 0});  // bus powered
        } else if (recipient == 1) {
            if (!need_configured() || !need_interface()) return;
            reply({0, 0});
        } else {
            const uint8_t ep = s.index & 0x7F;
            if (ep == 0) {
                reply({0, 0});
            } else if (configured && (s.index == 0x81 || (s.index == 0x82 && interfaces == 2))) {
                reply({static_cast<uint8_t>(s.index == 0x81 && ep1_halted_ ? 1 : 0), 0});
            } else {
                request_error(t, req + ": no such endpoint", true);
            }
        }
        return;
    }
    case kClearFeature:
    case kSetFeature: {
        const bool set = s.request == kSetFeature;
        if (dir_in || s.length != 0 || recipient > 2) {
            request_error(t, req + ": CLEAR/SET_FEATURE is 00/01/02 with no data (9.4.1, 9.4.9)", true);
            return;
        }
        if (recipient == 0 && s.value == 1) {  // DEVICE_REMOTE_WAKEUP
            remote_wakeup_ = set;
        } else if (recipient == 2 && s.value == 0 &&
                   (s.index == 0x81 || s.index == 0x00 || (s.index == 0x82 && interfaces == 2))) {  // ENDPOINT_HALT
            if (s.index == 0x81) {
                if (!need_configured()) return;
                ep1_halted_ = set;
                if (!set) ep1_toggle_ = 0;  // clearing the halt resets the toggle (9.4.5)
            }
        } else {
            request_error(t, req + ": no such feature (Table 9-6)", true);
        }
        return;
    }
    case kSetAddress:
        if (!want_bm(0x00)) return;
        if (s.value > 127 || s.index != 0 || s.length != 0) {
            request_error(t, req + ": SET_ADDRESS takes an address up to 127, wIndex 0, wLength 0 (9.4.6)", true);
            return;
        }
        if (configured) {
            request_error(t, req + ": SET_ADDRESS in the configured state (9.4.6: not specified)", true, "state");
            return;
        }
        pending_address_ = static_cast<uint8_t>(s.value);
        on_status_ = Action::kSetAddress;
        return;
    case kGetDescriptor: {
        if (s.bm != 0x80 && s.bm != 0x81) {
            request_error(t, req + ": GET_DESCRIPTOR is 80 (or 81 for a HID class descriptor)", true);
            return;
        }
        bool ok = true;
        std::vector<uint8_t> d = get_descriptor(t, s, &ok);
        if (ok) reply(std::move(d));
        return;
    }
    case kGetConfiguration:
        if (!want_bm(0x80)) return;
        if (state_ == UsbKbdState::kDefault) {
            violation(t, "state", req + ": GET_CONFIGURATION in the default state (9.4.2: not specified)");
        }
        reply({configuration_});
        return;
    case kSetConfiguration:
        if (!want_bm(0x00)) return;
        if (state_ == UsbKbdState::kDefault) {
            request_error(t, req + ": SET_CONFIGURATION in the default state (9.4.7: not specified)", true, "state");
            return;
        }
        if (s.value > 1 || s.index != 0 || s.length != 0) {
            request_error(t, req + ": the device has configuration 1 only", true);
            return;
        }
        configuration_ = static_cast<uint8_t>(s.value);
        state_ = configuration_ ? UsbKbdState::kConfigured : UsbKbdState::kAddress;
        ep1_toggle_ = 0;  // (9.4.5) a configuration starts every endpoint's toggle at DATA0
        ep1_halted_ = false;
        ep1_pending_ = false;
        have_poll_ = false;
        last_report_ps_ = t;
        return;
    case kGetInterface:
        if (!want_bm(0x81) || !need_configured() || !need_interface()) return;
        reply({0});
        return;
    case kSetInterface:
        if (!want_bm(0x01) || !need_configured() || !need_interface()) return;
        if (s.value != 0) {
            request_error(t, req + ": interface " + std::to_string(s.index) + " has alternate 0 only", false);
        }
        return;
    case kSetDescriptor:
    case kSynchFrame:
        request_error(t, req + ": not supported (a legal request error)", false);
        return;
    default:
        request_error(t, req + ": not a standard request (Table 9-4)", cfg_.strict_requests);
        return;
    }
}

std::vector<uint8_t> UsbKbdDevice::get_descriptor(uint64_t t, const Setup &s, bool *ok) {
    const uint8_t type = static_cast<uint8_t>(s.value >> 8), index = static_cast<uint8_t>(s.value & 0xFF);
    const std::string req = "GET_DESCRIPTOR type " + hex(type, 2) + " index " + std::to_string(index);
    *ok = false;
    if (s.bm == 0x81) {  // a HID class descriptor of an interface (HID 7.1.1)
        const uint8_t interfaces = cfg_.two_interfaces ? 2 : 1;
        if (state_ != UsbKbdState::kConfigured) {
            // Hosts read the report descriptor after SET_CONFIGURATION; before it there are no interfaces.
            request_error(t, req + ": an interface request before SET_CONFIGURATION (9.4)", true, "state");
            return {};
        }
        if (s.index >= interfaces || index != 0) {
            request_error(t, req + ": interface " + std::to_string(s.index) + " has no such descriptor", true);
            return {};
        }
        if (type == kDescReport) {
            *ok = true;
            return report_desc_[s.index];
        }
        if (type == kDescHid) {
            *ok = true;
            const size_t at = s.index == 0 ? 18 : 18 + 25;  // after configuration, interface (and interface 0's set)
            return std::vector<uint8_t>(cfg_desc_.begin() + static_cast<long>(at),
                                        cfg_desc_.begin() + static_cast<long>(at + 9));
        }
        request_error(t, req + ": not a HID class descriptor (HID 7.1.1)", false);
        return {};
    }
    switch (type) {
    case kDescDevice:
        if (index != 0 || s.index != 0) break;
        *ok = true;
        return dev_desc_;
    case kDescConfig:
        if (index != 0 || s.index != 0) break;
        *ok = true;
        return cfg_desc_;
    case kDescString:
        if (index < strings_.size() && !strings_[index].empty()) {
            if (index != 0 && s.index != 0x0409) {
                request_error(t, req + ": LANGID " + hex(s.index, 4) + " is not in string 0's list", true);
                return {};
            }
            *ok = true;
            return strings_[index];
        }
        request_error(t, req + ": no such string", cfg_.strict_requests);
        return {};
    default:
        break;
    }
    // Other types (device qualifier, interface, endpoint, ...) are a request error a host may meet (9.4.3).
    request_error(t, req + ": no such descriptor", false);
    return {};
}

// ---- transmitter: bits to line levels (stuffing 7.1.9, NRZI 7.1.8, SYNC 7.1.10, EOP) ----

void UsbKbdDevice::send(uint64_t after_eop, uint8_t pid, const std::vector<uint8_t> &payload, bool with_crc,
                        SentKind kind, const std::string &what) {
    std::vector<uint8_t> bytes = {static_cast<uint8_t>(pid | ((~pid & 0xF) << 4))};
    bytes.insert(bytes.end(), payload.begin(), payload.end());
    bool exempt = false, must_not_ack = false;
    uint32_t no_eop_bits = 0;
    const bool data = with_crc;
    if (data && fault_babble_) {
        fault_babble_ = false;
        ++counters_.faults_babble;
        exempt = must_not_ack = true;
        if (fault_babble_kind_ == UsbBabble::kLongPacket) {
            for (uint32_t i = 0; i < fault_babble_amount_; ++i) bytes.push_back(static_cast<uint8_t>(0xA5 ^ i));
        } else {
            no_eop_bits = fault_babble_amount_;
        }
    }
    if (data) {
        uint16_t crc = crc16(bytes.data() + 1, bytes.size() - 1);
        if (fault_crc_ > 0) {
            --fault_crc_;
            ++counters_.faults_crc;
            crc ^= 0x0001;
            exempt = must_not_ack = true;
        }
        bytes.push_back(static_cast<uint8_t>(crc & 0xFF));
        bytes.push_back(static_cast<uint8_t>(crc >> 8));
    }

    Tx tx;
    tx.scheduled = true;
    tx.start_ps = after_eop + bits_ps(cfg_.response_delay_bits);
    tx.kind = kind;
    tx.exempt = exempt;
    tx.must_not_ack = must_not_ack;
    tx.what = what;
    Line level = Line::kJ;  // idle before the SYNC
    int ones = 0;
    auto put = [&](int bit) {
        if (bit == 0) level = level == Line::kJ ? Line::kK : Line::kJ;  // a 0 is a transition
        tx.levels.push_back(level);
        ones = bit ? ones + 1 : 0;
        if (ones == 6) {  // the stuffed 0, also right before the EOP (7.1.9.1)
            level = level == Line::kJ ? Line::kK : Line::kJ;
            tx.levels.push_back(level);
            ones = 0;
        }
    };
    for (int i = 0; i < 7; ++i) put(0);  // SYNC: 0000000 then 1 = KJKJKJKK
    put(1);
    for (uint8_t byte : bytes) {
        for (int b = 0; b < 8; ++b) put((byte >> b) & 1);  // LSB first (8.1)
    }
    for (uint32_t i = 0; i < no_eop_bits; ++i) put(0);  // babble: transitions where the EOP belongs
    tx.levels.push_back(Line::kSE0);
    tx.levels.push_back(Line::kSE0);  // EOP: two bit times of SE0 ...
    tx.eop_index = tx.levels.size();
    tx.levels.push_back(Line::kJ);    // ... then J for one bit time, then the bus is released
    if (data && fault_disconnect_) {
        fault_disconnect_ = false;
        ++counters_.faults_disconnect;
        tx.disconnect_bit = fault_disconnect_bits_;
    }
    tx_ = std::move(tx);
    ++counters_.packets_sent;
    if (data) ++counters_.data_sent;
    trace(tx_.start_ps, "device " + std::string(pid_name(pid)) + " " + what + (bytes.size() > 1 ? ": " : "") +
                            bytes_text(std::vector<uint8_t>(bytes.begin() + 1, bytes.end())));
}

void UsbKbdDevice::send_handshake(uint64_t after_eop, uint8_t pid, const std::string &what) {
    if (pid == kAck) ++counters_.acks_sent;
    if (pid == kNak) ++counters_.naks_sent;
    if (pid == kStall) ++counters_.stalls_sent;
    send(after_eop, pid, {}, false, SentKind::kHandshake, what);
}

UsbDeviceDrive UsbKbdDevice::drive(uint64_t t) {
    UsbDeviceDrive d;
    d.attached = true;
    if (!tx_.scheduled || t < tx_.start_ps) return d;
    tx_.active = true;
    const size_t idx = static_cast<size_t>(static_cast<double>(t - tx_.start_ps) / dev_bit_ps_);
    if (idx >= tx_.disconnect_bit) {
        trace(t, "fault: unplugged in the middle of the " + tx_.what);
        detach(t);
        return {};
    }
    if (idx < tx_.levels.size()) {
        const Line l = tx_.levels[idx];
        d.oe = true;
        d.dp = l == Line::kK;
        d.dm = l == Line::kJ;
        return d;
    }
    tx_done(tx_.start_ps + static_cast<uint64_t>(static_cast<double>(tx_.levels.size()) * dev_bit_ps_));
    return d;
}

void UsbKbdDevice::tx_done(uint64_t t_end) {
    const Tx tx = std::move(tx_);
    tx_ = Tx();
    const uint64_t eop_end = tx.start_ps + static_cast<uint64_t>(static_cast<double>(tx.eop_index) * dev_bit_ps_);
    last_eop_end_ps_ = eop_end;
    have_eop_ = true;
    line_ = Line::kJ;  // the device let go: the pull-up holds J
    line_ps_ = t_end;
    last_activity_ps_ = t_end;
    if (tx.kind == SentKind::kControlData || tx.kind == SentKind::kReport) {
        expect_ = Expect::kHandshake;
        expect_deadline_ = eop_end + bits_ps(cfg_.timeout_bits);
        expect_met_ = false;
        awaiting_ack_ = tx.kind;
        awaiting_exempt_ = tx.exempt;
        awaiting_must_not_ack_ = tx.must_not_ack;
    }
}

// ---- the script ----

void UsbKbdDevice::queue_report(const UsbKbdReport &report, uint64_t not_before_ps) {
    queue_.push_back({report, not_before_ps});
}

void UsbKbdDevice::type_text(const std::string &text, uint64_t not_before_ps) {
    for (const UsbKbdReport &r : reports_for_text(text)) queue_report(r, not_before_ps);
}

std::vector<UsbKbdReport> UsbKbdDevice::reports_for_text(const std::string &text) {
    // HID Usage Tables 1.12, section 10 (Keyboard/Keypad page), US layout.
    constexpr uint8_t kShift = 0x02;  // left Shift (usage 0xE1): modifier bit 1
    static const std::map<char, std::pair<uint8_t, uint8_t>> kPunct = {
        {' ', {0x2C, 0}},       {'\n', {0x28, 0}},      {'\t', {0x2B, 0}},      {'\b', {0x2A, 0}},
        {'\x1b', {0x29, 0}},    {'-', {0x2D, 0}},       {'_', {0x2D, kShift}},  {'=', {0x2E, 0}},
        {'+', {0x2E, kShift}},  {'[', {0x2F, 0}},       {']', {0x30, 0}},       {'}', {0x30, kShift}},
        {'\\', {0x31, 0}},      {'|', {0x31, kShift}},  {';', {0x33, 0}},       {':', {0x33, kShift}},
        {'\'', {0x34, 0}},      {'"', {0x34, kShift}},  {'`', {0x35, 0}},       {'~', {0x35, kShift}},
        {',', {0x36, 0}},       {'<', {0x36, kShift}},  {'.', {0x37, 0}},       {'>', {0x37, kShift}},
        {'/', {0x38, 0}},       {'?', {0x38, kShift}},  {'!', {0x1E, kShift}},  {'@', {0x1F, kShift}},
        {'#', {0x20, kShift}},  {'$', {0x21, kShift}},  {'%', {0x22, kShift}},  {'^', {0x23, kShift}},
        {'&', {0x24, kShift}},  {'*', {0x25, kShift}},  {'(', {0x26, kShift}},  {')', {0x27, kShift}},
    };
    static const std::map<std::string, uint8_t> kNamed = {
        {"UP", 0x52},   {"DOWN", 0x51}, {"LEFT", 0x50}, {"RIGHT", 0x4F}, {"ESC", 0x29},  {"DEL", 0x4C},
        {"HOME", 0x4A}, {"END", 0x4D},  {"PGUP", 0x4B}, {"PGDN", 0x4E},  {"INS", 0x49},  {"ENTER", 0x28},
        {"TAB", 0x2B},  {"BS", 0x2A},   {"F1", 0x3A},   {"F2", 0x3B},    {"F3", 0x3C},   {"F4", 0x3D},
        {"F5", 0x3E},   {"F6", 0x3F},   {"F7", 0x40},   {"F8", 0x41},    {"F9", 0x42},   {"F10", 0x43},
        {"F11", 0x44},  {"F12", 0x45},
    };
    std::vector<UsbKbdReport> out;
    auto tap = [&](uint8_t usage, uint8_t mods) {
        UsbKbdReport press;
        press.modifiers = mods;
        press.keys[0] = usage;
        out.push_back(press);
        out.push_back(UsbKbdReport());  // all keys up
    };
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '{') {
            if (i + 1 < text.size() && text[i + 1] == '{') {
                tap(0x2F, kShift);
                ++i;
                continue;
            }
            const size_t close = text.find('}', i);
            const auto it = close == std::string::npos ? kNamed.end() : kNamed.find(text.substr(i + 1, close - i - 1));
            if (it == kNamed.end()) {
                throw std::invalid_argument("reports_for_text: unknown key name at " + text.substr(i));
            }
            tap(it->second, 0);
            i = close;
        } else if (c >= 'a' && c <= 'z') {
            tap(static_cast<uint8_t>(0x04 + (c - 'a')), 0);
        } else if (c >= 'A' && c <= 'Z') {
            tap(static_cast<uint8_t>(0x04 + (c - 'A')), kShift);
        } else if (c >= '1' && c <= '9') {
            tap(static_cast<uint8_t>(0x1E + (c - '1')), 0);
        } else if (c == '0') {
            tap(0x27, 0);
        } else {
            const auto it = kPunct.find(c);
            if (it == kPunct.end()) {
                throw std::invalid_argument(std::string("reports_for_text: no key for character ") +
                                            hex(static_cast<uint8_t>(c), 2));
            }
            tap(it->second.first, it->second.second);
        }
    }
    return out;
}
