// gpu_sim: drives the Verilated GPU (gpu_top) through its own ports — bus writes and reads, the
// clock — and watches its VGA pins with a monitor model. Nothing here drives anything inside the RTL;
// the one look inside is back_buffer(), for checks only (the back buffer has no port to be seen by).
#ifndef GPU_SIM_H
#define GPU_SIM_H

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

extern "C" {
#include "vga_monitor.h"
}

class Vgpu_top;
class VerilatedContext;

class GpuSim {
public:
    GpuSim();
    ~GpuSim();

    void reset();
    void tick();                                   // one system clock
    void write(uint32_t offset, uint32_t value);   // one bus write (1 cycle)
    uint32_t read(uint32_t offset);                // one bus read (1 cycle; data sampled after the edge)

    // Run until DONE_SEQ == tag and STATUS.BUSY is clear. False if max_cycles pass first.
    bool wait_done(uint32_t tag, uint64_t max_cycles);
    // Capture the next complete frame from the VGA pins. False on timeout or a timing error.
    bool capture_frame(uint64_t max_cycles);

    // The framebuffer being drawn (the back bank, !STATUS.FRONT), as GPU_FB_WIDTH x GPU_FB_HEIGHT palette indices,
    // row-major: read from the framebuffer's block-RAM arrays in the Verilated model (their
    // Verilator names, gpu_top.u_framebuffer.g_bank[b].u_main / g_tail.u_tail .mem, are checked at
    // compile time). Takes no clock and no bus cycle, so it changes nothing the GPU does.
    void back_buffer(uint8_t *pixels) const;

    const uint8_t *frame_rgb() const { return monitor_.rgb; }
    const char *vga_error() const { return monitor_.error; }
    uint64_t cycles() const { return cycles_; }

    // Work of the harness's own while the GPU runs (the co-simulation's UART: the firmware's
    // output and a client's input must flow during a batch's seconds of simulation, not only
    // between batches): fn() every `every` clocks of tick(). It must not touch the GPU.
    void set_background(std::function<void()> fn, uint64_t every)
    {
        background_ = std::move(fn);
        background_every_ = every;
        background_left_ = every;
    }

private:
    std::unique_ptr<VerilatedContext> context_;
    std::unique_ptr<Vgpu_top> top_;
    vga_monitor monitor_;
    uint64_t cycles_ = 0;
    std::function<void()> background_;
    uint64_t background_every_ = 0;
    uint64_t background_left_ = 0;
};

#endif
