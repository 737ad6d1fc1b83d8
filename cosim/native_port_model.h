// native_port_model: a memory behind a LiteDRAM native user port, as the controller behaves at that
// port — for the GPU's frames in external memory (FRAME_DRAM) in gpusim, without the controller.
//
// Written from LiteDRAM's port protocol (litedram/common.py LiteDRAMNativePort and its crossbar, as
// docs/sdram.md describes them), sharing nothing with the RTL that drives it (gpu_frame_dram):
//   - cmd: valid/ready; we and a native word address (32-bit words, Word: the half-rate PHY's
//     port, 4 pixels a word, the lowest-addressed byte in bits 7:0). The model takes a
//     command when cmd_ready is high, which it decides a clock ahead, at random when throttled
//     and never while WRITE_DEPTH writes wait for their data.
//   - wdata: valid/ready; each accepted write's data is taken in command order, on a clock with
//     wdata_ready (never before the clock after its command was taken), with WORD_BYTES byte
//     enables (bit i: bits [8i +: 8]).
//   - rdata: no ready (LiteDRAM cannot wait); each accepted read's word comes back in command order,
//     READ_LATENCY clocks after its command at the earliest, and never before every write accepted
//     before it has had its data taken (one port's commands stay in order).
// Outside [base, base + words) an access is an error: the first is recorded and the run fails.
// Each clock: drive() before the clock's low-phase eval (the outputs for this clock), sample()
// after it (the transfers of this clock, from the DUT's outputs), edge() after the rising edge.
#ifndef NATIVE_PORT_MODEL_H
#define NATIVE_PORT_MODEL_H

#include <cstdint>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include "rng.h"

class NativePortModel {
public:
    using Word = uint32_t;                        // a native word: gpu_top's MEM_DW (default 32)
    static constexpr unsigned WORD_BYTES = sizeof(Word);
    // Command to its read data, at the least: LiteDRAM's HalfRateGENSDRPHY at CL 2, row open, as
    // measured on the controller (tests/sdram/litedram.sh: the command sent in a request's first
    // clock, the first beat back in its 6th, 6.37 on average with the refreshes).
    static constexpr unsigned READ_LATENCY = 5;
    static constexpr unsigned WRITE_DEPTH = 8;   // writes accepted and waiting for their data

    NativePortModel(uint32_t base, uint32_t words) : base_(base), mem_(words, 0) {}

    // Refuse commands and write data on `percent` of the clocks (a controller busy with others).
    void throttle(unsigned percent, uint64_t seed)
    {
        throttle_ = percent;
        rng_ = Rng{seed};
    }
    // Refuse every command from clock `from` for `clocks` clocks (a memory that stops answering).
    void stall(uint64_t from, uint64_t clocks)
    {
        stall_from_ = from;
        stall_until_ = from + clocks;
    }

    // The outputs for this clock.
    struct Out {
        bool cmd_ready, wdata_ready, rdata_valid;
        Word rdata;
    };
    Out drive() const { return out_; }

    // The DUT's outputs in this clock's low phase: what moves on the coming edge.
    void sample(bool cmd_valid, bool cmd_we, uint32_t cmd_addr, bool wdata_valid, Word wdata,
                unsigned wdata_we)
    {
        cmd_fire_ = cmd_valid && out_.cmd_ready;
        cmd_we_ = cmd_we;
        cmd_addr_ = cmd_addr;
        wdata_fire_ = wdata_valid && out_.wdata_ready;
        wdata_ = wdata;
        wdata_we_ = wdata_we;
    }

    // After the rising edge: apply this clock's transfers, decide the next clock's outputs.
    void edge()
    {
        if (out_.rdata_valid) {
            reads_.pop_front();
            words_read_++;
        }
        if (wdata_fire_) {
            const Cmd w = writes_.front();
            writes_.pop_front();
            if (Word *cell = at(w.addr)) {
                for (unsigned i = 0; i < WORD_BYTES; i++) {
                    if (wdata_we_ & (1u << i)) {
                        const Word byte = Word{0xFF} << (8 * i);
                        *cell = static_cast<Word>((*cell & ~byte) | (wdata_ & byte));
                    }
                }
            }
            words_written_++;
        }
        if (cmd_fire_) {
            const Cmd c{cmd_addr_, seq_++, clock_};
            (cmd_we_ ? writes_ : reads_).push_back(c);
            commands_++;
        }
        clock_++;
        // The next clock's outputs.
        const bool stalled = clock_ >= stall_from_ && clock_ < stall_until_;
        out_.cmd_ready = !stalled && writes_.size() < WRITE_DEPTH && open();
        out_.wdata_ready = !writes_.empty() && writes_.front().taken < clock_ && open();
        out_.rdata_valid = false;
        if (!reads_.empty()) {
            const Cmd &r = reads_.front();
            const bool writes_before = !writes_.empty() && writes_.front().seq < r.seq;
            if (clock_ >= r.taken + READ_LATENCY && !writes_before) {
                const Word *cell = at(r.addr);
                out_.rdata_valid = true;
                out_.rdata = cell ? *cell : 0;
            }
        }
    }

    // The memory, native word `addr` (absolute): nullptr outside the model's range.
    const Word *word(uint32_t addr) const
    {
        return addr >= base_ && addr - base_ < mem_.size() ? &mem_[addr - base_] : nullptr;
    }
    const std::string &error() const { return error_; }
    uint64_t commands() const { return commands_; }
    uint64_t words_read() const { return words_read_; }
    uint64_t words_written() const { return words_written_; }

private:
    struct Cmd {
        uint32_t addr;
        uint64_t seq;
        uint64_t taken;  // the clock the command was taken in
    };

    bool open() { return throttle_ == 0 || rng_.below(100) >= throttle_; }
    Word *at(uint32_t addr)
    {
        if (addr >= base_ && addr - base_ < mem_.size()) {
            return &mem_[addr - base_];
        }
        if (error_.empty()) {
            char text[96];
            std::snprintf(text, sizeof text, "native port: word 0x%x outside the frames [0x%x, 0x%zx)",
                          addr, base_, base_ + mem_.size());
            error_ = text;
        }
        return nullptr;
    }

    uint32_t base_;
    std::vector<Word> mem_;
    std::deque<Cmd> writes_, reads_;
    Out out_{false, false, false, 0};
    bool cmd_fire_ = false, cmd_we_ = false, wdata_fire_ = false;
    uint32_t cmd_addr_ = 0;
    Word wdata_ = 0;
    unsigned wdata_we_ = 0;
    uint64_t seq_ = 0, clock_ = 0, stall_from_ = 0, stall_until_ = 0;
    uint64_t commands_ = 0, words_read_ = 0, words_written_ = 0;
    unsigned throttle_ = 0;
    Rng rng_{1};
    std::string error_;
};

#endif
