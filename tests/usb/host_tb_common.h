// host_tb_common.h: what the USB host's benches (tests/usb/host_tb.cpp, tests/usb/regs_tb.cpp) share:
// the CHECK counter, the host's states (usb_ls_host's state output; the contract's USB STATUS.STATE),
// the system clock, and the key events a sequence of boot reports implies — the expectation the
// benches hold usb_hid_keys' output to, written here from HID 1.11 Appendix B.1, not from the RTL.
#ifndef HOST_TB_COMMON_H
#define HOST_TB_COMMON_H

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "usb_kbd_device.h"

#ifndef TB_NAME
#error "define TB_NAME (the bench's name, for its messages) before including host_tb_common.h"
#endif

static long failures = 0, checks = 0;
static bool verbose = false;
#define CHECK(cond, ...)                                                    \
    do {                                                                    \
        checks++;                                                           \
        if (!(cond)) {                                                      \
            failures++;                                                     \
            std::printf(TB_NAME ": FAIL %s:%d: ", __FILE__, __LINE__);      \
            std::printf(__VA_ARGS__);                                       \
            std::printf("\n");                                              \
        }                                                                   \
    } while (0)

enum { S_DETACHED = 0, S_ATTACHED, S_RESETTING, S_ENUM, S_RUNNING, S_NOKBD, S_BABBLE };
static const uint64_t kClkPs = 20000;  // 50 MHz

struct Event {
    bool press;
    uint8_t usage;
    bool operator==(const Event &o) const { return press == o.press && usage == o.usage; }
};

// The events a boot report implies after the previous one (usb_hid_keys' order: releases of the
// modifier bits, of the old keys in slot order, then presses of the modifier bits, of the new keys).
static inline void diff(const UsbKbdReport &o, const UsbKbdReport &n, std::vector<Event> *out) {
    auto in = [](uint8_t k, const UsbKbdReport &r) {
        for (uint8_t x : r.keys)
            if (x == k) return true;
        return false;
    };
    for (int b = 0; b < 8; ++b)
        if ((o.modifiers >> b & 1) && !(n.modifiers >> b & 1)) out->push_back({false, uint8_t(0xE0 + b)});
    for (uint8_t k : o.keys)
        if (k >= 4 && !in(k, n)) out->push_back({false, k});
    for (int b = 0; b < 8; ++b)
        if (!(o.modifiers >> b & 1) && (n.modifiers >> b & 1)) out->push_back({true, uint8_t(0xE0 + b)});
    for (uint8_t k : n.keys)
        if (k >= 4 && !in(k, o)) out->push_back({true, k});
}

// The events typed text implies: the model's reports for it (UsbKbdDevice::reports_for_text), each
// against the one before.
static inline std::vector<Event> expected_for(const std::string &text) {
    std::vector<Event> ev;
    UsbKbdReport prev;
    for (const UsbKbdReport &r : UsbKbdDevice::reports_for_text(text)) {
        diff(prev, r, &ev);
        prev = r;
    }
    return ev;
}

#endif
