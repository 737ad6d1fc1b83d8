// model_check: see model_check.h.
#include "model_check.h"

#include <cstdio>
#include <cstdlib>

#include "gpu_sim.h"

extern "C" {
#include "gpu_regs.h"
}

namespace {

// The contract's read-only registers (generated, offset order), reordered with DONE_SEQ last: the
// firmware takes a new DONE_SEQ as the sign that the others are current.
#define MODEL_CHECK_RO_OFFSET(name) GPU_REG_##name,
constexpr uint32_t kContractReadOnly[] = {GPU_READ_ONLY_REGS(MODEL_CHECK_RO_OFFSET)};
#undef MODEL_CHECK_RO_OFFSET
constexpr int kCount = sizeof kContractReadOnly / sizeof kContractReadOnly[0];
static_assert(kCount == GPU_READ_ONLY_REG_COUNT, "gpu_regs.h: X-macro and count disagree");

struct RegList {
    uint32_t offset[kCount];
};

constexpr RegList done_seq_last()
{
    RegList list{};
    int n = 0;
    for (const uint32_t offset : kContractReadOnly) {
        if (offset != GPU_REG_DONE_SEQ) {
            list.offset[n++] = offset;
        }
    }
    list.offset[n++] = GPU_REG_DONE_SEQ;
    return list;
}

constexpr RegList kOrdered = done_seq_last();
static_assert(kOrdered.offset[kCount - 1] == GPU_REG_DONE_SEQ, "DONE_SEQ is not read-only");

}  // namespace

const uint32_t *const kReadOnlyRegs = kOrdered.offset;
const int kReadOnlyRegCount = kCount;

ModelCheck::ModelCheck(const gpu_model_config &cfg) : model_(new gpu_model), expected_(640 * 480 * 3)
{
    if (const char *why = gpu_model_config_error(&cfg)) {
        std::fprintf(stderr,
                     "model check: the GPU's build (SPAN_W=%u VTX_CAP=%u TRI_CAP=%u) has no golden model: %s\n",
                     cfg.span_w, cfg.vtx_cap, cfg.tri_cap, why);
        std::exit(2);
    }
    gpu_model_reset_config(model_, &cfg);
}

ModelCheck::~ModelCheck()
{
    delete model_;
}

void ModelCheck::release_writes()
{
    holding_ = false;
    for (const auto &w : held_) {
        gpu_model_write(model_, w.first, w.second);
    }
    held_.clear();
}

std::string ModelCheck::compare_registers(GpuSim &sim)
{
    for (int i = 0; i < kReadOnlyRegCount; i++) {
        const uint32_t offset = kReadOnlyRegs[i];
        if (offset == GPU_REG_PERF_BUSY_CYCLES || offset == GPU_REG_PERF_SPANS_VISITED) {
            continue;  // implementation-specific: the model has no time and no traversal order
        }
        const uint32_t rtl = sim.read(offset);
        const uint32_t model = gpu_model_read(model_, offset);
        if (rtl != model) {
            char text[120];
            std::snprintf(text, sizeof text, "register 0x%03X: RTL 0x%08X, model 0x%08X", offset, rtl, model);
            return text;
        }
    }
    return "";
}

std::string ModelCheck::compare_frame(const uint8_t *rgb)
{
    gpu_model_scanout(model_, expected_.data());
    long mismatches = 0;
    long first = -1;
    for (long i = 0; i < 640L * 480; i++) {
        const uint8_t *a = &rgb[i * 3];
        const uint8_t *b = &expected_[i * 3];
        if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) {
            if (first < 0) {
                first = i;
            }
            mismatches++;
        }
    }
    if (mismatches == 0) {
        return "";
    }
    char text[200];
    const long x = first % 640, y = first / 640;
    std::snprintf(text, sizeof text,
                  "%ld pixels differ; first at screen (%ld,%ld) = fb (%ld,%ld): VGA %02x%02x%02x, model %02x%02x%02x",
                  mismatches, x, y, x / 2, y / 2, rgb[first * 3], rgb[first * 3 + 1], rgb[first * 3 + 2],
                  expected_[first * 3], expected_[first * 3 + 1], expected_[first * 3 + 2]);
    return text;
}
