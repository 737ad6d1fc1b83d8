// UsbKbdDevice: a USB 1.1 low-speed HID boot keyboard at the bus's pins (D+, D-), for the simulators
// of the SoC's own USB host (issue #28): socsim gives it the host's drive every system clock, the
// model answers as a keyboard would and checks everything the host sends against the specifications.
// C++17, no Verilator dependency. It shares no code with the host RTL (soc_rtl/usb/): its
// NRZI, bit stuffing, CRC5/CRC16 and packet layer are its own, written from the specifications.
//
// Sources. Section and table numbers are the USB 2.0 specification's (USB 2.0 keeps USB 1.1's
// low-speed rules and adds the tables the limits below come from; the USB 1.1 text itself was not
// at hand), the HID 1.11 class definition's and the HID Usage Tables 1.12':
//   USB 2.0 7.1.5.1    speed identification: a low-speed device pulls D- up (1.5 kOhm), the host pulls
//                      both lines down (15 kOhm); nobody driving = J (D- high) attached, SE0 detached
//   USB 2.0 Table 7-2  line states: J/K (low speed: J = D- high, K = D+ high), SE0, SOP, EOP, reset
//   USB 2.0 7.1.7.5    reset: SE0 for more than TDETRST = 2.5 us is a reset; the host drives it for at
//                      least TDRST = 10 ms
//   USB 2.0 7.1.7.6    suspend: a device that sees a constant idle bus for more than 3.0 ms suspends
//   USB 2.0 11.8.4.1   low-speed keep-alive: a low-speed EOP in every frame (in place of the SOF)
//   USB 2.0 7.1.8/9/10 NRZI (a 0 is a transition), bit stuffing (a 0 after six 1s, also right before
//                      EOP; the SYNC's last 1 counts), SYNC = KJKJKJKK
//   USB 2.0 7.1.11     data rate: low-speed functions 1.5 Mb/s +-1.5 % (TLDRATE); hosts and hubs +-0.05 %
//                      (500 ppm) at any speed (TLDRATHS)
//   USB 2.0 Table 7-10 low-speed source: TDDJ1 +-25 ns (to the next transition) and TDDJ2 +-14 ns (paired
//                      transitions) for a downstream (host) port; TLDEOP -40..+100 ns (last data
//                      transition to SE0); TLEOPT 1.25..1.50 us (the SE0 of a source's EOP); TLEOPR
//                      670 ns (a receiver takes a longer SE0 as EOP)
//   USB 2.0 Table 7-9  TFRAME = 1.000 ms +-0.0005 ms (the keep-alive follows the frame)
//   USB 2.0 7.1.18.1   inter-packet delay >= 2 bit times (TIPD); a device answers within 6.5 bit times
//                      (TRSPIPD1)
//   USB 2.0 7.1.19.1   a waiting host or device times out after 16 (at most 18) bit times
//   USB 2.0 Table 7-14 TATTDB 100 ms attach debounce, TRSTRCY 10 ms reset recovery
//   USB 2.0 8.3-8.6    PIDs and check nibble (Table 8-1), token/data/handshake packets, CRC5
//                      (x^5+x^2+1) and CRC16 (x^16+x^15+x^2+1), control transfers (8.5.3), data toggle
//                      (8.6)
//   USB 2.0 9.1.1      device states; 9.2.6.3 SetAddress recovery 2 ms; 9.3/9.4 requests (Table 9-3..9-6);
//                      9.6 descriptors
//   HID 1.11 4.2/4.3   boot interface subclass 1, protocol 1 (keyboard); 6.2.1 HID descriptor; 7.1.1 class
//                      descriptors by GET_DESCRIPTOR; 7.2.1-7.2.6 GET/SET_REPORT, GET/SET_IDLE (default
//                      idle rate of a keyboard: 500 ms), GET/SET_PROTOCOL (report protocol after reset);
//                      Appendix B.1 the boot keyboard report (modifier byte, reserved, 6 key usages)
//   HID Usage Tables 1.12 section 10: the Keyboard/Keypad page (0x07)
// Where each limit was read, and which are not re-verified, is in docs/usb.md ("The keyboard model").
//
// The keyboard: a Dell USB Keyboard (VID 413c, PID 2010), a common low-speed keyboard, as `lsusb -v`
// shows it in raspberrypi/linux issue #273: device descriptor (bcdUSB 1.10, bMaxPacketSize0 8,
// bcdDevice 2.00, iManufacturer 1 "Dell", iProduct 3 "Dell USB Keyboard"), configuration (wTotalLength
// 59, 2 interfaces, iConfiguration 3, bmAttributes 0xa0, 50 mA) and interface 0 (HID, boot subclass,
// keyboard protocol, iInterface 3). The dump does not show the rest; those fields are marked ASSUMED in
// usb_kbd_device.cpp: HID descriptors (bcdHID 1.10), endpoint 0x81 (interrupt, 8 bytes, bInterval 10),
// interface 1 (HID, no subclass, endpoint 0x82, a consumer-control report that the model never sends),
// LANGID 0x0409. Interface 0's report descriptor is HID 1.11 Appendix B.1's.
//
// Calling convention. step(t_ps, host) says what the host drives from t_ps on (its output enable and
// the D+ and D- levels) and returns what the device drives from t_ps until the next call: its output
// enable, D+, D-, and whether its pull-up is connected (attached). Times never decrease (a decrease
// throws std::invalid_argument). socsim calls it once per system clock (50 MHz by default, any period);
// a bench may call it less often as long as it calls at every change of the host's drive and, while
// busy() is true, at least once per clock (the device's edges fall on calls, up to a period late: 20 ns
// at 50 MHz, well inside the receive jitter a host must take, +-152 ns to the next transition).
// The receiver samples each host bit in its middle and realigns on every transition, as a DPLL does:
// the time between two transitions, in bit times rounded, is the number of bits they hold.
// bus(host, device) resolves the lines for the host side: the host's levels when it drives (both
// driving is bus contention, reported by the model), else the device's, else J with the pull-up
// attached and SE0 without. The device answers a host packet response_delay_bits after the host's EOP
// (SE0 -> J), sending at the nominal 1.5 Mb/s.
//
// What is checked (each violation names its rule, the names below; its text ends in "[rule]"):
//   bus contention    the host drives while the device drives
//   SE1               the host drives D+ and D- high together (no such state, Table 7-2)
//   bit rate          a host packet's bit period off 1.5 Mb/s by more than host_rate_ppm, measured from its
//                     first to its last transition with rate_slack_ps allowed for their jitter (so a token
//                     resolves the rate to about 1,200 ppm, a full DATA packet to about 400; the keep-alive
//                     period checks the host's clock to 500 ppm)
//   jitter            no bit period within host_rate_ppm puts every host transition within TDDJ1 of N
//                     periods after the previous one and within TDDJ2 of N periods after the one before
//                     (paired transitions): Table 7-10's "N x TPERIOD +- jitter"
//   SYNC              a host packet not starting KJKJKJKK
//   bit stuffing      seven 1s in a row (no transition for 7 bit times), or no stuffed 0 after six 1s
//                     right before EOP
//   EOP               the SE0 of an EOP (or keep-alive) outside TLEOPT, shorter than TLEOPR inside a
//                     packet, the last transition to SE0 outside TLDEOP, or SE0 followed by K
//   SE0               an SE0 on an idle bus shorter than TLEOPR (neither EOP nor reset)
//   packet length     a packet not of whole bytes, a token not 3 bytes, a handshake not 1, host data
//                     longer than the endpoint's 8 bytes, a SETUP data stage not 8 bytes
//   PID               the check nibble is not the PID's complement, or a PID a low-speed host never
//                     sends (PRE, DATA2, MDATA, NYET, SPLIT, PING, reserved)
//   SOF               a SOF token sent to a low-speed device (it gets keep-alives, 11.8.4.1)
//   CRC5, CRC16       a token's or a data packet's CRC is wrong (the packet is ignored)
//   address           a token to an address that is not the device's
//   endpoint          a token to an endpoint the device does not have, or in the wrong direction
//   state             a token before the first reset after attach; endpoint 1 used before
//                     SET_CONFIGURATION; a request the device's state does not allow
//   request           a malformed request (bmRequestType not the request's, fields out of range, an
//                     unknown request): answered with STALL (strict_requests)
//   control sequence  a control transfer out of order: data or status stage without SETUP, an IN after
//                     the data stage ended, a status stage with data, an OUT where the status is IN
//   toggle            a host DATA PID not the expected one (SETUP data must be DATA0, the status stage
//                     DATA1, an OUT data stage alternates)
//   handshake         no ACK from the host within timeout_bits after a good data packet of the device,
//                     another packet in its place, a NAK/STALL from the host (it only ACKs, 8.4.6), an
//                     ACK with nothing to acknowledge, or an ACK of a packet the host must reject (a bad
//                     CRC16, more than 8 bytes: the fault switches')
//   turnaround        the host starts a packet before the device's answer came (it must wait up to its
//                     time-out), or sends the DATA after a SETUP/OUT token later than timeout_bits
//   inter-packet delay a host packet starting less than TIPD (2 bit times) after the previous EOP
//   suspend           the bus idle (no packet, no keep-alive) for more than 3 ms after the first reset
//                     (the device suspends; allow_suspend makes it legal)
//   keep-alive        two keep-alives not one frame (1 ms +-500 ppm) apart (a root port sends one every
//                     frame; the count restarts after a reset or a suspend)
//   reset             a reset SE0 shorter than TDRST (10 ms)
//   reset recovery    a token less than TRSTRCY (10 ms) after a reset ended
//   attach debounce   a reset less than TATTDB (100 ms) after attach
//   set address recovery  a token to the new address less than 2 ms after SET_ADDRESS's status stage
//   poll interval     endpoint 1 polled less often than bInterval (+1 ms of frame granularity)
//
// The device: attached = pull-up on D-. States (9.1.1): powered (attached, not reset: answers nothing),
// default (address 0), address, configured; suspended on 3 ms of idle bus, woken by any activity.
// Endpoint 0 carries control transfers: GET_STATUS, CLEAR/SET_FEATURE (remote wake-up, endpoint halt),
// SET_ADDRESS (in effect after the status stage), GET_DESCRIPTOR (device, configuration, strings 0, 1,
// 3; HID and report descriptors by interface), GET/SET_CONFIGURATION, GET/SET_INTERFACE (alternate 0);
// HID GET_REPORT, SET_REPORT (the LED byte), GET/SET_IDLE, GET/SET_PROTOCOL. SET_IDLE and SET_PROTOCOL
// can be made to STALL (real keyboards do). Endpoint 1 (interrupt IN, 8 bytes) sends the queued 8-byte
// boot reports, one per poll, toggling DATA0/DATA1 on the host's ACK and resending unacknowledged data
// with the same PID; with nothing new it NAKs, or, with an idle rate set, repeats the last report when
// the idle time is over (HID 7.2.4). Endpoint 2 (interface 1) always NAKs.
//
// Fault switches (for the host's tests; each counts down per use): corrupt the CRC16 of the next N data
// packets; stay silent for the next N answers (the host times out); STALL the next N IN/OUT; detach in
// the middle of the next data packet; babble (a data packet longer than 8 bytes, or one that goes on
// toggling where its EOP belongs); a report of the wrong length. A deliberately broken packet is not
// followed by a "handshake" violation when the host rightly ignores it.
//
// Not modelled: resume signalling by the device (remote wake-up is stored, never used), the
// electrical layer (edge rates, voltages: the lines are 0/1), full speed, the hub's PRE, isochronous
// and bulk. A host's resume K simply wakes a suspended device, like any other activity.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

// What the host drives from a call's time on.
struct UsbHostDrive {
    bool oe = false;  // the host's output enable
    bool dp = false;  // D+ level it drives
    bool dm = false;  // D- level it drives
};

// What the device drives from a call's time until the next.
struct UsbDeviceDrive {
    bool oe = false;        // the device drives D+/D-
    bool dp = false;
    bool dm = false;
    bool attached = false;  // its 1.5 kOhm pull-up on D- is connected
};

// The two lines as the host sees them.
struct UsbLines {
    bool dp = false;
    bool dm = false;
};

// An 8-byte boot keyboard report (HID 1.11 Appendix B.1).
struct UsbKbdReport {
    uint8_t modifiers = 0;  // bit 0 left Ctrl, 1 left Shift, 2 left Alt, 3 left GUI, 4..7 the right ones
    uint8_t reserved = 0;
    uint8_t keys[6] = {0, 0, 0, 0, 0, 0};  // key usages (Keyboard/Keypad page), 0 = none
    bool operator==(const UsbKbdReport &o) const;
    std::vector<uint8_t> bytes() const;  // the 8 bytes as sent
};

enum class UsbBabble : uint8_t {
    kLongPacket,  // the data packet carries `amount` bytes more than 8 (a valid CRC over all of them)
    kNoEop,       // the packet goes on with `amount` bit times of alternating K/J where its EOP belongs
};

struct UsbKbdConfig {
    // The host's timing (checked). Picoseconds unless named otherwise.
    double host_rate_ppm = 500;        // TLDRATHS: +-0.05 % for a host's transmitter (USB 2.0 7.1.11)
    uint64_t rate_slack_ps = 25000;    // allowance over a packet's span for the end transitions' jitter
    uint64_t jitter_next_ps = 25000;   // TDDJ1
    uint64_t jitter_paired_ps = 14000; // TDDJ2
    int64_t eop_skew_min_ps = -40000;  // TLDEOP: last data transition to SE0, against N whole bits
    int64_t eop_skew_max_ps = 100000;
    uint64_t eop_min_ps = 1250000;     // TLEOPT: the SE0 of the host's EOP / keep-alive
    uint64_t eop_max_ps = 1500000;
    uint64_t eop_receive_ps = 670000;  // TLEOPR: a shorter SE0 is no EOP
    uint64_t reset_detect_ps = 2500000;         // TDETRST
    uint64_t reset_min_ps = 10000000000ull;     // TDRST: 10 ms
    uint64_t reset_recovery_ps = 10000000000ull;  // TRSTRCY: 10 ms
    uint64_t attach_debounce_ps = 100000000000ull;  // TATTDB: 100 ms
    uint64_t set_address_recovery_ps = 2000000000ull;  // 9.2.6.3: 2 ms
    uint64_t suspend_idle_ps = 3000000000ull;   // 7.1.7.6: 3 ms
    uint64_t frame_ps = 1000000000ull;          // TFRAME: 1 ms ...
    double frame_ppm = 500;                     // ... +-0.0005 ms
    double min_gap_bits = 2.0;         // TIPD
    double timeout_bits = 16.0;        // 7.1.19.1: how long the device waits for the host's packet
    bool check_keep_alive = true;      // the keep-alive's period
    bool check_poll_interval = true;   // endpoint 1 polled at least every bInterval ms
    bool allow_suspend = false;        // 3 ms of idle bus after the first reset is legal (a host suspending)
    bool strict_requests = true;       // unknown requests are violations (they are STALLed either way)

    // The device.
    double response_delay_bits = 3.0;  // from the host's EOP to the device's SYNC (TRSPIPD1: <= 6.5)
    double device_rate_ppm = 0;        // the device's own bit clock against 1.5 Mb/s (TLDRATE: +-15000)
    bool stall_set_idle = false;       // answer SET_IDLE with STALL, as some keyboards do
    bool stall_set_protocol = false;   // answer SET_PROTOCOL with STALL
    bool two_interfaces = true;        // the Dell's two interfaces (59-byte configuration) or interface 0 only
    uint8_t interval_ms = 10;          // endpoint 1's bInterval (ASSUMED for the Dell)
    uint8_t default_idle_4ms = 125;    // the idle rate after reset, 4 ms units (HID 7.2.4: 500 ms for keyboards)

    bool fail_fast = false;            // the first violation goes to stderr and failed() is true
    bool trace = false;                // every packet to stderr
    uint32_t max_messages = 1000;      // violations kept as text (all are counted)
};

struct UsbKbdViolation {
    uint64_t t_ps;
    std::string rule;  // "CRC5", "jitter", ... (the header's list)
    std::string text;  // the whole message, as errors() has it
};

struct UsbKbdCounters {
    uint64_t attaches = 0, detaches = 0, resets = 0, keep_alives = 0, suspends = 0, resumes = 0;
    uint64_t packets_received = 0;     // host packets decoded (any, good or bad)
    uint64_t tokens_setup = 0, tokens_in = 0, tokens_out = 0;  // good tokens to this device
    uint64_t data_received = 0, acks_received = 0;
    uint64_t packets_sent = 0, data_sent = 0, acks_sent = 0, naks_sent = 0, stalls_sent = 0;
    uint64_t setups = 0;               // SETUP transactions acknowledged
    uint64_t control_transfers = 0;    // status stages completed
    uint64_t requests_stalled = 0;
    uint64_t polls = 0;                // IN tokens to endpoint 1 while configured
    uint64_t reports_sent = 0;         // report data packets sent (retransmissions included)
    uint64_t reports_delivered = 0;    // reports the host acknowledged (each queued report once)
    uint64_t idle_repeats = 0;         // reports repeated because the idle time ran out
    uint64_t retransmissions = 0;      // data packets sent again after no ACK
    uint64_t handshake_timeouts = 0;   // data packets the host did not acknowledge
    uint64_t led_reports = 0;          // SET_REPORT (output) received
    uint64_t faults_crc = 0, faults_silent = 0, faults_stall = 0, faults_babble = 0, faults_length = 0,
             faults_disconnect = 0;    // fault switches used
};

enum class UsbKbdState : uint8_t { kDetached, kPowered, kDefault, kAddress, kConfigured };

class UsbKbdDevice {
public:
    explicit UsbKbdDevice(const UsbKbdConfig &cfg = UsbKbdConfig());

    // Plug in / unplug: the pull-up connects or disconnects from t_ps on (a fresh device each time).
    void attach(uint64_t t_ps);
    void detach(uint64_t t_ps);

    // The host's drive from t_ps on; returns the device's (see the calling convention).
    UsbDeviceDrive step(uint64_t t_ps, const UsbHostDrive &host);
    static UsbLines bus(const UsbHostDrive &host, const UsbDeviceDrive &device);
    bool busy() const { return tx_.scheduled; }  // an answer is scheduled or being sent

    // The keyboard's script: reports go out in order, each at the first poll at or after not_before_ps.
    void queue_report(const UsbKbdReport &report, uint64_t not_before_ps = 0);
    // Press and release reports for text (queue_report each): letters, digits, the US layout's
    // punctuation with Shift where it needs it, '\n' Enter, '\t' Tab, '\b' Backspace, and {UP} {DOWN}
    // {LEFT} {RIGHT} {ESC} {DEL} {HOME} {END} {PGUP} {PGDN} {INS} {F1}..{F12} {ENTER} {TAB} {BS} {{.
    // Throws std::invalid_argument on anything else.
    void type_text(const std::string &text, uint64_t not_before_ps = 0);
    static std::vector<UsbKbdReport> reports_for_text(const std::string &text);
    size_t reports_queued() const { return queue_.size(); }
    const UsbKbdReport &current_report() const { return current_; }  // the last one the host acknowledged

    // Fault switches (see the header).
    void corrupt_crc_next(uint32_t n) { fault_crc_ += n; }
    void no_answer_next(uint32_t n) { fault_silent_ += n; }
    void stall_next(uint32_t n) { fault_stall_ += n; }
    void disconnect_during_next_data(uint32_t after_bits) {
        fault_disconnect_ = true;
        fault_disconnect_bits_ = after_bits;
    }
    void babble_next(UsbBabble kind, uint32_t amount) {
        fault_babble_ = true;
        fault_babble_kind_ = kind;
        fault_babble_amount_ = amount;
    }
    void wrong_length_next(uint32_t n, uint8_t length) {
        fault_length_ += n;
        fault_length_bytes_ = length;
    }
    void set_endpoint_halt(bool halted) { ep1_halted_ = halted; }  // endpoint 1 STALLs until CLEAR_FEATURE

    // Status for the harness.
    UsbKbdState state() const { return state_; }
    bool attached() const { return state_ != UsbKbdState::kDetached; }
    bool configured() const { return state_ == UsbKbdState::kConfigured; }
    bool enumerated() const { return configured(); }
    bool suspended() const { return suspended_; }
    uint8_t address() const { return address_; }
    uint8_t protocol() const { return protocol_; }   // 0 boot, 1 report (HID 7.2.6)
    uint8_t idle_rate() const { return idle_4ms_; }  // 4 ms units, 0 = only on change
    uint8_t leds() const { return leds_; }           // the last SET_REPORT output byte
    bool endpoint_halted() const { return ep1_halted_; }
    const UsbKbdCounters &counters() const { return counters_; }
    std::string stats() const;  // one line

    bool failed() const { return cfg_.fail_fast && error_count_ != 0; }
    const std::vector<std::string> &errors() const { return errors_; }  // "usbkbd: <t>: ... [rule]"
    const std::vector<UsbKbdViolation> &violations() const { return violations_; }
    uint64_t error_count() const { return error_count_; }
    const UsbKbdConfig &config() const { return cfg_; }

    // The descriptors as sent.
    const std::vector<uint8_t> &device_descriptor() const { return dev_desc_; }
    const std::vector<uint8_t> &configuration_descriptor() const { return cfg_desc_; }
    const std::vector<uint8_t> &report_descriptor(int interface) const { return report_desc_[interface ? 1 : 0]; }
    std::vector<uint8_t> string_descriptor(uint8_t index) const;  // empty: no such string

    // The model's own CRCs, exposed for the known-value tests. crc5: `nbits` bits in transmission order
    // (bit 0 first), returns the 5 CRC bits with the first one sent in bit 4 (the white paper's
    // orientation). crc16: over bytes (each LSB first), returns the 16-bit field sent low byte first.
    static uint8_t crc5(uint32_t bits, int nbits);
    static uint16_t crc16(const uint8_t *data, size_t n);
    static uint16_t token_field(uint8_t address, uint8_t endpoint);  // the 16 bits after a token's PID

    static constexpr double kBitPs = 1e12 / 1.5e6;  // 666,666.67 ps: one low-speed bit

private:
    enum class Line : uint8_t { kSE0, kJ, kK, kSE1 };
    enum class Expect : uint8_t { kNothing, kSetupData, kOutData, kHandshake };
    enum class Stage : uint8_t { kIdle, kDataIn, kDataOut, kStatusIn, kStatusOut, kStalled };
    enum class SentKind : uint8_t { kNone, kHandshake, kControlData, kReport, kOther };

    struct Setup {
        uint8_t bm = 0, request = 0;
        uint16_t value = 0, index = 0, length = 0;
    };

    struct Tx {                      // the device's packet on the wire
        bool scheduled = false;      // waiting for start_ps or being sent
        bool active = false;
        uint64_t start_ps = 0;
        std::vector<Line> levels;    // one per bit time, SYNC to the EOP's J
        size_t eop_index = 0;        // the level index where the EOP's J begins
        SentKind kind = SentKind::kNone;
        bool exempt = false;         // a deliberately broken packet: no handshake expected
        bool must_not_ack = false;   // ... and one the host must reject (bad CRC16, longer than 8 bytes)
        uint32_t disconnect_bit = UINT32_MAX;
        std::string what;
    };

    struct Rx {                      // the host's packet being received
        bool active = false;
        bool resume = false;         // begun while suspended: a long K is the host's resume
        uint64_t sop_ps = 0;
        uint64_t last_tr_ps = 0;
        std::vector<uint64_t> tr_ps;   // transition times
        std::vector<uint32_t> tr_bit;  // the raw bit each transition starts
        std::vector<uint8_t> raw;      // NRZI-decoded bits, stuffed
        bool se0 = false;              // in the EOP's SE0
        uint64_t se0_ps = 0;
    };

    // Bits and lines.
    static std::string time_text(uint64_t ps);
    static const char *pid_name(uint8_t pid);
    void violation(uint64_t t, const char *rule, const std::string &what);
    void trace(uint64_t t, const std::string &what) const;
    double bits(uint64_t ps) const { return static_cast<double>(ps) / kBitPs; }
    uint64_t bits_ps(double n) const { return static_cast<uint64_t>(n * kBitPs + 0.5); }

    // Receiver.
    Line host_line(const UsbHostDrive &h) const;
    void rx_line(uint64_t t, Line now);
    void rx_transition(uint64_t t);
    void rx_end_se0(uint64_t t, uint64_t since, Line next);
    void rx_abort();
    void drop_expectation();
    void rx_timers(uint64_t t);
    void rx_packet(uint64_t eop_end);
    void check_timing(const Rx &r);
    void activity(uint64_t t);

    // Bus events.
    void bus_reset(uint64_t t);
    void keep_alive(uint64_t t_start, uint64_t t_end);
    void wake(uint64_t t);

    // Packets.
    void on_sop(uint64_t t, bool was_suspended);
    void on_packet(uint64_t sop, uint64_t eop_end, const std::vector<uint8_t> &bytes);
    void on_token(uint64_t sop, uint64_t eop_end, uint8_t pid, uint8_t addr, uint8_t ep);
    void on_data(uint64_t sop, uint64_t t, uint8_t pid, bool setup, const std::vector<uint8_t> &payload);
    void on_ack(uint64_t t);
    void answer_ep0_in(uint64_t t);
    void answer_ep1_in(uint64_t t);
    void handshake_timeout(uint64_t t);

    // Transmitter.
    void send(uint64_t after_eop, uint8_t pid, const std::vector<uint8_t> &payload, bool with_crc, SentKind kind,
              const std::string &what);
    void send_handshake(uint64_t after_eop, uint8_t pid, const std::string &what);
    bool take_silent(uint64_t t, const std::string &what);
    bool take_stall(uint64_t t);
    UsbDeviceDrive drive(uint64_t t);
    void tx_done(uint64_t t);

    // Control transfers and requests.
    void on_setup(uint64_t t, const std::vector<uint8_t> &b);
    void request_error(uint64_t t, const std::string &why, bool is_violation, const char *rule = "request");
    void complete_status(uint64_t t);
    std::vector<uint8_t> get_descriptor(uint64_t t, const Setup &s, bool *ok);

    void build_descriptors();
    void reset_device_state();

    UsbKbdConfig cfg_;
    double dev_bit_ps_;

    std::vector<uint8_t> dev_desc_, cfg_desc_, report_desc_[2];
    std::vector<std::vector<uint8_t>> strings_;  // by index; empty = none

    // Time and the pins.
    bool started_ = false;
    uint64_t t_ = 0;
    bool contention_ = false;
    bool se1_ = false;

    // Device state.
    UsbKbdState state_ = UsbKbdState::kDetached;
    uint64_t attach_ps_ = 0;
    bool suspended_ = false;
    uint8_t address_ = 0;
    uint8_t pending_address_ = 0;
    bool address_change_pending_ = false;
    uint64_t address_set_ps_ = 0;
    bool address_recovering_ = false;
    uint8_t configuration_ = 0;
    bool remote_wakeup_ = false;
    uint8_t protocol_ = 1;
    uint8_t idle_4ms_ = 125;
    uint8_t leds_ = 0;

    // Line and receiver.
    Line line_ = Line::kJ;
    uint64_t line_ps_ = 0;          // line_ since
    Rx rx_;
    bool reset_active_ = false;
    bool ever_reset_ = false;
    uint64_t reset_end_ps_ = 0;
    bool recovering_ = false;       // in TRSTRCY after a reset
    uint64_t last_activity_ps_ = 0; // the bus last left idle (J) or came back to it
    bool have_keep_alive_ = false;
    uint64_t last_keep_alive_ps_ = 0;
    bool discard_ = false;          // after a receive error: ignore the line until it is idle or EOP
    uint64_t last_eop_end_ps_ = 0;  // the last EOP on the bus (host's or device's): TIPD
    bool have_eop_ = false;

    // Transaction state.
    Expect expect_ = Expect::kNothing;
    uint64_t expect_deadline_ = 0;
    bool expect_met_ = false;       // the awaited packet's SOP came in time
    Expect late_ = Expect::kNothing;  // what timed out last: its late packet is not reported twice
    uint8_t token_ep_ = 0;
    Tx tx_;
    SentKind awaiting_ack_ = SentKind::kNone;  // what the awaited handshake acknowledges
    bool awaiting_exempt_ = false;
    bool awaiting_must_not_ack_ = false;

    // Control pipe.
    Stage stage_ = Stage::kIdle;
    Setup setup_;
    std::vector<uint8_t> in_data_;
    size_t in_offset_ = 0;
    size_t in_chunk_ = 0;           // bytes in the data packet awaiting ACK
    uint8_t ep0_toggle_ = 1;        // the next DATA PID on endpoint 0's data/status stage (1 = DATA1)
    std::vector<uint8_t> out_data_;
    bool status_stall_ = false;
    enum class Action : uint8_t { kNone, kSetAddress } on_status_ = Action::kNone;

    // Endpoint 1.
    bool ep1_halted_ = false;
    uint8_t ep1_toggle_ = 0;
    bool ep1_pending_ = false;      // data sent, not acknowledged
    std::vector<uint8_t> ep1_data_;
    UsbKbdReport ep1_report_;
    bool ep1_new_ = false;          // the pending data is a queued report (counts when delivered)
    uint64_t last_report_ps_ = 0;   // the last report acknowledged (idle rate)
    bool have_poll_ = false;
    uint64_t last_poll_ps_ = 0;
    struct Queued {
        UsbKbdReport report;
        uint64_t not_before;
    };
    std::deque<Queued> queue_;
    UsbKbdReport current_;

    // Faults.
    uint32_t fault_crc_ = 0, fault_silent_ = 0, fault_stall_ = 0, fault_length_ = 0;
    uint8_t fault_length_bytes_ = 8;
    bool fault_disconnect_ = false;
    uint32_t fault_disconnect_bits_ = 0;
    bool fault_babble_ = false;
    UsbBabble fault_babble_kind_ = UsbBabble::kLongPacket;
    uint32_t fault_babble_amount_ = 0;

    std::vector<std::string> errors_;
    std::vector<UsbKbdViolation> violations_;
    uint64_t error_count_ = 0;
    UsbKbdCounters counters_;
};
