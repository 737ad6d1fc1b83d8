// cpu_profile.h — socsim's --profile: where the CPU's clocks go, instruction by instruction.
//
// Every retired instruction is charged the clocks since the one before it retired: its own clock
// and every clock the pipeline waited for it (a cache refill, a store on the bus, a load's result,
// the custom-function unit) or ran empty before it (an instruction-cache refill of its fetch, a
// mispredicted branch's bubbles: those land on the first instruction after the wait). So the
// charges of a span of execution sum to its clocks exactly, and a hot loop's waits stay on its own
// instructions. Cache-line refills started on either bus go to the next instruction to retire too:
// a data refill's is the load that missed (it retires once the line is in), an instruction
// refill's the instruction it fetched, or one soon after it.
//
// Frames are the firmware's own: from one retirement of the frame mark's address (scene_update's
// entry, as make profile-fw) to the next. Frame 0 (warm-up) and the frame cut short by the exit
// are left out, as profile-fw leaves them out; write() gives the sum over the frames between.
#ifndef SOCSIM_CPU_PROFILE_H
#define SOCSIM_CPU_PROFILE_H

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <map>
#include <unordered_map>

class CpuProfile {
public:
    explicit CpuProfile(uint32_t frame_mark) : mark_(frame_mark) {}

    // An instruction at pc retired in clock `cycle` (a count that only grows); instret() reads the
    // core's own retired-instruction counter (minstret), asked at frame marks only.
    template <class Instret>
    void on_retire(uint32_t pc, uint64_t cycle, Instret instret)
    {
        if (pc == mark_) {
            marks_++;
            if (marks_ == 2) {  // frame 1, the first kept, starts
                first_cycle_ = cycle;
                first_instret_ = instret();
            }
            if (marks_ >= 3) {  // frame marks_ - 2 has just ended; frame 0 is not kept
                end_cycle_ = cycle;
                end_instret_ = instret();
                for (const auto &kv : frame_) {
                    Count &t = total_[kv.first];
                    t.cycles += kv.second.cycles;
                    t.instructions += kv.second.instructions;
                    t.d_refills += kv.second.d_refills;
                    t.i_refills += kv.second.i_refills;
                }
                frames_++;
            }
            frame_.clear();
        }
        Count &c = frame_[pc];
        c.cycles += started_ ? cycle - last_cycle_ : 1u;
        c.instructions++;
        c.d_refills += d_pending_;
        c.i_refills += i_pending_;
        d_pending_ = i_pending_ = 0;
        last_cycle_ = cycle;
        started_ = true;
    }
    // A cache-line refill started on the data (ibus false) or the instruction bus.
    void on_refill(bool ibus) { (ibus ? i_pending_ : d_pending_)++; }

    uint32_t frames() const { return frames_; }

    // "frames N", "mark 0x...", "span_cycles C" and "span_instret I" (the clocks and minstret's
    // count from the first kept frame's start to the last one's end: what the lines below sum to,
    // counted another way), then one line per address that retired in the kept frames:
    // "pc cycles instructions d_refills i_refills" (address in hex, counts summed over the frames),
    // in address order.
    bool write(const char *path) const
    {
        FILE *f = std::fopen(path, "w");
        if (f == nullptr) {
            return false;
        }
        std::fprintf(f, "frames %u\nmark 0x%08" PRIx32 "\nspan_cycles %" PRIu64 "\nspan_instret %" PRIu64 "\n", frames_,
                     mark_, end_cycle_ - first_cycle_, end_instret_ - first_instret_);
        const std::map<uint32_t, Count> sorted(total_.begin(), total_.end());
        for (const auto &kv : sorted) {
            std::fprintf(f, "%08" PRIx32 " %" PRIu64 " %" PRIu64 " %" PRIu64 " %" PRIu64 "\n", kv.first, kv.second.cycles,
                         kv.second.instructions, kv.second.d_refills, kv.second.i_refills);
        }
        return std::fclose(f) == 0;
    }

private:
    struct Count {
        uint64_t cycles = 0, instructions = 0, d_refills = 0, i_refills = 0;
    };
    uint32_t mark_;
    uint32_t marks_ = 0;   // retirements of the mark so far
    uint32_t frames_ = 0;  // frames summed into total_
    bool started_ = false;
    uint64_t last_cycle_ = 0;
    uint64_t first_cycle_ = 0, first_instret_ = 0, end_cycle_ = 0, end_instret_ = 0;
    uint32_t d_pending_ = 0, i_pending_ = 0;  // refills not yet charged
    std::unordered_map<uint32_t, Count> frame_, total_;
};

#endif  // SOCSIM_CPU_PROFILE_H
