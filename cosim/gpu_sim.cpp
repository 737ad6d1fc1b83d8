// gpu_sim: see gpu_sim.h.
#include "gpu_sim.h"

#include "Vgpu_top.h"
#include "verilated.h"

extern "C" {
#include "gpu_regs.h"
}

GpuSim::GpuSim() : context_(new VerilatedContext), top_(new Vgpu_top(context_.get()))
{
    vga_monitor_reset(&monitor_);
    reset();
}

GpuSim::~GpuSim()
{
    top_->final();
}

void GpuSim::reset()
{
    top_->bus_valid = 0;
    top_->bus_write = 0;
    top_->rst = 1;
    for (int i = 0; i < 4; i++) {
        tick();
    }
    top_->rst = 0;
}

void GpuSim::tick()
{
    // Outputs change on the edge at which vga_pix_stb is high; sample them right after it.
    top_->clk = 0;
    top_->eval();
    const bool pixel_edge = top_->vga_pix_stb;
    top_->clk = 1;
    top_->eval();
    cycles_++;
    if (pixel_edge) {
        vga_monitor_sample(&monitor_, top_->vga_hsync_n, top_->vga_vsync_n, top_->vga_r,
                           top_->vga_g, top_->vga_b);
    }
}

void GpuSim::write(uint32_t offset, uint32_t value)
{
    top_->bus_valid = 1;
    top_->bus_write = 1;
    top_->bus_addr = offset >> 2;
    top_->bus_wdata = value;
    tick();
    top_->bus_valid = 0;
    top_->bus_write = 0;
}

uint32_t GpuSim::read(uint32_t offset)
{
    top_->bus_valid = 1;
    top_->bus_write = 0;
    top_->bus_addr = offset >> 2;
    tick();  // the request is taken on this edge; bus_rdata is valid in the cycle after it
    top_->bus_valid = 0;
    return top_->bus_rdata;
}

bool GpuSim::wait_done(uint32_t tag, uint64_t max_cycles)
{
    const uint64_t limit = cycles_ + max_cycles;
    while (cycles_ < limit) {
        if (read(GPU_REG_DONE_SEQ) == tag && !(read(GPU_REG_STATUS) & GPU_STATUS_BUSY_MASK)) {
            return true;
        }
        for (int i = 0; i < 60; i++) {  // poll every 64 cycles, as a CPU would
            tick();
        }
    }
    return false;
}

bool GpuSim::capture_frame(uint64_t max_cycles)
{
    const uint64_t limit = cycles_ + max_cycles;
    vga_monitor_arm(&monitor_);
    while (!monitor_.frame_ready && cycles_ < limit && monitor_.error[0] == '\0') {
        tick();
    }
    return monitor_.frame_ready && monitor_.error[0] == '\0';
}
