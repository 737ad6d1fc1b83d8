// gpu_sim: drives the Verilated GPU through its own ports — bus writes and reads, the clock — and
// shows its frames, on one of two display paths chosen when the simulator is built:
//   - the pin path (default): gpu_top, whose VGA pins a monitor model watches; a frame is a whole
//     VGA scan (800 x 525 pixels of PIX_DIV 4 clocks, 1.68 M clocks), and a swap waits for the
//     scan's vertical blank.
//   - the fast path (GPUSIM_FAST_DISPLAY=1): gpu_core, the GPU without gpu_vga, with this harness as
//     its display. It pulses the core's vblank_start every kFastVblankEvery clocks (a display that
//     is ready for a new frame at once), never clocks clk_pix, and shows the RTL's own front bank
//     through the RTL's own palette (their block-RAM arrays), 2x2 as gpu_vga does. No scan is
//     simulated: a frame costs the GPU's busy clocks only. The tests hold it to the pin path's
//     frames, frame for frame.
// Nothing here drives anything inside the RTL; the looks inside are back_buffer() and the fast path's
// front bank and palette (arrays that have no port to be seen by without clocking a scan).
#ifndef GPU_SIM_H
#define GPU_SIM_H

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

extern "C" {
#include "gpu_model.h"
#include "vga_monitor.h"
}
#include "rng.h"

class NativePortModel;

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
    // The pin path: arm_capture() arms the monitor for the next complete frame from the VGA pins,
    // wait_capture() runs until it is in (false on timeout or a timing error), frame_captured() says
    // whether it is; capture_frame() arms and waits. The fast path: arm_capture() takes the front
    // bank as it is now, through the palette, at no clock; the frame is then always captured.
    void arm_capture();
    bool wait_capture(uint64_t max_cycles);
    bool frame_captured() const { return fast_display() || monitor_.frame_ready; }
    bool capture_frame(uint64_t max_cycles)
    {
        arm_capture();
        return wait_capture(max_cycles);
    }
    static bool fast_display();  // true in a simulator built for the fast path
    // The golden model's configuration for this simulator: its -G parameters (cosim/gpu_build.h).
    static gpu_model_config build_config();
    static constexpr unsigned kFastVblankEvery = 64;  // the fast path's vblank_start period, clocks
    // The pin path's display: gpu_top's default PIX_DIV (4 clocks a pixel), 640x480@60's 800 pixels
    // a line and 525 lines a scan.
    static constexpr uint64_t kScanLineClocks = 800 * 4;
    static constexpr uint64_t kScanClocks = 525 * kScanLineClocks;

    // The framebuffer being drawn (the back bank, !STATUS.FRONT), as the build's frame (build_config's
    // fb_width x fb_height) of palette indices,
    // row-major: read from the framebuffer's block-RAM arrays in the Verilated model (their
    // Verilator names, gpu_top.u_core.g_frame_bram.u_framebuffer.g_split.g_bank[b].u_main / g_tail.u_tail .mem, or
    // g_merged.u_both.mem with the write mask, are checked at
    // compile time). A strip build's strips still on chip (being flushed, open) are laid over it
    // from the strip buffer's banks: the frame as it will be written. Takes no clock and no bus
    // cycle, so it changes nothing the GPU does.
    void back_buffer(uint8_t *pixels) const;
    // The fast path: the back frame refuses a span on `percent` of the clocks, at random from `seed`
    // (a frame memory busy elsewhere; a strip build's flush must wait, never drop). The pin path
    // with the frames in external memory (FRAME_DRAM): its memory port refuses commands and write
    // data on `percent` of the clocks. The pin path's frame in block RAM takes a span every clock:
    // false there.
    bool throttle_frame(unsigned percent, uint64_t seed);
    // FRAME_DRAM, pin path: the memory refuses every command for `clocks` clocks from now (reads
    // for the scan-out included: the display underflows). False in other builds.
    bool stall_memory(uint64_t clocks);
    // FRAME_DRAM, pin path: the memory port model's first protocol error (empty: none), and what
    // moved through the port since reset, in native words of memory_word_bytes() bytes (the
    // port's width, gpu_top's MEM_DW / 8; 0 in a build without FRAME_DRAM).
    std::string memory_error() const;
    uint64_t memory_words_read() const;
    uint64_t memory_words_written() const;
    static unsigned memory_word_bytes();

    const uint8_t *frame_rgb() const { return monitor_.rgb; }  // VGA_W x VGA_H RGB888
    const char *vga_error() const { return monitor_.error; }
    uint64_t cycles() const { return cycles_; }

    // Waves (`make waves`): in a simulator built with GPUSIM_TRACE=1 (and Verilator's --trace-fst),
    // an FST of every signal, dumped at both edges of each tick() while the trace is on (time in ns
    // of a 100 MHz clock: the falling edge at 10 * cycles(), the rising one 5 ns later). trace_open
    // starts it on; trace_on pauses and resumes it; trace_close flushes and closes the file. In
    // other builds trace_supported() is false and trace_open fails with *error saying so.
    static bool trace_supported();
    bool trace_open(const std::string &path, std::string *error);
    void trace_on(bool on);
    void trace_close();

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
    void show_front_bank();  // the fast path's display
    void read_frame(bool bank, uint8_t *pixels) const;  // a frame's pixels (either kind of frame)

    struct Verilated;  // the model (gpu_top or gpu_core) and its context: gpu_sim.cpp, the one
                       // file compiled per simulator, defines it
    std::unique_ptr<Verilated> v_;
    vga_monitor monitor_;
    uint64_t cycles_ = 0;
    // FRAME_DRAM: the pin path's memory behind gpu_top's port; the fast path's frames (both
    // banks, pixels), written from gpu_core's frame stream.
    std::unique_ptr<NativePortModel> memory_;
    std::vector<uint8_t> fast_frames_;
    unsigned throttle_percent_ = 0;
    Rng throttle_rng_{1};
    std::function<void()> background_;
    uint64_t background_every_ = 0;
    uint64_t background_left_ = 0;
};

#endif
