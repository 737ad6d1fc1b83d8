// raster_run: `gpusim raster --in LIST --out DIR` — renders a primitive list (prim_list.h) through
// the RTL and through the golden model, for users who want the GPU without firmware and for tests.
// Writes DIR/rtl.raw and DIR/model.raw (the GPU's frame, 320x240 by default, of palette indices,
// row-major, top row first), the RTL's
// frame as DIR/rtl.png (captured from the VGA pins) and DIR/stats.json (counters and cycles). The RTL's
// indices are read back from the VGA colours through a palette that gives every index its own colour.
// On a GPU with a strip buffer (STRIP_ROWS > 0: it draws one strip of rows at a time, contract "The
// strip buffer") the list is drawn strip by strip, as the GPU walks a batch once per strip
// (firmware's FW_STRIP_WALK): every batch again for each strip, STRIP set to its rows, the strip's
// first batch clearing it (the list's clear colour, else 0: a frame's power-on contents) and its
// depths where the list tests depth; the swap with the last strip's last batch. A list without a
// clear so draws what it draws on a GPU without strips, on a frame that starts cleared to 0.
// Exit status: 0 equal, 1 RTL and model differ, 2 bad input.
#include <cerrno>
#include <cstdio>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "gpu_sim.h"
#include "model_check.h"
#include "prim_list.h"

extern "C" {
#include "gpu_regs.h"
#include "png_write.h"
}

namespace {

// An injective palette: index i -> RGB444 with 3, 3 and 2 bits of i in the high bits of R, G and B.
uint32_t raster_palette(uint32_t i)
{
    return ((i >> 5) & 7u) << 9 | ((i >> 2) & 7u) << 5 | (i & 3u) << 2 | 0x111u;
}

struct Counters {
    uint64_t busy_cycles = 0, prims_in = 0, drawn = 0, rejected = 0, pixels = 0, samples = 0, spans_written = 0,
             spans_visited = 0, batches = 0;
    uint32_t errors = 0;
};

bool write_file(const std::string &path, const void *data, size_t size)
{
    FILE *f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) {
        std::fprintf(stderr, "raster: cannot create %s\n", path.c_str());
        return false;
    }
    const bool ok = std::fwrite(data, 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

}  // namespace

int raster_main(int argc, char **argv)
{
    std::string in_path, out_dir;
    for (int i = 0; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--in") {
            in_path = argv[i + 1];
        } else if (a == "--out") {
            out_dir = argv[i + 1];
        }
    }
    if (in_path.empty() || out_dir.empty()) {
        std::fprintf(stderr, "usage: gpusim raster --in LIST --out DIR\n");
        return 2;
    }
    std::vector<ListOp> ops;
    std::string error;
    if (!prim_list_read(in_path, ops, error)) {
        std::fprintf(stderr, "raster: %s\n", error.c_str());
        return 2;
    }
    if (mkdir(out_dir.c_str(), 0755) != 0 && errno != EEXIST) {
        std::fprintf(stderr, "raster: cannot create %s\n", out_dir.c_str());
        return 2;
    }

    GpuSim sim;
    ModelCheck model(GpuSim::build_config());
    auto write = [&](uint32_t offset, uint32_t value) {
        sim.write(offset, value);
        model.write(offset, value);
    };
    for (uint32_t p = 0; p < 256; p++) {
        write(GPU_WIN_PALETTE + 4 * p, raster_palette(p));
    }

    const std::vector<Batch> batches = prim_list_batches(ops, GPU_VTX_CAP, GPU_TRI_CAP);
    const uint32_t fb_rows = model.model()->cfg.fb_height;
    const uint32_t strip_rows = sim.read(GPU_REG_STRIP_ROWS);  // 0: the whole frame at once
    const uint32_t strips = strip_rows == 0 ? 1 : (fb_rows + strip_rows - 1) / strip_rows;
    Counters total;
    uint32_t tag = 0;
    for (uint32_t strip = 0; strip < strips; strip++) {
        for (size_t k = 0; k < batches.size(); k++) {
            const Batch &b = batches[k];
            if (strip == 0 || batches.size() > 1) {  // one batch stays in the GPU's buffers
                for (size_t w = 0; w < b.vtx.size(); w++) {
                    write(GPU_WIN_VTX + 4 * static_cast<uint32_t>(w), b.vtx[w]);
                }
                for (size_t w = 0; w < b.idx.size(); w++) {
                    write(GPU_WIN_IDX + 4 * static_cast<uint32_t>(w), b.idx[w]);
                }
            }
            const bool last = strip + 1 == strips && k + 1 == batches.size();
            const bool opens = strip_rows != 0 && k == 0;  // the strip's first batch clears it
            write(GPU_REG_VTX_BASE, 0);
            write(GPU_REG_VTX_COUNT, static_cast<uint32_t>(b.vtx.size() / 2));
            write(GPU_REG_TRI_BASE, 0);
            write(GPU_REG_TRI_COUNT, static_cast<uint32_t>(b.idx.size() / 2));
            write(GPU_REG_CLEAR_COLOR, b.clear ? b.clear_color : 0);
            uint32_t ctrl = (b.clear || opens ? GPU_CTRL_CLEAR_MASK : 0) | (last ? GPU_CTRL_SWAP_MASK : 0);
            if (b.dither) {
                ctrl |= GPU_CTRL_DITHER_MASK;
            }
            if (b.depth) {
                ctrl |= GPU_CTRL_ZTEST_MASK | ((b.clear || k == 0) ? GPU_CTRL_ZCLEAR_MASK : 0);
            }
            if (strip_rows != 0) {
                const uint32_t first = strip * strip_rows;
                write(GPU_REG_STRIP, first << GPU_STRIP_FIRST_LSB | (first + strip_rows - 1) << GPU_STRIP_LAST_LSB);
            }
            write(GPU_REG_CTRL, ctrl);
            tag++;
            write(GPU_REG_DOORBELL, tag);
            if (!sim.wait_done(tag, 2000000000ull)) {
                std::fprintf(stderr, "raster: GPU timeout in batch %zu (strip %u)\n", k, strip);
                return 1;
            }
            const std::string diff = model.compare_registers(sim);
            if (!diff.empty()) {
                std::fprintf(stderr, "raster: batch %zu (strip %u): RTL and model differ: %s\n", k, strip, diff.c_str());
                return 1;
            }
            total.batches++;
            total.busy_cycles += sim.read(GPU_REG_PERF_BUSY_CYCLES);
            total.prims_in += sim.read(GPU_REG_PERF_TRIS_IN);
            total.drawn += sim.read(GPU_REG_PERF_TRIS_DRAWN);
            total.rejected += sim.read(GPU_REG_PERF_TRIS_REJECTED);
            total.pixels += sim.read(GPU_REG_PERF_PIXELS);
            total.samples += sim.read(GPU_REG_PERF_SAMPLES);
            total.spans_written += sim.read(GPU_REG_PERF_SPANS_WRITTEN);
            total.spans_visited += sim.read(GPU_REG_PERF_SPANS_VISITED);
            total.errors |= sim.read(GPU_REG_ERRORS);
        }
    }
    if (!sim.capture_frame(3 * GpuSim::kScanClocks)) {
        std::fprintf(stderr, "raster: no frame from the VGA pins: %s\n", sim.vga_error());
        return 1;
    }

    // VGA colours back to palette indices; every scale x scale block (2x2 for 320x240) must be one
    // pixel.
    const int fb_w = static_cast<int>(model.model()->cfg.fb_width);
    const int fb_h = static_cast<int>(model.model()->cfg.fb_height);
    const int scale = GPU_MODEL_SCREEN_W / fb_w;
    const std::size_t fb_pixels = static_cast<std::size_t>(fb_w) * static_cast<std::size_t>(fb_h);
    std::vector<uint8_t> rtl_raw(fb_pixels);
    std::vector<int> index_of(4096, -1);
    for (uint32_t p = 0; p < 256; p++) {
        index_of[raster_palette(p)] = static_cast<int>(p);
    }
    const uint8_t *rgb = sim.frame_rgb();
    for (int y = 0; y < fb_h; y++) {
        for (int x = 0; x < fb_w; x++) {
            const auto colour = [&](int q) {  // screen pixel q of the block, as RGB444
                const uint8_t *c = &rgb[((scale * y + q / scale) * GPU_MODEL_SCREEN_W + scale * x + q % scale) * 3];
                return (c[0] / 17u) << 8 | (c[1] / 17u) << 4 | (c[2] / 17u);
            };
            const uint32_t first = colour(0);
            bool clean = index_of[first] >= 0;
            for (int q = 1; q < scale * scale; q++) {
                clean = clean && colour(q) == first;
            }
            if (!clean) {
                std::fprintf(stderr, "raster: VGA pixel (%d,%d) is not a clean %dx%d palette colour\n", x, y, scale, scale);
                return 1;
            }
            rtl_raw[y * fb_w + x] = static_cast<uint8_t>(index_of[first]);
        }
    }
    const uint8_t *model_raw = gpu_model_front(model.model());
    long differ = 0;
    for (std::size_t i = 0; i < fb_pixels; i++) {
        differ += rtl_raw[i] != model_raw[i];
    }

    const std::string dir = out_dir + "/";
    bool ok = write_file(dir + "rtl.raw", rtl_raw.data(), rtl_raw.size()) &&
              write_file(dir + "model.raw", model_raw, fb_pixels) &&
              png_write_rgb((dir + "rtl.png").c_str(), rgb, 640, 480) == 0;
    FILE *json = std::fopen((dir + "stats.json").c_str(), "w");
    if (json != nullptr) {
        std::fprintf(json,
                     "{\n  \"primitives_listed\": %zu,\n  \"batches\": %llu,\n  \"strip_rows\": %u,\n  \"span_width\": %u,\n"
                     "  \"busy_cycles\": %llu,\n  \"simulated_cycles\": %llu,\n  \"prims_in\": %llu,\n"
                     "  \"prims_drawn\": %llu,\n  \"prims_rejected\": %llu,\n  \"pixels\": %llu,\n"
                     "  \"samples\": %llu,\n  \"spans_written\": %llu,\n  \"spans_visited\": %llu,\n"
                     "  \"errors\": %u,\n  \"rtl_equals_model\": %s,\n  \"pixels_differing\": %ld,\n"
                     "  \"frame_memory_word_bytes\": %u\n}\n",
                     ops.size(), static_cast<unsigned long long>(total.batches), strip_rows,
                     (sim.read(GPU_REG_CAPS) & GPU_CAPS_SPAN_W_MASK) >> GPU_CAPS_SPAN_W_LSB,
                     static_cast<unsigned long long>(total.busy_cycles), static_cast<unsigned long long>(sim.cycles()),
                     static_cast<unsigned long long>(total.prims_in), static_cast<unsigned long long>(total.drawn),
                     static_cast<unsigned long long>(total.rejected), static_cast<unsigned long long>(total.pixels),
                     static_cast<unsigned long long>(total.samples), static_cast<unsigned long long>(total.spans_written),
                     static_cast<unsigned long long>(total.spans_visited), total.errors, differ == 0 ? "true" : "false",
                     differ, GpuSim::memory_word_bytes());
        ok = std::fclose(json) == 0 && ok;
    } else {
        ok = false;
    }
    if (!ok) {
        std::fprintf(stderr, "raster: cannot write the results in %s\n", out_dir.c_str());
        return 2;
    }
    std::printf("raster: %zu primitives in %llu batches, %llu pixels, %llu busy cycles: %s\n", ops.size(),
                static_cast<unsigned long long>(total.batches), static_cast<unsigned long long>(total.pixels),
                static_cast<unsigned long long>(total.busy_cycles),
                differ == 0 ? "RTL equals model" : "RTL AND MODEL DIFFER");
    if (differ != 0) {
        std::fprintf(stderr, "raster: %ld pixels differ between RTL and model\n", differ);
        return 1;
    }
    return 0;
}
