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
//     registers with the model; when FRAME_COUNT moved, captures the next frame from the VGA pins,
//     compares it with the model and writes FRAMES_DIR/NNNN.png (none when frames_dir is empty),
//     printing one "cosim: frame" line; then publishes the registers. frame_rgb() is the last frame
//     captured (VGA_W x VGA_H RGB888). With --drop-doorbell N batch N is recorded but never run. With
//     --dump-lists DIR each batch is written first as DIR/batchNNNN.txt (prim_list.h format: ztri
//     when CTRL.ZTEST is set). On a GPU timeout, a disagreement, or a frame that cannot be captured
//     or written, it returns false with *error set (the caller reports it) and error_kind() naming
//     the failure for the run's summary: gpu-timeout, model-mismatch, capture or write.
//   - With --trace FILE (a simulator built for waves, GpuSim::trace_open) the GPU's signals go to
//     FILE from the first batch serviced once frame trace_frame - 1 is written (from the first batch
//     for frame 0) until frame trace_frame is captured, when the file is closed: the batches that
//     draw the frame, the wait for its swap and its scan-out. A trace that cannot be opened is an
//     error of kind "trace".
//   - service_reset(value) forwards a RESET at once (a watchdog gave up on a batch), prints
//     "cosim: GPU reset by the firmware", then publishes the registers.
// Simulated time advances only inside these calls, so results do not depend on host timing.
#ifndef BATCH_BRIDGE_H
#define BATCH_BRIDGE_H

#include <cstdint>
#include <string>
#include <vector>

#include "gpu_sim.h"
#include "model_check.h"

struct BridgeOptions {
    std::string frames_dir = "out/frames";  // empty: no PNG files
    uint64_t max_batch_cycles = 100000000;  // 1 s of GPU time at 100 MHz
    bool check_model = true;
    uint32_t drop_doorbell = 0;  // batch number never serviced (0: none)
    std::string dump_lists;      // directory for each batch as a primitive list
    std::string trace;           // --trace FILE.fst: the waves of frame trace_frame (a trace build)
    uint32_t trace_frame = 0;
};

class BatchBridge {
public:
    explicit BatchBridge(const BridgeOptions &o);

    void attach(volatile uint32_t *window) { window_ = window; }
    bool pending_doorbell(uint32_t *tag) const;
    bool pending_reset(uint32_t *value) const;
    bool service_batch(uint32_t tag, std::string *error);
    void service_reset(uint32_t value);
    void publish_registers();

    uint32_t batches() const { return batches_; }  // doorbells taken so far (dropped ones included)
    uint32_t doorbells_dropped() const { return dropped_; }
    uint32_t resets() const { return resets_; }
    uint32_t frames() const { return frames_written_; }
    uint32_t frames_model_checked() const { return frames_checked_; }
    uint64_t cycles() const { return sim_.cycles(); }
    const uint8_t *frame_rgb() const { return sim_.frame_rgb(); }
    const char *error_kind() const { return error_kind_; }
    // The harness's UART work during a batch (GpuSim::set_background).
    void set_background(std::function<void()> fn, uint64_t every) { sim_.set_background(std::move(fn), every); }

private:
    void dump_list();

    const BridgeOptions &opt_;
    GpuSim sim_;
    ModelCheck model_;
    volatile uint32_t *window_ = nullptr;
    std::vector<uint32_t> shadow_;  // the window as last forwarded to the RTL
    uint32_t frames_written_ = 0;  // frames captured (and written, with a frames_dir)
    uint32_t frames_checked_ = 0;  // frames compared with the golden model and found equal
    uint32_t batches_ = 0;
    uint32_t dropped_ = 0;
    uint32_t resets_ = 0;
    const char *error_kind_ = "none";
    enum class Trace { Waiting, On, Done } trace_ = Trace::Waiting;
};

#endif
