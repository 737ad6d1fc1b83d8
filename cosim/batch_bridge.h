// batch_bridge: the GPU side of the co-simulation — turns the firmware's stores in the GPU's window
// of shared RAM into bus writes of the Verilated GPU, runs it, and writes back what the firmware may
// read. The golden model gets the same writes and is compared after every batch.
//
// Contract, for a window attached with attach() (PLATFORM_GPU_BASE in the shared RAM):
//   - publish_registers() copies the GPU's read-only registers into the window, DONE_SEQ last with a
//     release fence before it (kReadOnlyRegs order), so a firmware that sees the new DONE_SEQ sees
//     every counter of that batch.
//   - pending_doorbell() / pending_reset() say whether the firmware wrote a new DOORBELL tag or a new
//     RESET value since the bridge last forwarded one (acquire loads).
//   - service_batch(tag) replays every window word that changed since the last batch into the RTL
//     (and the model), DOORBELL last; runs the GPU until DONE_SEQ shows the tag; compares the
//     registers with the model; when FRAME_COUNT moved, the frame the new front buffer shows is
//     captured from the VGA pins and handed to the harness (Harness::take_frame: compared with the
//     model, written as FRAMES_DIR/NNNN.png, shown, one "cosim: frame" line); then it publishes
//     the registers.
//     On the pin path that capture overlaps the firmware's next frame, as on a board: the frame is
//     scanned out while the next batches draw (the firmware sees DONE_SEQ after the swap, not after
//     the scan), and it is finished — compared before the model runs the batch that ends its scan —
//     during the batch whose swap waits for that scan's end, or at once before a palette write or a
//     RESET would change the pins, or by finish_frames(), which the caller calls when the firmware
//     has ended. Each displayed frame costs one scan of simulated time instead of two (the wait for
//     the swap's vertical blank, then the scan). The fast path and a traced run capture at once.
//     With --drop-doorbell N batch N is recorded but never run. With
//     --dump-lists DIR each batch is written first as DIR/batchNNNN.txt (prim_list.h format: ztri
//     when CTRL.ZTEST is set). On a GPU timeout, a disagreement, or a frame that cannot be captured
//     or written, it returns false with *error set (the caller reports it) and error_kind() naming
//     the failure for the run's summary: gpu-timeout, model-mismatch, capture or write.
//   - With --trace FILE (a simulator built for waves, GpuSim::trace_open) the GPU's signals go to
//     FILE from the first batch serviced once frame trace_frame - 1 is written (from the first batch
//     for frame 0) until frame trace_frame is captured, when the file is closed: the batches that
//     draw the frame, the wait for its swap and its scan-out. A trace that cannot be opened is an
//     error of kind "trace".
//   - service_reset(value) forwards a RESET at once (a watchdog gave up on a batch; the frame on the
//     pins is finished first), prints "cosim: GPU reset by the firmware", then publishes the
//     registers; false on an error of that frame.
// Simulated time advances only inside these calls, so results do not depend on host timing.
#ifndef BATCH_BRIDGE_H
#define BATCH_BRIDGE_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gpu_sim.h"
#include "harness.h"
#include "model_check.h"

// The bridge's own options; the frames', the model's and the trace's are the harness's.
struct BridgeOptions {
    uint64_t max_batch_cycles = 100000000;  // 1 s of GPU time at 100 MHz
    uint32_t drop_doorbell = 0;  // batch number never serviced (0: none)
    std::string dump_lists;      // directory for each batch as a primitive list
};

class BatchBridge {
public:
    BatchBridge(const BridgeOptions &o, Harness &harness);

    // The firmware's view of the window starts as the GPU's power-on registers where they are not
    // 0 (FB_WRITE_MASK: both planes; STRIP: the whole frame), so that the shadow and the RTL agree
    // before the first replay: a store of 0 there is then a change, replayed like any other (the
    // first strip of one row is STRIP = 0).
    void attach(volatile uint32_t *window)
    {
        window_ = window;
        for (const uint32_t reg : {GPU_REG_FB_WRITE_MASK, GPU_REG_STRIP}) {
            window_[reg / 4] = shadow_[reg / 4] = sim_.read(reg);
        }
    }
    bool pending_doorbell(uint32_t *tag) const;
    // Whether the pending doorbell's batch asks for a swap (CTRL SWAP as the firmware left it).
    bool pending_swaps() const
    {
        return (__atomic_load_n(&window_[GPU_REG_CTRL / 4], __ATOMIC_ACQUIRE) & GPU_CTRL_SWAP_MASK) != 0;
    }
    bool pending_reset(uint32_t *value) const;
    bool service_batch(uint32_t tag, std::string *error);
    bool service_reset(uint32_t value, std::string *error);
    bool finish_frames(std::string *error);
    void publish_registers();

    uint32_t batches() const { return batches_; }  // doorbells taken so far (dropped ones included)
    uint32_t doorbells_dropped() const { return dropped_; }
    uint32_t resets() const { return resets_; }
    uint64_t cycles() const { return sim_.cycles(); }
    // SCANOUT_UNDERFLOWS as last published; the frames' memory port's traffic (FRAME_DRAM, pin path).
    uint32_t scanout_underflows() const { return shadow_[GPU_REG_SCANOUT_UNDERFLOWS / 4]; }
    uint64_t memory_words_read() const { return sim_.memory_words_read(); }
    uint64_t memory_words_written() const { return sim_.memory_words_written(); }
    const char *error_kind() const { return error_kind_; }
    // The harness's UART work during a batch (GpuSim::set_background).
    void set_background(std::function<void()> fn, uint64_t every) { sim_.set_background(std::move(fn), every); }

private:
    void dump_list();
    void feed_model();
    void feed_model_write(uint32_t offset, uint32_t value)
    {
        if (hopt_.check_model) {
            model_.write(offset, value);
        }
    }
    bool finish_capture(std::string *error);

    const BridgeOptions &opt_;
    Harness &harness_;
    const HarnessOptions &hopt_;
    GpuSim sim_;
    ModelCheck model_;
    volatile uint32_t *window_ = nullptr;
    std::vector<uint32_t> shadow_;  // the window as last forwarded to the RTL
    bool capture_pending_ = false;  // a swapped frame is armed on the pins, not yet finished
    uint32_t batches_ = 0;
    uint32_t dropped_ = 0;
    uint32_t resets_ = 0;
    const char *error_kind_ = "none";
    enum class Trace { Waiting, On, Done } trace_ = Trace::Waiting;
};

#endif
