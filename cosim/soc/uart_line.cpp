// uart_line: see uart_line.h.
#include "uart_line.h"

bool UartLineDecoder::sample(int level, uint8_t *byte)
{
    switch (state_) {
    case Idle:
        if (level == 0) {
            state_ = Start;
            wait_ = cpb_ / 2;  // to the middle of the start bit
        }
        return false;
    case Start:
        if (--wait_ > 0) {
            return false;
        }
        if (level != 0) {  // a glitch, not a start bit
            state_ = Idle;
            return false;
        }
        state_ = Data;
        bit_ = 0;
        shift_ = 0;
        wait_ = cpb_;
        return false;
    case Data:
        if (--wait_ > 0) {
            return false;
        }
        shift_ = static_cast<uint8_t>(shift_ | ((level & 1) << bit_));
        wait_ = cpb_;
        if (++bit_ == 8) {
            state_ = Stop;
        }
        return false;
    case Stop:
        if (--wait_ > 0) {
            return false;
        }
        state_ = Idle;
        if (level == 0) {
            framing_errors_++;
            return false;
        }
        *byte = shift_;
        return true;
    }
    return false;
}

int UartLineSender::tick()
{
    if (bit_ < 0) {
        if (queue_.empty()) {
            return 1;
        }
        frame_ = queue_.front();
        queue_.pop_front();
        bit_ = 0;
        left_ = cpb_;
    }
    const int level = (frame_ >> bit_) & 1;
    if (--left_ == 0) {
        left_ = cpb_;
        if (++bit_ == 10) {
            bit_ = -1;
            sent_++;
        }
    }
    return level;
}
