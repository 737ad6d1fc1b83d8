// scanout_check: `gpusim scanout-underflow` — what the display does when the frames' memory stops
// answering (a GPU built with FRAME_DRAM, on the pin path): the contract says such a display line
// is counted in SCANOUT_UNDERFLOWS and shown whole in SCANOUT_UNDERFLOW_RGB444, never torn, and
// that the frame survives. The run:
//   1. every strip cleared to one colour, the frame swapped; a frame from the VGA pins: that colour
//      everywhere, no underflow;
//   2. the memory refuses every command for --stall-lines display lines, starting --at-line lines
//      into the next frame's capture: the captured frame's lines are each either the colour or
//      wholly the underflow colour, the latter at least one and one per underflow counted;
//   3. the next frame: the colour everywhere again, the count unchanged.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "gpu_sim.h"

extern "C" {
#include "gpu_regs.h"
#include "vga_monitor.h"
}

namespace {

constexpr uint32_t kIndex = 5;         // the palette entry cleared to
constexpr uint32_t kRgb444 = 0x2A7;    // its colour

uint32_t rgb888(uint32_t rgb444)  // as the monitor model takes the pins: each channel times 17
{
    return ((rgb444 >> 8 & 15) * 17) << 16 | ((rgb444 >> 4 & 15) * 17) << 8 | (rgb444 & 15) * 17;
}

// Each display line of the captured frame: 0 the colour everywhere, 1 the underflow colour
// everywhere, -1 anything else (a torn or wrong line).
int line_kind(const uint8_t *rgb, int y)
{
    const uint8_t *row = rgb + std::size_t{VGA_W} * 3 * y;
    const uint32_t first = uint32_t{row[0]} << 16 | uint32_t{row[1]} << 8 | row[2];
    for (int x = 1; x < VGA_W; x++) {
        const uint32_t p = uint32_t{row[3 * x]} << 16 | uint32_t{row[3 * x + 1]} << 8 | row[3 * x + 2];
        if (p != first) {
            return -1;
        }
    }
    return first == rgb888(kRgb444) ? 0 : first == rgb888(GPU_SCANOUT_UNDERFLOW_RGB444) ? 1 : -1;
}

bool capture(GpuSim &sim, const char *what)
{
    if (!sim.capture_frame(3 * GpuSim::kScanClocks)) {
        std::printf("scanout-underflow: %s: no VGA frame: %s\n", what, sim.vga_error());
        return false;
    }
    return true;
}

}  // namespace

int scanout_underflow_main(int argc, char **argv)
{
    uint64_t stall_lines = 20, at_line = 100;
    for (int i = 0; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--stall-lines") {
            stall_lines = std::strtoull(argv[i + 1], nullptr, 0);
        } else if (a == "--at-line") {
            at_line = std::strtoull(argv[i + 1], nullptr, 0);
        } else {
            std::fprintf(stderr, "usage: gpusim scanout-underflow [--stall-lines N] [--at-line N]\n");
            return 2;
        }
    }
    GpuSim sim;
    const uint32_t strip_rows = sim.read(GPU_REG_STRIP_ROWS);
    const uint32_t height = sim.read(GPU_REG_FB_SIZE) >> 16;
    if (!sim.stall_memory(0) || strip_rows == 0) {
        std::fprintf(stderr, "scanout-underflow: needs a GPU with its frames in external memory (FRAME_DRAM) on the pin path\n");
        return 2;
    }

    // 1. The frame cleared strip by strip (each strip's batch opens it with a whole clear), swapped.
    sim.write(GPU_WIN_PALETTE + 4 * kIndex, kRgb444);
    sim.write(GPU_REG_CLEAR_COLOR, kIndex);
    sim.write(GPU_REG_VTX_COUNT, 0);
    sim.write(GPU_REG_TRI_COUNT, 0);
    uint32_t tag = 0;
    for (uint32_t first = 0; first < height; first += strip_rows) {
        const bool last = first + strip_rows >= height;
        sim.write(GPU_REG_CTRL, GPU_CTRL_CLEAR_MASK | (last ? GPU_CTRL_SWAP_MASK : 0));
        sim.write(GPU_REG_STRIP, first << GPU_STRIP_FIRST_LSB | (first + strip_rows - 1) << GPU_STRIP_LAST_LSB);
        sim.write(GPU_REG_DOORBELL, ++tag);
        if (!sim.wait_done(tag, 20000000) || sim.read(GPU_REG_ERRORS) != 0) {
            std::printf("scanout-underflow: the clear of rows %u.. did not finish cleanly (ERRORS 0x%x)\n", first,
                        sim.read(GPU_REG_ERRORS));
            return 1;
        }
    }
    if (!capture(sim, "before the stall")) {
        return 1;
    }
    for (int y = 0; y < VGA_H; y++) {
        if (line_kind(sim.frame_rgb(), y) != 0) {
            std::printf("scanout-underflow: before the stall, display line %d is not the cleared colour\n", y);
            return 1;
        }
    }
    const uint32_t before = sim.read(GPU_REG_SCANOUT_UNDERFLOWS);
    if (before != 0) {
        std::printf("scanout-underflow: %u underflows before the stall\n", before);
        return 1;
    }

    // 2. The memory stops answering for a while inside the next frame.
    sim.arm_capture();
    for (uint64_t c = 0; c < at_line * GpuSim::kScanLineClocks; c++) {
        sim.tick();
    }
    sim.stall_memory(stall_lines * GpuSim::kScanLineClocks);
    if (!sim.wait_capture(3 * GpuSim::kScanClocks)) {
        std::printf("scanout-underflow: during the stall: no VGA frame: %s\n", sim.vga_error());
        return 1;
    }
    int shown_late = 0, first_late = -1, last_late = -1;
    for (int y = 0; y < VGA_H; y++) {
        const int kind = line_kind(sim.frame_rgb(), y);
        if (kind < 0) {
            std::printf("scanout-underflow: display line %d is neither the frame's colour nor wholly the underflow colour\n", y);
            return 1;
        }
        if (kind == 1) {
            shown_late++;
            last_late = y;
            first_late = first_late < 0 ? y : first_late;
        }
    }
    const uint32_t counted = sim.read(GPU_REG_SCANOUT_UNDERFLOWS);
    if (shown_late == 0 || counted != static_cast<uint32_t>(shown_late) || last_late - first_late + 1 != shown_late) {
        std::printf("scanout-underflow: %d lines shown in the underflow colour (%d .. %d), %u counted\n", shown_late,
                    first_late, last_late, counted);
        return 1;
    }

    // 3. The memory answers again: the frame is whole, nothing more is counted.
    if (!capture(sim, "after the stall")) {
        return 1;
    }
    for (int y = 0; y < VGA_H; y++) {
        if (line_kind(sim.frame_rgb(), y) != 0) {
            std::printf("scanout-underflow: after the stall, display line %d is not the cleared colour\n", y);
            return 1;
        }
    }
    if (sim.read(GPU_REG_SCANOUT_UNDERFLOWS) != counted || !sim.memory_error().empty()) {
        std::printf("scanout-underflow: after the stall: %u underflows (%u before) %s\n",
                    sim.read(GPU_REG_SCANOUT_UNDERFLOWS), counted, sim.memory_error().c_str());
        return 1;
    }
    std::printf("scanout-underflow: the memory refused every command for %llu lines: display lines %d .. %d shown "
                "whole in the underflow colour, %u counted; the frames before and after whole\n",
                static_cast<unsigned long long>(stall_lines), first_late, last_late, counted);
    return 0;
}
