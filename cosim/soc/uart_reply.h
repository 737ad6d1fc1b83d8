// uart_reply: socsim's `--reply PROMPT=TEXT`, a scripted answer on uart_rx to a prompt the firmware
// prints, for programs that test the SoC's receiver (tests/soc/smoke.c): each time the bytes
// decoded from uart_tx end with PROMPT, TEXT is queued on the sender. In the whole option, \n is a
// newline and \f a frame whose stop bit is low (the receiver's framing-error path); it is split at
// the first '=' after that. Plain data, no clocks: bytes in, frames queued on a UartLineSender.
#ifndef UART_REPLY_H
#define UART_REPLY_H

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "uart_line.h"

class UartReplies {
public:
    // Adds one PROMPT=TEXT; false when there is no '=' or the prompt is empty (it could never be seen).
    bool add(const std::string &spec)
    {
        const std::string s = unescape(spec);
        const size_t eq = s.find('=');
        if (eq == std::string::npos || eq == 0) {
            return false;
        }
        replies_.emplace_back(s.substr(0, eq), s.substr(eq + 1));
        longest_ = std::max(longest_, eq);
        return true;
    }

    // One byte decoded from uart_tx, '\r' included (the prompt is matched on the bytes as sent).
    void byte(uint8_t b, UartLineSender *tx)
    {
        if (replies_.empty()) {
            return;
        }
        tail_.push_back(static_cast<char>(b));
        if (tail_.size() > longest_) {
            tail_.erase(0, tail_.size() - longest_);   // only the last bytes can end a prompt
        }
        for (const auto &r : replies_) {
            const std::string &prompt = r.first;
            if (tail_.size() < prompt.size() ||
                tail_.compare(tail_.size() - prompt.size(), prompt.size(), prompt) != 0) {
                continue;
            }
            sent_++;
            for (const char c : r.second) {
                if (c == '\f') {
                    tx->queue_bad_stop(0x55);
                } else {
                    tx->queue(std::string(1, c));
                }
            }
        }
    }

    uint32_t sent() const { return sent_; }   // replies queued so far

private:
    static std::string unescape(const std::string &s)
    {
        std::string out;
        for (size_t i = 0; i < s.size(); i++) {
            if (s[i] == '\\' && i + 1 < s.size() && (s[i + 1] == 'n' || s[i + 1] == 'f')) {
                out += s[i + 1] == 'n' ? '\n' : '\f';
                i++;
            } else {
                out += s[i];
            }
        }
        return out;
    }

    std::vector<std::pair<std::string, std::string>> replies_;  // (prompt, text)
    size_t longest_ = 0;   // the longest prompt's length
    std::string tail_;     // the last bytes received, at most longest_
    uint32_t sent_ = 0;
};

#endif
