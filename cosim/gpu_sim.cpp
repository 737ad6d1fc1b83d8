// gpu_sim: see gpu_sim.h.
#include "gpu_sim.h"

#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <type_traits>
#include <utility>

// The model, and its core's arrays by their Verilator names.
#ifndef GPUSIM_FAST_DISPLAY
#define GPUSIM_FAST_DISPLAY 0
#endif
#if GPUSIM_FAST_DISPLAY
#include "Vgpu_core.h"
#include "Vgpu_core___024root.h"
using VerilatedGpu = Vgpu_core;
#define GPU_CORE_NAME(path) gpu_core__DOT__##path
#else
#include "Vgpu_top.h"
#include "Vgpu_top___024root.h"
using VerilatedGpu = Vgpu_top;
#define GPU_CORE_NAME(path) gpu_top__DOT__u_core__DOT__##path
#endif
#include "gpu_build.h"
#include "native_port_model.h"
#include "verilated.h"
#ifndef GPUSIM_TRACE
#define GPUSIM_TRACE 0
#endif
#if GPUSIM_TRACE
#include "verilated_fst_c.h"
#endif

extern "C" {
#include "gpu_regs.h"
}

struct GpuSim::Verilated {
    VerilatedContext context;
#if GPUSIM_TRACE
    bool trace_ever_on = (context.traceEverOn(true), true);  // before time 0, as Verilator asks
#endif
    VerilatedGpu top{&context};
#if GPUSIM_TRACE
    std::unique_ptr<VerilatedFstC> fst;  // open while a trace is being written
    bool fst_on = false;
    void dump(uint64_t time_ns)
    {
        if (fst_on) {
            fst->dump(time_ns);
        }
    }
#else
    void dump(uint64_t) {}
#endif
};

bool GpuSim::fast_display()
{
    return GPUSIM_FAST_DISPLAY != 0;
}

gpu_model_config GpuSim::build_config()
{
    return gpu_build_config();
}

namespace {

template <class T>
uint8_t lane(const T &word, unsigned i)  // a word of at most 64 bits
{
    return static_cast<uint8_t>(static_cast<uint64_t>(word) >> (8 * i));
}
template <std::size_t N>
uint8_t lane(const VlWide<N> &word, unsigned i)  // a word wider than 64 bits, in 32-bit parts
{
    return static_cast<uint8_t>(word.m_storage[i / 4] >> (8 * (i % 4)));
}

}  // namespace

// FRAME_DRAM: the frames' place behind gpu_top's memory port (its FRAME_BASE: the simulator
// passes none), in native words of kWordPixels pixels (its MEM_DW, the default: the model's Word;
// pixel p of a frame in byte p % kWordPixels of word p / kWordPixels, little-endian).
constexpr uint32_t kFrameBase = 0;
constexpr uint32_t kFramePixels = uint32_t{GPU_BUILD_FB_WIDTH} * GPU_BUILD_FB_HEIGHT;
constexpr uint32_t kWordPixels = NativePortModel::WORD_BYTES;
constexpr uint32_t kFrameWords = kFramePixels / kWordPixels;
static_assert(GPU_BUILD_FRAME_DRAM == 0
                  || (kFrameWords * kWordPixels == kFramePixels && GPU_BUILD_SPAN_W % kWordPixels == 0),
              "gpu_frame_dram: a frame and a span are whole native words");
#if !GPUSIM_FAST_DISPLAY
// gpu_top's memory port as Verilated (C types of 8, 16, 32, 64 bits) holds the model's words.
static_assert(sizeof(std::declval<VerilatedGpu &>().mem_rdata_data) == sizeof(NativePortModel::Word) &&
                  sizeof(std::declval<VerilatedGpu &>().mem_wdata_data) == sizeof(NativePortModel::Word),
              "gpu_top's MEM_DW is not the native port model's Word");
#endif

GpuSim::GpuSim() : v_(new Verilated)
{
    if constexpr (GPU_BUILD_FRAME_DRAM != 0) {
        if (fast_display()) {
            fast_frames_.assign(2 * std::size_t{kFramePixels}, 0);
        } else {
            memory_.reset(new NativePortModel(kFrameBase, 2 * kFrameWords));
        }
    }
    vga_monitor_reset(&monitor_);
    reset();
}

GpuSim::~GpuSim()
{
    trace_close();
    v_->top.final();
}

// ---- waves: see gpu_sim.h ----
bool GpuSim::trace_supported()
{
    return GPUSIM_TRACE != 0;
}

bool GpuSim::trace_open(const std::string &path, std::string *error)
{
#if GPUSIM_TRACE
    trace_close();
    v_->fst.reset(new VerilatedFstC);
    v_->fst->set_time_unit("1ns");
    v_->fst->set_time_resolution("1ns");
    v_->top.trace(v_->fst.get(), 99);
    v_->fst->open(path.c_str());
    if (!v_->fst->isOpen()) {
        v_->fst.reset();
        *error = "cannot create " + path;
        return false;
    }
    v_->fst_on = true;
    return true;
#else
    *error = "this simulator was built without tracing (" + path + " not written): use make waves";
    return false;
#endif
}

void GpuSim::trace_on(bool on)
{
#if GPUSIM_TRACE
    v_->fst_on = on && v_->fst != nullptr;
#else
    (void)on;
#endif
}

void GpuSim::trace_close()
{
#if GPUSIM_TRACE
    if (v_->fst != nullptr) {
        v_->fst->close();
        v_->fst.reset();
    }
    v_->fst_on = false;
#endif
}

void GpuSim::reset()
{
    v_->top.bus_valid = 0;
    v_->top.bus_write = 0;
    v_->top.rst = 1;
    for (int i = 0; i < 4; i++) {
        tick();
    }
    v_->top.rst = 0;
}

void GpuSim::tick()
{
#if GPUSIM_FAST_DISPLAY
    // The display is this harness: vertical blank every kFastVblankEvery clocks, clk_pix still.
    v_->top.vblank_start = (cycles_ % kFastVblankEvery) == 0;
    // The back frame takes a span this clock unless throttled (a frame memory busy elsewhere).
    v_->top.fb_wr_ready = throttle_percent_ == 0 || throttle_rng_.below(100) >= throttle_percent_;
    v_->top.fb_wr_idle = 1;  // FRAME_DRAM: this harness writes each span as it takes it
    v_->top.scanout_underflows = 0;
    v_->top.clk = 0;
    v_->top.eval();
    v_->dump(cycles_ * 10);
    if constexpr (GPU_BUILD_FRAME_DRAM != 0) {
        if (v_->top.fb_wr_valid && v_->top.fb_wr_ready) {  // a span into the back frame
            uint8_t *span = &fast_frames_[(v_->top.front_bank ? 0 : kFramePixels)
                                          + std::size_t{v_->top.fb_wr_addr_out} * GPU_BUILD_SPAN_W];
            for (unsigned i = 0; i < GPU_BUILD_SPAN_W; i++) {
                span[i] = lane(v_->top.fb_wr_data_out, i);
            }
        }
    }
    v_->top.clk = 1;
    v_->top.eval();
    v_->dump(cycles_ * 10 + 5);
    cycles_++;
#else
    // Outputs change on the edge at which vga_pix_stb is high; sample them right after it. The
    // scan-out's clock is the system clock here (PIX_DIV clocks a pixel), its crossings still in.
    if (memory_) {  // FRAME_DRAM: the memory's side of the port for this clock
        const NativePortModel::Out out = memory_->drive();
        v_->top.mem_cmd_ready = out.cmd_ready;
        v_->top.mem_wdata_ready = out.wdata_ready;
        v_->top.mem_rdata_valid = out.rdata_valid;
        v_->top.mem_rdata_data = out.rdata;
    }
    v_->top.clk = v_->top.clk_pix = 0;
    v_->top.eval();
    v_->dump(cycles_ * 10);
    const bool pixel_edge = v_->top.vga_pix_stb;
    if (memory_) {
        memory_->sample(v_->top.mem_cmd_valid, v_->top.mem_cmd_we, v_->top.mem_cmd_addr,
                        v_->top.mem_wdata_valid, v_->top.mem_wdata_data, v_->top.mem_wdata_we);
    }
    v_->top.clk = v_->top.clk_pix = 1;
    v_->top.eval();
    v_->dump(cycles_ * 10 + 5);
    cycles_++;
    if (memory_) {
        memory_->edge();
    }
    if (pixel_edge) {
        vga_monitor_sample(&monitor_, v_->top.vga_hsync_n, v_->top.vga_vsync_n, v_->top.vga_r,
                           v_->top.vga_g, v_->top.vga_b);
    }
#endif
    if (background_every_ != 0 && --background_left_ == 0) {
        background_left_ = background_every_;
        background_();
    }
}

bool GpuSim::throttle_frame(unsigned percent, uint64_t seed)
{
    if (percent > 100) {
        return false;
    }
    if (memory_) {
        memory_->throttle(percent, seed);
        return true;
    }
    if (!fast_display()) {
        return false;
    }
    throttle_percent_ = percent;
    throttle_rng_ = Rng{seed};
    return true;
}

bool GpuSim::stall_memory(uint64_t clocks)
{
    if (!memory_) {
        return false;
    }
    memory_->stall(cycles_, clocks);
    return true;
}

std::string GpuSim::memory_error() const
{
    return memory_ ? memory_->error() : std::string{};
}

uint64_t GpuSim::memory_words_read() const
{
    return memory_ ? memory_->words_read() : 0;
}

uint64_t GpuSim::memory_words_written() const
{
    return memory_ ? memory_->words_written() : 0;
}

unsigned GpuSim::memory_word_bytes()
{
    return GPU_BUILD_FRAME_DRAM != 0 ? NativePortModel::WORD_BYTES : 0;
}

void GpuSim::write(uint32_t offset, uint32_t value)
{
    v_->top.bus_valid = 1;
    v_->top.bus_write = 1;
    v_->top.bus_addr = offset >> 2;
    v_->top.bus_wdata = value;
    tick();
    v_->top.bus_valid = 0;
    v_->top.bus_write = 0;
}

uint32_t GpuSim::read(uint32_t offset)
{
    v_->top.bus_valid = 1;
    v_->top.bus_write = 0;
    v_->top.bus_addr = offset >> 2;
    tick();  // the request is taken on this edge; bus_rdata is valid in the cycle after it
    v_->top.bus_valid = 0;
    return v_->top.bus_rdata;
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

void GpuSim::arm_capture()
{
    if (fast_display()) {
        show_front_bank();
    } else {
        vga_monitor_arm(&monitor_);
    }
}

bool GpuSim::wait_capture(uint64_t max_cycles)
{
    if (fast_display()) {
        return true;
    }
    const uint64_t limit = cycles_ + max_cycles;
    while (!monitor_.frame_ready && cycles_ < limit && monitor_.error[0] == '\0') {
        tick();
    }
    return monitor_.frame_ready && monitor_.error[0] == '\0';
}

// ---- back_buffer: the framebuffer's arrays, as Verilator names them ----
// gpu_framebuffer.v: bank b is a main RAM of whole 1024-word blocks plus a tail RAM for the rest (none
// when the bank is whole blocks, at SPAN_W = 1); a word holds SPAN_W pixels, pixel i in bits
// [8i +: 8]; bank !front_q is the back bank. A renamed array is a compile error here, not a wrong
// reading; SPAN_W is derived from the arrays' depths and checked against their word width.
// With the write mask (ENABLE_WMASK) both banks are one RAM of 2 x WORDS words instead, bank b
// at words [b * WORDS, (b + 1) * WORDS) (g_merged).
#define GPU_FB_MAIN(bank) \
    GPU_CORE_NAME(g_frame_bram__DOT__u_framebuffer__DOT__g_split__DOT__g_bank__BRA__##bank##__KET____DOT__u_main__DOT__mem)
#define GPU_FB_TAIL(bank) \
    GPU_CORE_NAME(g_frame_bram__DOT__u_framebuffer__DOT__g_split__DOT__g_bank__BRA__##bank##__KET____DOT__g_tail__DOT__u_tail__DOT__mem)
#define GPU_FB_BOTH GPU_CORE_NAME(g_frame_bram__DOT__u_framebuffer__DOT__g_merged__DOT__u_both__DOT__mem)
#define GPU_FB_FRONT GPU_CORE_NAME(g_frame_bram__DOT__u_framebuffer__DOT__front_q)
#define GPU_PALETTE GPU_CORE_NAME(u_palette__DOT__mem)
// The strip buffer (STRIP_ROWS > 0, gpu_strip_buffer.v): its colour RAM (words of SPAN_W pixels;
// bank b's words from b times half its depth on), the flush's state, and the raster's open strip.
#define GPU_STRIP_RAM GPU_CORE_NAME(g_strips__DOT__u_strips__DOT__colour_mem)
#define GPU_STRIPS(reg) GPU_CORE_NAME(g_strips__DOT__u_strips__DOT__##reg)
#define GPU_RASTER(reg) GPU_CORE_NAME(u_raster__DOT__##reg)

namespace {

template <class R, class = void>
struct HasTail : std::false_type {};
template <class R>
struct HasTail<R, std::void_t<decltype(std::declval<const R &>().GPU_FB_TAIL(0))>> : std::true_type {};

template <class R, class = void>
struct HasBoth : std::false_type {};
template <class R>
struct HasBoth<R, std::void_t<decltype(std::declval<const R &>().GPU_FB_BOTH)>> : std::true_type {};

template <class T, std::size_t D>
constexpr std::size_t depth(const VlUnpacked<T, D> &)
{
    return D;
}

template <class T, std::size_t D>
void copy_words(const VlUnpacked<T, D> &mem, std::size_t first_word, unsigned span_w, uint8_t *pixels)
{
    if (sizeof(T) < span_w) {  // the array is not what gpu_framebuffer.v says it is
        std::fprintf(stderr, "gpusim: framebuffer words of %zu bytes for %u pixels\n", sizeof(T), span_w);
        std::abort();
    }
    for (std::size_t w = 0; w < D; w++) {
        for (unsigned i = 0; i < span_w; i++) {
            pixels[(first_word + w) * span_w + i] = lane(mem[w], i);
        }
    }
}

template <class Main, class Tail>
void copy_bank(const Main &main, const Tail *tail, uint8_t *pixels)
{
    const std::size_t words = depth(main) + (tail ? depth(*tail) : 0);
    const unsigned span_w = static_cast<unsigned>(GPU_BUILD_FB_WIDTH * GPU_BUILD_FB_HEIGHT / words);
    if (span_w * words != GPU_BUILD_FB_WIDTH * GPU_BUILD_FB_HEIGHT) {
        std::fprintf(stderr, "gpusim: a framebuffer bank of %zu words\n", words);
        std::abort();
    }
    copy_words(main, 0, span_w, pixels);
    if (tail) {
        copy_words(*tail, depth(main), span_w, pixels);
    }
}

// Bank `bank` of the merged RAM: its words from bank * WORDS on.
template <class T, std::size_t D>
void copy_merged_bank(const VlUnpacked<T, D> &mem, unsigned bank, uint8_t *pixels)
{
    const std::size_t words = D / 2;
    const unsigned span_w = static_cast<unsigned>(GPU_BUILD_FB_WIDTH * GPU_BUILD_FB_HEIGHT / words);
    if (span_w * words * 2 != 2u * GPU_BUILD_FB_WIDTH * GPU_BUILD_FB_HEIGHT || sizeof(T) < span_w) {
        std::fprintf(stderr, "gpusim: a two-bank framebuffer RAM of %zu words\n", D);
        std::abort();
    }
    for (std::size_t w = 0; w < words; w++) {
        for (unsigned i = 0; i < span_w; i++) {
            pixels[w * span_w + i] = lane(mem[bank * words + w], i);
        }
    }
}

template <class R>
void read_bank(const R &root, bool back_is_1, uint8_t *pixels)
{
    if constexpr (HasBoth<R>::value) {
        copy_merged_bank(root.GPU_FB_BOTH, back_is_1 ? 1u : 0u, pixels);
    } else if constexpr (HasTail<R>::value) {
        if (back_is_1) {
            copy_bank(root.GPU_FB_MAIN(1), &root.GPU_FB_TAIL(1), pixels);
        } else {
            copy_bank(root.GPU_FB_MAIN(0), &root.GPU_FB_TAIL(0), pixels);
        }
    } else {
        using Main = std::decay_t<decltype(root.GPU_FB_MAIN(0))>;
        if (back_is_1) {
            copy_bank(root.GPU_FB_MAIN(1), static_cast<const Main *>(nullptr), pixels);
        } else {
            copy_bank(root.GPU_FB_MAIN(0), static_cast<const Main *>(nullptr), pixels);
        }
    }
}

// Strip `words` spans of bank `bank` of the strip buffer over the frame's spans from `base` on.
template <class R>
void overlay_strip(const R &root, unsigned bank, std::size_t base, std::size_t words, uint8_t *pixels)
{
    constexpr unsigned span_w = GPU_BUILD_SPAN_W;
    const auto &mem = root.GPU_STRIP_RAM;
    const std::size_t bank_words = depth(mem) / 2;
    if (words > bank_words || (base + words) * span_w > std::size_t{GPU_BUILD_FB_WIDTH} * GPU_BUILD_FB_HEIGHT) {
        std::fprintf(stderr, "gpusim: a strip of %zu spans at span %zu\n", words, base);
        std::abort();
    }
    for (std::size_t w = 0; w < words; w++) {
        for (unsigned i = 0; i < span_w; i++) {
            pixels[(base + w) * span_w + i] = lane(mem[bank * bank_words + w], i);
        }
    }
}

// One span the flush has read and not yet moved (its queue's head or tail, or the word arriving).
template <class T>
void overlay_span(const T &word, std::size_t frame_span, uint8_t *pixels)
{
    for (unsigned i = 0; i < GPU_BUILD_SPAN_W; i++) {
        pixels[frame_span * GPU_BUILD_SPAN_W + i] = lane(word, i);
    }
}

// The back frame as it will be once the strip buffer has written what it holds: the frame's bank,
// then the strip being flushed, then the open strip, which is newer (a strip opens only once the
// other bank's flush is over). The flush clears each span as it reads it: its spans not yet read
// are in the bank (from rd_addr_q on, at rd_frame_q), those read and not yet moved in its queue.
template <class R>
void overlay_strips(const R &root, uint8_t *pixels)
{
    if constexpr (GPU_BUILD_STRIP_ROWS > 0) {
        if (root.GPU_STRIPS(job_q)) {
            const std::size_t bank_words = depth(root.GPU_STRIP_RAM) / 2;
            const std::size_t unread = root.GPU_STRIPS(issue_left_q);
            const std::size_t first = root.GPU_STRIPS(rd_addr_q);
            if (first + unread > bank_words) {
                std::fprintf(stderr, "gpusim: a flush of %zu spans from span %zu\n", unread, first);
                std::abort();
            }
            for (std::size_t w = 0; w < unread; w++) {
                overlay_span(root.GPU_STRIP_RAM[root.GPU_STRIPS(job_bank_q) * bank_words + first + w],
                             root.GPU_STRIPS(rd_frame_q) + w, pixels);
            }
            if (root.GPU_STRIPS(inflight_q)) {
                overlay_span(root.GPU_STRIPS(arriving_q), root.GPU_STRIPS(inflight_frame_q), pixels);
            }
            if (root.GPU_STRIPS(tail_valid_q)) {
                overlay_span(root.GPU_STRIPS(tail_data_q), root.GPU_STRIPS(tail_addr_q), pixels);
            }
            if (root.GPU_STRIPS(head_valid_q)) {
                overlay_span(root.GPU_STRIPS(head_data_q), root.GPU_STRIPS(head_addr_q), pixels);
            }
        }
        if (root.GPU_RASTER(open_q)) {
            overlay_strip(root, root.GPU_RASTER(open_bank_q), root.GPU_RASTER(open_base_q),
                          root.GPU_RASTER(open_words_q), pixels);
        }
    }
}

// FRAME_DRAM (gpu_core.v g_frame_dram; gpu_top.v g_frame_dram.u_frames, gpu_frame_dram.v): the
// bank shown, and the flush queue's spans whose data the memory has not taken yet.
#define GPU_DRAM_FRONT GPU_CORE_NAME(g_frame_dram__DOT__front_q)
#define GPU_DRAM_Q(reg) gpu_top__DOT__g_frame_dram__DOT__u_frames__DOT__##reg

template <class R>
bool front_bank(const R &root)
{
    if constexpr (GPU_BUILD_FRAME_DRAM != 0) {
        return root.GPU_DRAM_FRONT != 0;
    } else {
        return root.GPU_FB_FRONT != 0;
    }
}

// The pin path's flush queue over the frame (a span's words from the first the memory has not
// taken): newer than the memory, older than any strip still in the strip buffer.
template <class R>
void overlay_flush_queue(const R &root, unsigned back, uint8_t *pixels)
{
    constexpr unsigned span_words = GPU_BUILD_SPAN_W / kWordPixels;
    constexpr unsigned depth = 4;  // gpu_frame_dram's SPAN_Q
    unsigned entry = root.GPU_DRAM_Q(dat_q), word = root.GPU_DRAM_Q(dat_lane_q);
    for (; entry != root.GPU_DRAM_Q(tail_q); entry = (entry + 1) % (2 * depth), word = 0) {
        const uint32_t first = root.GPU_DRAM_Q(q_addr)[entry % depth];
        for (; word < span_words; word++) {
            const uint32_t addr = first + word - kFrameBase;
            const uint32_t pixel = (addr % kFrameWords) * kWordPixels;
            if (addr >= 2 * kFrameWords) {
                std::fprintf(stderr, "gpusim: a queued span at native word 0x%x\n", first);
                std::abort();
            }
            if (addr / kFrameWords != back) {  // the frame now shown, written before its swap
                continue;
            }
            for (unsigned i = 0; i < kWordPixels; i++) {
                pixels[pixel + i] = lane(root.GPU_DRAM_Q(q_data)[entry % depth], kWordPixels * word + i);
            }
        }
    }
}

}  // namespace

void GpuSim::read_frame(bool bank, uint8_t *pixels) const
{
    if constexpr (GPU_BUILD_FRAME_DRAM != 0) {
        if (fast_display()) {
            std::copy_n(&fast_frames_[bank ? kFramePixels : 0], kFramePixels, pixels);
            return;
        }
        for (uint32_t i = 0; i < kFrameWords; i++) {
            const NativePortModel::Word word = *memory_->word(kFrameBase + (bank ? kFrameWords : 0) + i);
            for (uint32_t b = 0; b < kWordPixels; b++) {
                pixels[kWordPixels * i + b] = lane(word, b);
            }
        }
    } else {
        read_bank(*v_->top.rootp, bank, pixels);
    }
}

void GpuSim::back_buffer(uint8_t *pixels) const
{
    const auto &root = *v_->top.rootp;
    read_frame(!front_bank(root), pixels);
    if constexpr (GPU_BUILD_FRAME_DRAM != 0 && !GPUSIM_FAST_DISPLAY) {
        overlay_flush_queue(root, front_bank(root) ? 0 : 1, pixels);
    }
    overlay_strips(root, pixels);
}

// The front bank through the palette (RGB444, each channel times 17 as the monitor model takes the
// pins), each pixel scale x scale: what gpu_vga would scan out of it.
void GpuSim::show_front_bank()
{
    static uint8_t front[GPU_BUILD_FB_WIDTH * GPU_BUILD_FB_HEIGHT];
    constexpr int scale = VGA_W / GPU_BUILD_FB_WIDTH;
    const auto &root = *v_->top.rootp;
    read_frame(front_bank(root), front);
    static_assert(VGA_W == scale * GPU_BUILD_FB_WIDTH && VGA_H == scale * GPU_BUILD_FB_HEIGHT,
                  "gpu_vga shows each pixel scale x scale");
    for (int y = 0; y < VGA_H; y++) {
        for (int x = 0; x < VGA_W; x++) {
            const uint32_t rgb444 = root.GPU_PALETTE[front[(y / scale) * GPU_BUILD_FB_WIDTH + x / scale]];
            uint8_t *out = &monitor_.rgb[(y * VGA_W + x) * 3];
            out[0] = static_cast<uint8_t>(((rgb444 >> 8) & 15) * 17);
            out[1] = static_cast<uint8_t>(((rgb444 >> 4) & 15) * 17);
            out[2] = static_cast<uint8_t>((rgb444 & 15) * 17);
        }
    }
}
