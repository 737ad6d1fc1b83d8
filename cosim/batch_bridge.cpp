// batch_bridge: see batch_bridge.h.
#include "batch_bridge.h"

#include <cstdarg>
#include <cstdio>

#include "prim_list.h"

extern "C" {
#include "gpu_regs.h"
}

namespace {

std::string format(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    return text;
}

}  // namespace

BatchBridge::BatchBridge(const BridgeOptions &o, Harness &harness)
    : opt_(o), harness_(harness), hopt_(harness.options()), model_(GpuSim::build_config()),
      shadow_(GPU_APERTURE_BYTES / 4, 0)
{
}

bool BatchBridge::pending_doorbell(uint32_t *tag) const
{
    *tag = __atomic_load_n(&window_[GPU_REG_DOORBELL / 4], __ATOMIC_ACQUIRE);
    return *tag != shadow_[GPU_REG_DOORBELL / 4];
}

bool BatchBridge::pending_reset(uint32_t *value) const
{
    *value = __atomic_load_n(&window_[GPU_REG_RESET / 4], __ATOMIC_ACQUIRE);
    return *value != shadow_[GPU_REG_RESET / 4];
}

bool BatchBridge::service_reset(uint32_t value, std::string *error)
{
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    if (!finish_frames(error)) {  // the frame on the pins first: a reset may change what shows
        return false;
    }
    sim_.write(GPU_REG_RESET, value);
    if (hopt_.check_model) {
        model_.write(GPU_REG_RESET, value);
    }
    shadow_[GPU_REG_RESET / 4] = value;
    resets_++;
    std::printf("cosim: GPU reset by the firmware (RESET = %u)\n", value);
    publish_registers();
    return true;
}

// The batch about to run, as a primitive list (vertices expanded; invalid primitives left out).
void BatchBridge::dump_list()
{
    const auto reg = [&](uint32_t offset) { return shadow_[offset / 4]; };
    std::vector<ListOp> ops;
    if (reg(GPU_REG_CTRL) & GPU_CTRL_CLEAR_MASK) {
        ops.push_back(ListOp{ListOp::Clear, {0, 0, 0, 0, 0, 0}, {0, 0, 0}, reg(GPU_REG_CLEAR_COLOR) & 0xFFu});
    }
    const bool depth = (reg(GPU_REG_CTRL) & GPU_CTRL_ZTEST_MASK) != 0;
    const uint32_t vbase = reg(GPU_REG_VTX_BASE), vcount = reg(GPU_REG_VTX_COUNT);
    const uint32_t tbase = reg(GPU_REG_TRI_BASE), tcount = reg(GPU_REG_TRI_COUNT);
    const auto vertex = [&](uint32_t i, ListOp &op, int k) {
        const uint32_t xy = shadow_[(GPU_WIN_VTX + 8 * (vbase + i)) / 4];
        const uint32_t attr = shadow_[(GPU_WIN_VTX + 8 * (vbase + i) + 4) / 4];
        op.v[2 * k] = static_cast<int16_t>(xy >> GPU_VTX_X_LSB);
        op.v[2 * k + 1] = static_cast<int16_t>(xy >> GPU_VTX_Y_LSB);
        op.z[k] = depth ? (attr >> GPU_VTX_Z_LSB) & GPU_VTX_Z_MASK : 0;
    };
    for (uint32_t t = 0; t < tcount && tbase + t < GPU_TRI_CAP && vbase + vcount <= GPU_VTX_CAP; t++) {
        const uint32_t w0 = shadow_[(GPU_WIN_IDX + 8 * (tbase + t)) / 4];
        const uint32_t w1 = shadow_[(GPU_WIN_IDX + 8 * (tbase + t) + 4) / 4];
        const uint32_t i0 = (w0 >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK, i1 = (w0 >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK;
        const uint32_t i2 = (w1 >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK;
        const uint32_t kind = (w1 >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK;
        ListOp op{};
        op.color = (w1 >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK;
        if (i0 >= vcount || i1 >= vcount) {
            continue;
        }
        vertex(i0, op, 0);
        vertex(i1, op, 1);
        if (kind == GPU_PRIM_KIND_LINE) {
            op.kind = ListOp::Line;
            op.z[0] = op.z[1] = 0;  // a line has no depth test
        } else if (kind == GPU_PRIM_KIND_TRI && i2 < vcount) {
            vertex(i2, op, 2);
            op.kind = depth ? ListOp::ZTri : ListOp::Tri;
        } else if (kind == GPU_PRIM_KIND_TRI_GOURAUD && i2 < vcount) {
            // A Gouraud triangle keeps its intensities (the list format has no depth-tested one).
            vertex(i2, op, 2);
            op.kind = ListOp::GTri;
            for (uint32_t k = 0; k < 3; k++) {
                const uint32_t vi = k == 0 ? i0 : (k == 1 ? i1 : i2);
                op.z[k] = (shadow_[(GPU_WIN_VTX + 8 * (vbase + vi) + 4) / 4] >> GPU_VTX_I_LSB) & GPU_VTX_I_MASK;
            }
        } else {
            continue;
        }
        ops.push_back(op);
    }
    char path[512];
    std::snprintf(path, sizeof path, "%s/batch%04u.txt", opt_.dump_lists.c_str(), batches_);
    FILE *f = std::fopen(path, "w");
    if (f == nullptr) {
        return;
    }
    std::fputs(prim_list_write(ops).c_str(), f);
    std::fclose(f);
}

// Copy the GPU's read-only registers into the shared window, DONE_SEQ last (kReadOnlyRegs order).
void BatchBridge::publish_registers()
{
    for (int i = 0; i < kReadOnlyRegCount; i++) {
        const uint32_t offset = kReadOnlyRegs[i];
        const uint32_t value = sim_.read(offset);
        if (offset == GPU_REG_DONE_SEQ) {
            __atomic_thread_fence(__ATOMIC_RELEASE);
        }
        window_[offset / 4] = value;
        shadow_[offset / 4] = value;
    }
}

bool BatchBridge::service_batch(uint32_t tag, std::string *error)
{
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    if (!hopt_.trace.empty() && trace_ == Trace::Waiting && harness_.frames() == hopt_.trace_frame) {
        if (!sim_.trace_open(hopt_.trace, error)) {
            error_kind_ = "trace";
            return false;
        }
        trace_ = Trace::On;
        std::printf("cosim: tracing frame %u -> %s\n", hopt_.trace_frame, hopt_.trace.c_str());
    }
    const uint32_t doorbell_word = GPU_REG_DOORBELL / 4;
    // A palette write shows at once on the pins: the frame being scanned out is captured first.
    for (uint32_t w = GPU_WIN_PALETTE / 4; capture_pending_ && w < (GPU_WIN_PALETTE + GPU_WIN_PALETTE_BYTES) / 4; w++) {
        if (window_[w] != shadow_[w] && !finish_capture(error)) {
            return false;
        }
    }
    // Replay the firmware's stores into the RTL: every word that changed since the last batch,
    // DOORBELL last. The model takes them once the frame on the pins is compared (held writes).
    model_.hold_writes();
    for (uint32_t w = 0; w < shadow_.size(); w++) {
        const uint32_t value = window_[w];
        if (value != shadow_[w] && w != doorbell_word) {
            sim_.write(w * 4, value);
            feed_model_write(w * 4, value);
            shadow_[w] = value;
        }
    }
    if (batches_ + 1 == opt_.drop_doorbell) {
        batches_++;
        dropped_++;
        shadow_[doorbell_word] = tag;
        std::printf("cosim: doorbell %u (tag %u) dropped on purpose (--drop-doorbell)\n", batches_, tag);
        feed_model();  // the stores, without the doorbell: nothing runs, nothing shows
        return true;
    }
    if (!opt_.dump_lists.empty()) {
        dump_list();
    }
    const uint32_t frames_before = sim_.read(GPU_REG_FRAME_COUNT);
    sim_.write(GPU_REG_DOORBELL, tag);
    feed_model_write(GPU_REG_DOORBELL, tag);
    shadow_[doorbell_word] = tag;
    batches_++;

    if (!sim_.wait_done(tag, opt_.max_batch_cycles)) {
        error_kind_ = "gpu-timeout";
        *error = format("GPU timeout: batch %u (tag %u) did not finish within %llu cycles", batches_, tag,
                        static_cast<unsigned long long>(opt_.max_batch_cycles));
        return false;
    }
    const bool swapped = sim_.read(GPU_REG_FRAME_COUNT) != frames_before;
    // The previous frame's scan-out ran while this batch drew: a swap waits for its end, so after
    // one the frame is complete on the pins (but for the last pixels, a few clocks on); so is it
    // when the scan happened to end during the batch. Either way it is compared before the model
    // runs this batch, which may swap the model's front buffer at once.
    if (capture_pending_ && (swapped || sim_.frame_captured()) && !finish_capture(error)) {
        return false;
    }
    feed_model();
    if (hopt_.check_model) {
        const std::string diff = model_.compare_registers(sim_);
        if (!diff.empty()) {
            error_kind_ = "model-mismatch";
            *error = format("batch %u: RTL and golden model disagree: %s", batches_, diff.c_str());
            return false;
        }
    }
    if (swapped) {
        // The pin path overlaps the new front buffer's scan-out with the firmware's next frame, as
        // a board does (DONE_SEQ is published now, not after the scan); the fast path and a traced
        // run capture it at once.
        sim_.arm_capture();
        capture_pending_ = true;
        if ((GpuSim::fast_display() || !hopt_.trace.empty()) && !finish_capture(error)) {
            return false;
        }
    }
    publish_registers();
    return true;
}

bool BatchBridge::finish_frames(std::string *error)
{
    return !capture_pending_ || finish_capture(error);
}

// The model takes the stores the RTL took, in the same order.
void BatchBridge::feed_model()
{
    model_.release_writes();
}

// The armed frame: scanned to its end (a frame at most), then the harness's (compared with the
// model's front buffer, which the model's next batch has not yet changed; written; counted).
bool BatchBridge::finish_capture(std::string *error)
{
    capture_pending_ = false;
    const uint64_t frame_cycles = 800ull * 525 * 4;
    if (!sim_.wait_capture(3 * frame_cycles)) {
        error_kind_ = "capture";
        *error = format("no frame captured from the VGA pins: %s", sim_.vga_error()[0] ? sim_.vga_error() : "timeout");
        return false;
    }
    const std::string detail = format("gpu busy %u cycles | simulated %llu cycles", sim_.read(GPU_REG_PERF_BUSY_CYCLES),
                                      static_cast<unsigned long long>(sim_.cycles()));
    if (!harness_.take_frame(sim_.frame_rgb(), model_, sim_.cycles(), detail, error, &error_kind_)) {
        return false;
    }
    if (trace_ == Trace::On) {
        sim_.trace_close();
        trace_ = Trace::Done;
        std::printf("cosim: trace of frame %u written: %s\n", hopt_.trace_frame, hopt_.trace.c_str());
    }
    return true;
}
