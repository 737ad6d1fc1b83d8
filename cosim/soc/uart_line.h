// uart_line: a UART line at a fixed number of clocks per bit, 8N1, as the harness sees the SoC's
// pins: UartLineDecoder turns samples of the SoC's uart_tx into bytes, UartLineSender turns queued
// bytes into levels for its uart_rx. One call per system clock; nothing else in them knows about
// clocks, so both are plain data and host-testable.
//
// Decoder: idle high; a low level starts a byte; the start bit is checked at its middle (a glitch
// shorter than half a bit is ignored), then each data bit (LSB first) and the stop bit are sampled
// at their middles. A low stop bit is a framing error: the byte is dropped and counted.
// Sender: while frames are queued, a start bit, eight data bits LSB first and one stop bit, each
// clocks_per_bit clocks; the line is high (idle) otherwise. queue_bad_stop() sends a frame whose stop
// bit is low, for testing a receiver's framing-error path.
#ifndef UART_LINE_H
#define UART_LINE_H

#include <cstdint>
#include <deque>
#include <string>

class UartLineDecoder {
public:
    explicit UartLineDecoder(uint32_t clocks_per_bit) : cpb_(clocks_per_bit) {}
    // One sample of the line (0 or 1). True when a byte completed at this sample (in *byte).
    bool sample(int level, uint8_t *byte);
    uint32_t framing_errors() const { return framing_errors_; }
    bool idle() const { return state_ == Idle; }

private:
    enum State { Idle, Start, Data, Stop };
    uint32_t cpb_;
    State state_ = Idle;
    uint32_t wait_ = 0;   // samples until the next bit's middle
    int bit_ = 0;
    uint8_t shift_ = 0;
    uint32_t framing_errors_ = 0;
};

class UartLineSender {
public:
    explicit UartLineSender(uint32_t clocks_per_bit) : cpb_(clocks_per_bit) {}
    void queue(const std::string &bytes)
    {
        for (const char c : bytes) {
            queue_.push_back(frame(static_cast<uint8_t>(c), true));
        }
    }
    void queue_bad_stop(uint8_t byte) { queue_.push_back(frame(byte, false)); }
    // The line's level for the next clock.
    int tick();
    bool busy() const { return bit_ >= 0 || !queue_.empty(); }  // a byte on the line or waiting
    size_t queued() const { return queue_.size(); }             // bytes waiting, not yet on the line
    uint64_t bytes_sent() const { return sent_; }

private:
    // The 10 bits on the line, first in bit 0: start (0), data LSB first, stop.
    static uint16_t frame(uint8_t byte, bool stop)
    {
        return static_cast<uint16_t>((stop ? 1u << 9 : 0u) | (static_cast<uint32_t>(byte) << 1));
    }
    uint32_t cpb_;
    std::deque<uint16_t> queue_;  // frames
    int bit_ = -1;        // -1 idle; 0 start bit; 1..8 data bits; 9 stop bit
    uint32_t left_ = 0;   // clocks left in the current bit
    uint16_t frame_ = 0;
    uint64_t sent_ = 0;
};

#endif
