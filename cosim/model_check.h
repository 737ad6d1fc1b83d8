// model_check: runs the golden C model beside the RTL on the same bus writes and compares what
// software can observe — every read-only register except the cycle counter, and every pixel of each
// frame the VGA pins show. Any difference is an RTL or model bug.
#ifndef MODEL_CHECK_H
#define MODEL_CHECK_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

extern "C" {
#include "gpu_model.h"
}

class GpuSim;

class ModelCheck {
public:
    // The model is configured like the RTL: span width, lines, depth buffer and capacities as the
    // simulator was built (GpuSim::build_config(), socsim's gpu_build_config()). A configuration
    // the model cannot take as it is ends the program with a message (exit status 2): it would
    // otherwise be checked against another GPU.
    explicit ModelCheck(const gpu_model_config &cfg);
    ~ModelCheck();
    // A write, at once or, after hold_writes(), held until release_writes(): while a frame is on
    // its way to the pins the firmware may already draw (and swap) the next one, so the model's
    // front buffer must stay that frame's until the frame is compared (Harness::take_frame).
    void write(uint32_t offset, uint32_t value)
    {
        if (holding_) {
            held_.emplace_back(offset, value);
        } else {
            gpu_model_write(model_, offset, value);
        }
    }
    void hold_writes() { holding_ = true; }
    void release_writes();  // the held writes, in order; the writes that follow go at once
    bool holds_writes() const { return !held_.empty(); }
    // Compare the read-only registers; returns "" when equal, else a description.
    std::string compare_registers(GpuSim &sim);
    // Compare a captured 640x480 RGB frame with the model's front buffer through its palette.
    std::string compare_frame(const uint8_t *rgb);
    const gpu_model *model() const { return model_; }

private:
    gpu_model *model_;
    std::vector<uint8_t> expected_;
    bool holding_ = false;
    std::vector<std::pair<uint32_t, uint32_t>> held_;  // (offset, value), in the order written
};

// Read-only registers copied back to the firmware after a batch, DONE_SEQ last: the contract's
// list (GPU_READ_ONLY_REGS in gpu_regs.h) in offset order, DONE_SEQ moved to the end.
extern const uint32_t *const kReadOnlyRegs;
extern const int kReadOnlyRegCount;

#endif
