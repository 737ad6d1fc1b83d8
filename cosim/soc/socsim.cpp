// socsim: the whole SoC in one Verilated model — soc_top (VexRiscv with its caches, the Wishbone
// bus, the on-chip RAM, the UART, SYS and the GPU with its VGA output) — with the outside world the
// board would have, at its pins: a UART terminal on uart_tx/uart_rx at the real baud rate and a VGA
// monitor (cosim/vga_monitor) on the VGA pins. Unlike `gpusim cosim`, nothing is replayed: the
// firmware's own bus traffic drives the GPU, cycle by cycle. soc_top's scan-out clock is tied to its
// system clock (PIX_CLK_HZ = CLK_HZ).
//
// Built with SOCSIM_BOARD_ULX3S (socsim.mk's board build), the model is the ULX3S build instead:
// boards/ulx3s/ulx3s_system, everything between the board's PLL and its pins, on its three clocks
// (system, 25 MHz pixel, 125 MHz TMDS, as the PLL makes them, unlocked for the first microsecond),
// and the monitor sees what the GPDI connector carries: the four TMDS channels' bit pairs (the
// ODDRX1F inputs), decoded by cosim/soc/tmds_decoder — which checks every symbol against the DVI
// encoding, DC balance included — back into syncs and colours. The frames it writes are those of
// the VGA build, byte for byte, when the board's video path is right. With SOCSIM_SDRAM as well
// (socsim.mk's ulx3s-sdram system, cosim/soc/ulx3s_sdram_sim.sv), that board build with LiteDRAM
// on its SDRAM ports, the chip and the flash played as in the system with SDRAM below.
//
//   socsim --fw FILE.elf | --hex FILE [--frames DIR] [--uart-log FILE] [--summary FILE]
//          [--keys-at N:TEXT]... [--reply PROMPT=TEXT]... [--max-cycles N] [--stop-frames N]
//          [--no-model-check] [--uart-pty LINK] [--window] [--window-fps N] [--trace FILE.fst [--trace-frame N]]
//          [--profile FILE --profile-mark ADDR]
//
// The program: RAM_INIT's format (one 32-bit hex word per line from address 0; --fw FILE.elf reads
// FILE.elf.hex, the soc platform's post-link output), loaded at time 0 through soc_ram's
// simulation plusarg +ram_init=FILE. Loading at run time keeps one simulator per RTL configuration
// (RAM size and span width are parameters, -G at build time: a Verilator build takes minutes) for
// every image, instead of one build per image with RAM_INIT.
//
// What the harness sees besides the pins comes from taps bound into gpu_top and VexRiscv
// (socsim_taps.sv): the GPU's bus writes, which also feed the golden model (cosim/model_check), and
// FRAME_COUNT, whose every change arms the monitor: the first complete VGA frame after a swap is
// captured, compared with the model's front buffer as it was at the swap, and written as
// FRAMES_DIR/NNNN.png — the names and bytes `gpusim cosim` writes. The model's further writes wait
// until that frame is compared, since the firmware may already draw (and, in the model, swap) the
// next frame while the VGA still shows this one. The read-only registers the firmware reads after
// a batch (ERRORS, the PERF_* counters but the cycle and span counts, STATUS, ...) are compared
// with the model's too (registers_model_checked in the summary).
//
// Waves (`make waves PLATFORM=soc`; a simulator built with SOCSIM_TRACE=1 and --trace-fst, socsim.mk's
// trace build): --trace FILE.fst writes every signal at both clock edges (time in ps) from the swap
// of frame N-1 (--trace-frame N, default 0: from time 0) until frame N is captured, when the file is
// closed: the frame's work on the CPU and the GPU, its swap and its scan-out (and, from the start,
// the scan-out of frame N-1, which runs while frame N is drawn). Other builds refuse --trace.
//
// Keys: --keys-at N:TEXT starts sending TEXT on uart_rx when the GPU takes its Nth DOORBELL write
// (the point where `gpusim cosim` types it; fF:TEXT the doorbell that starts frame F, keys_at.h);
// if bytes are still on the line when the firmware next
// reads UART DATA after the following swap, the firmware's frame saw part of them, so the run would
// differ from co-simulation: a warning, counted as keys_late in the summary. With a terminal on
// stdin the keystrokes are sent as well (cosim/uart_terminal); Ctrl-C ends the run. With
// --uart-pty LINK the line is also a pseudo-terminal (cosim/uart_pty): what a client writes there
// is queued on uart_rx (at most kPtyQueue bytes ahead of the line, so that the pty holds a fast
// client back instead of this process buffering without bound), and every byte decoded from
// uart_tx goes to the client as it came. --reply PROMPT=TEXT (cosim/soc/uart_reply) answers a
// prompt instead of a doorbell: TEXT is sent each time the text from uart_tx ends with PROMPT, as
// the smoke program (tests/soc/smoke.c) asks for its receiver's tests.
//
// USB (a build with the keyboard host, socsim.mk's -DSOCSIM_USB and soc_top's USB_HOST): a low-speed
// keyboard (cosim/usb/usb_kbd_device.h, written from the USB and HID specifications, sharing no code
// with the host) is plugged into the USB pins at time 0 (--usb-unplugged: none) and stepped after
// every rising edge of the system clock, where the host's registered outputs change; the lines it
// and the host make are what the host's synchronisers sample at the next one. --usb-keys-at N:TEXT
// types TEXT on it from the GPU's Nth DOORBELL write: the model's reports for TEXT (a press and a
// release a key), one a poll, each release left out where the next press shares no key with the
// one before (a report of a new key alone releases the last one: a key a poll instead of two). Every event the firmware takes from USB KEY is printed ("socsim: usb
// key ..." with the doorbells before it: the UART's --keys-at of the same key at that doorbell
// reaches the same frame). The keyboard's first violation of the specifications ends the run.
//
// The run ends when the firmware writes SYS EXIT (soc_top's exit_valid): the process exits with its
// status (0..255); or, with --stop-frames N, with status 0 once N frames were captured and compared
// (a board's firmware runs until Q: make netlist-sim's reference frames). A harness failure — a frame that differs from the model or cannot be captured,
// the cycle limit, SIGINT/SIGTERM — prints "socsim: error: ..." and exits 1; usage errors exit 2.
// --summary FILE holds the outcome as key=value lines, with the keys of `gpusim cosim --summary`
// and the SoC's own counts and pins: exit_valid, the LEDs (the VGA build), the vertical syncs the
// monitor saw (vga_vsyncs, with or without a swap), the replies sent. Simulation is deterministic:
// the same image gives the same files. The options both simulators take, the frames' path (model
// check, PNG, window, frame line), the failures and the summary's common keys are the harness
// core's (cosim/harness.h), shared with `gpusim cosim`; this file adds the SoC, its RAM image, its
// clocks and pins, its taps and the board's TMDS decoder.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#if defined(SOCSIM_BOARD_ULX3S) && defined(SOCSIM_SDRAM)
#include "Vulx3s_sdram_sim.h"
#include "sdram_pins.h"
#include "spi_flash.h"
#include "tmds_decoder.h"
using SocModel = Vulx3s_sdram_sim;
#elif defined(SOCSIM_BOARD_ULX3S)
#include "Vulx3s_system.h"
#include "tmds_decoder.h"
using SocModel = Vulx3s_system;
#elif defined(SOCSIM_SDRAM)
#include "Vsoc_sdram_sim.h"
#include "sdram_pins.h"
#include "spi_flash.h"
using SocModel = Vsoc_sdram_sim;
#else
#include "Vsoc_top.h"
using SocModel = Vsoc_top;
#endif
#include "svdpi.h"
#include "verilated.h"
#ifndef SOCSIM_TRACE
#define SOCSIM_TRACE 0
#endif
#if SOCSIM_TRACE
#include "verilated_fst_c.h"
#endif

#include "cpu_profile.h"
#include "gpu_build.h"
#include "harness.h"
#include "model_check.h"
#include "uart_line.h"
#include "uart_reply.h"
#ifdef SOCSIM_USB
#include "usb_kbd_device.h"
#endif

extern "C" {
#include "gpu_regs.h"
#include "soc_map.h"
#include "vga_monitor.h"
}

#ifndef SOCSIM_RAM_BYTES
#define SOCSIM_RAM_BYTES SOC_RAM_DEFAULT_BYTES
#endif
#ifndef SOCSIM_CLK_HZ
#define SOCSIM_CLK_HZ SOC_CLK_HZ_DEFAULT
#endif
// The UART's rate: the contract's, or the build's own (mk/builds.toml uart_baud, the RTL's BAUD).
#ifndef SOCSIM_UART_BAUD
#define SOCSIM_UART_BAUD SOC_UART_BAUD
#endif

extern "C" long long socsim_read_instret();  // exported by socsim_cpu_tap
extern "C" long long socsim_read_bus_clocks(unsigned which);  // likewise (SocRun::bus_clocks)

namespace {

struct Options {
    HarnessOptions harness;
    std::string hex;
    uint64_t max_cycles = 3000000000ull;  // 60 s of SoC time at 50 MHz
    uint64_t progress_cycles = 50000000;  // a progress line after this many cycles without a frame
    uint32_t stop_frames = 0;             // --stop-frames N: end after N frames (0: at SYS EXIT only)
    int sdram_fault_a = -1;               // --sdram-fault-a N: the SDRAM's address pin N stuck low
    std::string boot;                     // --boot FILE.hex: the RAM's image, the firmware in the flash
    std::string flash_image;              // --flash FILE: the flash's image at the boot offset
    uint32_t uart_divider = (SOCSIM_CLK_HZ + SOCSIM_UART_BAUD / 2) / SOCSIM_UART_BAUD;  // as soc_uart rounds
    UartReplies replies;
    KeysAt usb_keys_at;           // --usb-keys-at N:TEXT
    bool usb_unplugged = false;                                 // --usb-unplugged
    bool usb_window = false;      // --usb-window: the window's keys on the USB keyboard, not the UART
    std::string profile;          // --profile FILE: the clocks of every instruction (cpu_profile.h)
    uint32_t profile_mark = 0;    // --profile-mark ADDR: the address that starts a frame
};

int usage()
{
    return harness_usage(
        "usage: socsim --fw FILE.elf | --hex FILE [--frames DIR] [--uart-log FILE] [--summary FILE]\n"
        "              [--keys-at N:TEXT]... [--reply PROMPT=TEXT]... [--max-cycles N] [--stop-frames N]\n"
        "              [--no-model-check] [--uart-divider N] [--uart-pty LINK] [--window] [--window-fps N]\n"
        "              [--trace FILE.fst [--trace-frame N]] [--profile FILE --profile-mark ADDR]\n"
        "  --fw FILE.elf      run FILE.elf.hex (the soc build's RAM image); -kernel FILE.elf is the same\n"
        "  --hex FILE         run FILE, a RAM image (one 32-bit hex word per line from address 0)\n"
        "  --reply PROMPT=TEXT  send TEXT on uart_rx each time the text from uart_tx ends with PROMPT\n"
        "                     (\\n a newline, \\f a frame with a low stop bit)\n"
        "  --max-cycles N     give up after N clocks (default 3e9: 60 s at 50 MHz)\n"
        "  --stop-frames N    end with status 0 once N frames were captured (a firmware that runs until Q)\n"
        "  --profile FILE     at the firmware's exit, write each instruction address's clocks, retirements\n"
        "                     and cache refills, summed over the frames between the first and the last\n"
        "                     (a frame starts where ADDR of --profile-mark retires: make profile-soc)\n"
#ifdef SOCSIM_SDRAM
        "  --sdram-fault-a N  the SDRAM chip's address pin A<N> stuck low (0..12): a broken board\n"
        "  --boot FILE.hex    the RAM's image is the boot program FILE.hex (bsp/soc/boot), and the\n"
        "                     firmware (--fw FILE.elf) goes into the flash as FILE.elf.img\n"
        "  --flash FILE       the flash holds FILE at the boot image's offset (default with --boot:\n"
        "                     the firmware's image; without either the flash is erased)\n"
#endif
#ifdef SOCSIM_USB
        "  --usb-keys-at N:TEXT  type TEXT on the USB keyboard from the GPU's Nth DOORBELL write (fF:TEXT:\n"
        "                     from the doorbell that starts frame F, as --keys-at)\n"
        "                     ({UP} {DOWN} {LEFT} {RIGHT} {ESC} ... for keys without a character)\n"
        "  --usb-unplugged    no keyboard on the USB port\n"
        "  --usb-window       with --window: its keys typed on the USB keyboard instead of the UART\n"
#endif
        "  Exit status: the firmware's (SYS EXIT); 1 on a harness error; 2 on a usage error.\n");
}

bool parse(int argc, char **argv, Options &o)
{
    const auto own = [&](const std::string &a, bool has_value, int *i) {
        if (a == "-kernel" && has_value) {
            o.harness.firmware = argv[++*i];
        } else if (a == "--hex" && has_value) {
            o.hex = argv[++*i];
        } else if (a == "--max-cycles" && has_value) {
            o.max_cycles = static_cast<uint64_t>(std::strtod(argv[++*i], nullptr));
        } else if (a == "--profile" && has_value) {
            o.profile = argv[++*i];
        } else if (a == "--profile-mark" && has_value) {
            o.profile_mark = static_cast<uint32_t>(std::strtoul(argv[++*i], nullptr, 0));
        } else if (a == "--stop-frames" && has_value) {
            o.stop_frames = static_cast<uint32_t>(std::strtoul(argv[++*i], nullptr, 0));
#ifdef SOCSIM_SDRAM
        } else if (a == "--sdram-fault-a" && has_value) {
            o.sdram_fault_a = std::atoi(argv[++*i]);
            if (o.sdram_fault_a < 0 || o.sdram_fault_a > 12) {
                std::fprintf(stderr, "socsim: --sdram-fault-a wants an address pin 0..12, got '%s'\n", argv[*i]);
                return HarnessArg::Bad;
            }
        } else if (a == "--boot" && has_value) {
            o.boot = argv[++*i];
        } else if (a == "--flash" && has_value) {
            o.flash_image = argv[++*i];
#endif
#ifdef SOCSIM_USB
        } else if (a == "--usb-keys-at" && has_value) {
            if (!parse_keys_at("socsim", argv[++*i], &o.usb_keys_at)) {
                return HarnessArg::Bad;
            }
            try {
                UsbKbdDevice::reports_for_text(o.usb_keys_at.back().text);  // refuses a key it cannot type
            } catch (const std::invalid_argument &e) {
                std::fprintf(stderr, "socsim: --usb-keys-at: %s\n", e.what());
                return HarnessArg::Bad;
            }
        } else if (a == "--usb-unplugged") {
            o.usb_unplugged = true;
        } else if (a == "--usb-window") {
            o.usb_window = true;
#endif
        } else if (a == "--uart-divider" && has_value) {
            o.uart_divider = static_cast<uint32_t>(std::strtoul(argv[++*i], nullptr, 0));
        } else if (a == "--reply" && has_value) {
            if (!o.replies.add(argv[++*i])) {
                std::fprintf(stderr, "socsim: --reply wants PROMPT=TEXT, got '%s'\n", argv[*i]);
                return HarnessArg::Bad;
            }
        } else {
            return HarnessArg::Other;
        }
        return HarnessArg::Taken;
    };
    if (!harness_parse("socsim", argc, argv, 1, SOCSIM_TRACE != 0, &o.harness, own)) {
        return false;
    }
    if (o.usb_unplugged && (!o.usb_keys_at.empty() || o.usb_window)) {
        std::fprintf(stderr, "socsim: --usb-keys-at and --usb-window type on the keyboard, which --usb-unplugged leaves out\n");
        return false;
    }
    if (o.profile.empty() != (o.profile_mark == 0)) {
        std::fprintf(stderr, "socsim: --profile and --profile-mark go together\n");
        return false;
    }
    if (!o.boot.empty()) {
        o.hex = o.boot;  // the boot program in the RAM, the firmware's image in the flash
        if (o.flash_image.empty() && !o.harness.firmware.empty()) {
            o.flash_image = o.harness.firmware + ".img";
        }
    } else if (!o.harness.firmware.empty()) {
        o.hex = o.harness.firmware + ".hex";  // --fw FILE.elf: its RAM image
    }
    return !o.hex.empty() && o.uart_divider >= 4;
}

// The model's context: a trace build allows traces from time 0, as Verilator asks of --trace.
VerilatedContext *new_context()
{
    auto *context = new VerilatedContext;
    context->traceEverOn(SOCSIM_TRACE != 0);
    return context;
}

#ifdef SOCSIM_USB
// The boot reports that type TEXT, a key a poll: see the header (--usb-keys-at).
std::vector<UsbKbdReport> usb_reports_for_text(const std::string &text)
{
    const std::vector<UsbKbdReport> all = UsbKbdDevice::reports_for_text(text);
    const auto shares_key = [](const UsbKbdReport &a, const UsbKbdReport &b) {
        for (uint8_t k : a.keys) {
            for (uint8_t l : b.keys) {
                if (k != 0 && k == l) {
                    return true;
                }
            }
        }
        return false;
    };
    std::vector<UsbKbdReport> out;
    for (size_t i = 0; i < all.size(); i++) {
        const bool release = all[i] == UsbKbdReport();
        if (release && !out.empty() && i + 1 < all.size() && !shares_key(out.back(), all[i + 1])) {
            continue;
        }
        out.push_back(all[i]);
    }
    return out;
}

// A terminal's bytes (the window's keys: text, the cursor keys as ESC [ A..D) as --usb-keys-at
// TEXT: the cursor keys by name, '{' doubled; a byte no key of the keyboard types is left out, as
// the firmware ignores a byte it has no key for.
std::string usb_text_from_terminal(const std::string &bytes)
{
    static const char *const kCursor[] = {"{UP}", "{DOWN}", "{RIGHT}", "{LEFT}"};
    std::string out;
    for (size_t i = 0; i < bytes.size(); i++) {
        if (bytes.compare(i, 2, "\x1b[") == 0 && i + 2 < bytes.size() && bytes[i + 2] >= 'A' && bytes[i + 2] <= 'D') {
            out += kCursor[bytes[i + 2] - 'A'];
            i += 2;
            continue;
        }
        const std::string one = bytes[i] == '{' ? "{{" : std::string(1, bytes[i]);
        try {
            UsbKbdDevice::reports_for_text(one);
            out += one;
        } catch (const std::invalid_argument &) {
        }
    }
    return out;
}
#endif

class SocRun;
SocRun *g_run = nullptr;  // the DPI callbacks' target (one run per process)
bool g_profiling = false;  // --profile: the CPU tap reports every retirement (socsim_profiling)
svScope g_cpu_scope = nullptr;

class SocRun : public Harness {
public:
    explicit SocRun(const Options &o)
        : Harness("socsim", o.harness), opt_(o), top_(new SocModel(context_.get())), model_(gpu_build_config()),
          rx_(o.uart_divider), tx_(o.uart_divider), replies_(o.replies)
    {
        g_run = this;
        vga_monitor_reset(&monitor_);
        if (!o.profile.empty()) {
            profile_.reset(new CpuProfile(o.profile_mark));
            g_profiling = true;
        }
    }
    ~SocRun() override
    {
        trace_close();
        terminal_.restore();
        top_->final();
        g_run = nullptr;
    }
    int run();

    // DPI events (socsim_taps.sv), during an eval.
    void on_gpu_write(uint32_t offset, uint32_t value);
    void on_gpu_read(uint32_t offset, uint32_t value);
    void on_gpu_swap(uint32_t frame_count);
    void on_gpu_underflows(uint32_t count)
    {
        if (scanout_underflows_ == 0 || count % 100 == 0) {  // the first, then every hundredth
            std::printf("socsim: scan-out underflow %u at cycle %llu (a display line shown in the underflow colour)\n",
                        count, static_cast<unsigned long long>(cycles_));
        }
        scanout_underflows_ = count;
    }
    void on_row_fetch(uint32_t clocks) { worst_row_fetch_ = clocks; }
    void on_bus_cycle(bool ibus, uint32_t word_addr, bool write);
    void on_retire(uint32_t pc)  // only while profiling
    {
        profile_->on_retire(pc, cycles_, [this] { return instret(); });
    }
    void on_uart_data_read();
    void on_usb_key_read(uint32_t value);

private:
    struct KeyWatch {
        uint32_t doorbell;
        bool sent = false;        // queued on uart_rx
        bool after_swap = false;  // the frame that saw the doorbell has swapped
        bool done = false;
    };

    // The harness's ends (harness.h): the last UART output, the terminal, the speed line.
    void stop_parts() override;
    HarnessCounts counts() const override
    {
        HarnessCounts c;
        c.batches = doorbells_;
        c.gpu_resets = resets_;
        c.gpu_cycles = cycles_;
        return c;
    }
    void summary_keys(FILE *f) const override;
    bool load_ram(std::string *error);
    void tick();
    void clock_once();   // the model's clocks up to the system clock's next rising edge
    void uart_byte(uint8_t b);
    void vga_sample(int hsync_n, int vsync_n, int r, int g, int b);
    bool finish_frame(std::string *error, const char **kind);
    uint64_t instret() const;
    // socsim_cpu_tap's bus counts: the clocks of 0 the instruction bus's cycles, 1 data-cache
    // refills, 2 stores, 3 uncached loads; 4 the number of stores.
    uint64_t bus_clocks(unsigned which) const;
    bool trace_open(std::string *error);
    void trace_close();
    void trace_dump(uint64_t time_ps)
    {
#if SOCSIM_TRACE
        if (fst_ != nullptr) {
            fst_->dump(time_ps);
        }
#else
        (void)time_ps;
#endif
    }

    const Options &opt_;
    std::unique_ptr<VerilatedContext> context_{new_context()};
    std::unique_ptr<SocModel> top_;
#ifdef SOCSIM_BOARD_ULX3S
    // The board's clocks in picoseconds: the time of each one's next edge.
    static constexpr uint64_t kTmdsHalfPs = 4000, kPixHalfPs = 20000, kLockPs = 1000000;
    static constexpr uint64_t kSysHalfPs = 500000000000ull / SOCSIM_CLK_HZ;
    uint64_t next_sys_ps_ = kSysHalfPs, next_pix_ps_ = kPixHalfPs, next_tmds_ps_ = kTmdsHalfPs;
#ifdef SOCSIM_SDRAM
    static_assert(kSysHalfPs % 2 == 0, "clk_sys2x's half period in whole picoseconds");
    uint64_t next_sys2x_ps_ = kSysHalfPs;   // clk_sys2x: twice clk_sys, rising with clk_sys's first
#endif
    TmdsDecoder tmds_;
    void tmds_clock();
#endif
#ifdef SOCSIM_SDRAM
    // The SDRAM chip on soc_sdram_sim's pins (cosim/sdram/sdram_chip.h), clocked at clk2x's rate a
    // whole clk2x period behind the PHY (its edge at clk2x's rising edge, with the pins as they were
    // just before it): the phase docs/sdram.md argues. Its first violation ends the run.
    std::unique_ptr<SdramChip> sdram_;
    void sdram_clock(const SdramPins &before);
    // The SPI flash on soc_top's flash pins (cosim/flash/spi_flash.h), stepped after each rising
    // edge of the system clock, where soc_spiflash's registered pins change; its MISO is what the
    // reader samples at the next one. Its first violation ends the run.
    std::unique_ptr<SpiFlash> flash_;
    void flash_step(uint64_t t_ps);
#endif
#ifdef SOCSIM_USB
    // The keyboard on the USB pins (cosim/usb/usb_kbd_device.h): see the header.
    std::unique_ptr<UsbKbdDevice> kbd_;
    void usb_step(uint64_t t_ps);
#endif
    uint32_t usb_keys_read_ = 0;  // events the firmware took from USB KEY
    std::string video_error_;   // the board's: the first TMDS error, or a colour it cannot have sent
    ModelCheck model_;
    UartLineDecoder rx_;   // the firmware's output: soc_top's uart_tx
    UartLineSender tx_;    // keys: soc_top's uart_rx
    static constexpr size_t kPtyQueue = 64;  // bytes from the pty queued ahead of the line, at most
    vga_monitor monitor_;
    std::string ram_init_arg_;

    uint64_t cycles_ = 0;
    double t_start_ = 0;
    uint64_t last_frame_cycle_ = 0;
    uint64_t last_progress_cycle_ = 0;
    uint32_t ctrl_ = 0;                // the last CTRL written
    uint64_t swap_cycle_ = 0;          // of the swap whose frame is being captured
    uint64_t prev_swap_cycle_ = 0;     // of the swap before it
    uint64_t swap_doorbell_cycle_ = 0; // the DOORBELL of the last batch with CTRL.SWAP
    uint64_t frame_doorbell_cycle_ = 0;  // that of the frame being captured
    uint64_t icache_at_frame_ = 0, dcache_at_frame_ = 0;
    uint64_t sdram_busy_ = 0, sdram_busy_at_frame_ = 0;  // cycles with a request on the SDRAM port
    bool arm_pending_ = false;     // a swap happened in this cycle's eval: arm the monitor after it
    bool capture_pending_ = false; // armed, waiting for the frame
    std::vector<KeyWatch> watches_;
    KeysSchedule uart_keys_{hopt_.keys_at};  // --keys-at
#ifdef SOCSIM_USB
    KeysSchedule usb_keys_{opt_.usb_keys_at};  // --usb-keys-at
    // TEXT's reports queued on the keyboard from now (usb_reports_for_text: a key a poll).
    void type_on_usb(const std::string &text)
    {
        for (const UsbKbdReport &r : usb_reports_for_text(text)) {
            kbd_->queue_report(r, cycles_ * (1000000000000ull / SOCSIM_CLK_HZ));
        }
    }
#endif

    uint32_t doorbells_ = 0, resets_ = 0, keys_late_ = 0;
    uint32_t scanout_underflows_ = 0;  // the GPU's SCANOUT_UNDERFLOWS (frames in the SDRAM)
    uint32_t worst_row_fetch_ = 0;     // the scan-out's slowest row fetch, clocks (its deadline: a line)
    uint32_t last_tag_ = 0;       // the last DOORBELL value
    bool batch_done_ = true;      // the firmware has read DONE_SEQ == last_tag_ since (or no batch yet)
    uint64_t regs_checked_ = 0;   // register reads compared with the model
    std::string reg_error_;       // the first register that differed
    uint64_t icache_refills_ = 0, dcache_refills_ = 0, uart_reads_ = 0;
    uint64_t bus_at_frame_[5] = {0, 0, 0, 0, 0};  // bus_clocks() at the last frame's report
    uint64_t vsyncs_ = 0;          // vertical sync pulses at the monitor: the scan-out runs
    bool vsync_n_ = true;
    UartReplies replies_;          // --reply: a copy, since it keeps what was received
    uint32_t swaps_ = 0;
    std::unique_ptr<CpuProfile> profile_;  // --profile
#if SOCSIM_TRACE
    std::unique_ptr<VerilatedFstC> fst_;  // open while frame trace_frame is traced
#endif
};

void SocRun::on_gpu_write(uint32_t offset, uint32_t value)
{
    if (hopt_.check_model) {
        model_.write(offset, value);  // held from a swap until its frame is compared (on_gpu_swap)
    }
    if (offset == GPU_REG_RESET) {
        resets_++;
    }
    if (offset == GPU_REG_CTRL) {
        ctrl_ = value;
    }
    if (offset != GPU_REG_DOORBELL) {
        return;
    }
    doorbells_++;
    last_tag_ = value;
    batch_done_ = false;
    const bool swaps = (ctrl_ & GPU_CTRL_SWAP_MASK) != 0;
    if (swaps) {
        swap_doorbell_cycle_ = cycles_;
    }
    uart_keys_.doorbell(swaps, [this](const std::string &text) {
        tx_.queue(text);
        KeyWatch w{doorbells_};
        w.sent = true;
        watches_.push_back(w);
    });
#ifdef SOCSIM_USB
    usb_keys_.doorbell(swaps, [this](const std::string &text) { type_on_usb(text); });
#endif
}

// A register the firmware reads, against the model's: only once the firmware has seen the last
// batch done (the model finishes a batch at its doorbell, the RTL later) and while no model write
// is held back, and never the implementation-specific counters (as ModelCheck::compare_registers).
void SocRun::on_gpu_read(uint32_t offset, uint32_t value)
{
    if (offset == GPU_REG_DONE_SEQ && value == last_tag_) {
        batch_done_ = true;
    }
    if (!hopt_.check_model || !batch_done_ || model_.holds_writes() || !reg_error_.empty() ||
        offset == GPU_REG_PERF_BUSY_CYCLES || offset == GPU_REG_PERF_SPANS_VISITED) {
        return;
    }
    bool read_only = false;
    for (int i = 0; i < kReadOnlyRegCount; i++) {
        read_only = read_only || kReadOnlyRegs[i] == offset;
    }
    if (!read_only) {
        return;
    }
    regs_checked_++;
    const uint32_t model = gpu_model_read(model_.model(), offset);
    if (model != value) {
        char text[160];
        std::snprintf(text, sizeof text, "register 0x%03X read by the firmware at cycle %llu: RTL 0x%08X, model 0x%08X",
                      offset, static_cast<unsigned long long>(cycles_), value, model);
        reg_error_ = text;
    }
}

void SocRun::on_gpu_swap(uint32_t)
{
    arm_pending_ = true;
    model_.hold_writes();
    prev_swap_cycle_ = swap_cycle_;
    swap_cycle_ = cycles_;
    frame_doorbell_cycle_ = swap_doorbell_cycle_;
    for (auto &w : watches_) {
        w.after_swap = true;
    }
}

void SocRun::on_bus_cycle(bool ibus, uint32_t word_addr, bool write)
{
    // A cycle to a cached address that is not a store is a cache-line refill (stores go through).
    if (ibus) {
        icache_refills_++;
    } else if (!write && (word_addr << 2) < 0x80000000u) {
        dcache_refills_++;
    } else {
        return;
    }
    if (profile_) {
        profile_->on_refill(ibus);
    }
}

void SocRun::on_uart_data_read()
{
    uart_reads_++;
    for (auto &w : watches_) {
        if (w.after_swap && !w.done) {
            w.done = true;
            if (tx_.busy()) {
                keys_late_++;
                std::printf("socsim: warning: the keys of doorbell %u were still being sent when the next "
                            "frame read the UART (cycle %llu): this run differs from co-simulation\n",
                            w.doorbell, static_cast<unsigned long long>(cycles_));
            }
        }
    }
}

// A key event the firmware popped from USB KEY, with the doorbells before it: the UART's
// --keys-at of that doorbell reaches the same frame (tests/soc/usb_keys.sh replays them so).
void SocRun::on_usb_key_read(uint32_t value)
{
    usb_keys_read_++;
    std::printf("socsim: usb key 0x%02x %s after doorbell %u (cycle %llu)\n",
                (value >> SOC_USB_KEY_USAGE_LSB) & (SOC_USB_KEY_USAGE_MASK >> SOC_USB_KEY_USAGE_LSB),
                (value & SOC_USB_KEY_PRESS_MASK) ? "press" : "release", doorbells_,
                static_cast<unsigned long long>(cycles_));
}

uint64_t SocRun::instret() const
{
    if (g_cpu_scope == nullptr) {
        return 0;
    }
    svSetScope(g_cpu_scope);
    return static_cast<uint64_t>(socsim_read_instret());
}

uint64_t SocRun::bus_clocks(unsigned which) const
{
    if (g_cpu_scope == nullptr) {
        return 0;
    }
    svSetScope(g_cpu_scope);
    return static_cast<uint64_t>(socsim_read_bus_clocks(which));
}

// The image goes in through soc_ram's own simulation hook, +ram_init=FILE ($readmemh at time 0),
// after a check here that it fits the RAM this simulator was built with.
bool SocRun::load_ram(std::string *error)
{
    std::ifstream in(opt_.hex);
    if (!in) {
        *error = "cannot read " + opt_.hex + ": " + std::strerror(errno);
        return false;
    }
    std::string word;
    size_t n = 0;
    while (in >> word) {
        n++;
    }
    if (n * 4 > SOCSIM_RAM_BYTES) {
        *error = opt_.hex + " (" + std::to_string(n * 4) + " bytes) is larger than this simulator's RAM (" +
                 std::to_string(SOCSIM_RAM_BYTES) + " bytes): build socsim with the firmware's SOC_RAM_KIB";
        return false;
    }
    ram_init_arg_ = "+ram_init=" + opt_.hex;
    const char *args[] = {"socsim", ram_init_arg_.c_str()};
    context_->commandArgs(2, args);
    std::printf("socsim: %s: %zu words, RAM %u KiB\n", opt_.hex.c_str(), n, SOCSIM_RAM_BYTES / 1024);
    return true;
}

#ifdef SOCSIM_BOARD_ULX3S
// One system clock: every edge of the three clocks up to and including the system clock's next
// rising one, in time order (edges at the same instant in one eval); the TMDS bit pairs are read
// after each rising edge of the TMDS clock, which the ODDRX1Fs send during the period that follows.
// With SDRAM, clk_sys2x too; the chip is clocked at its rising edges and the flash stepped after
// clk_sys's rising one, as in the system with SDRAM.
void SocRun::clock_once()
{
    for (;;) {
#ifdef SOCSIM_SDRAM
        const uint64_t t = std::min({next_sys_ps_, next_sys2x_ps_, next_pix_ps_, next_tmds_ps_});
        const bool sys2x_rose = next_sys2x_ps_ == t && !top_->clk_sys2x;
        SdramPins before{};
        if (sys2x_rose) {
            before = sdram_pins_of(*top_);   // what the chip samples at clk_sys2x's edge
        }
        if (next_sys2x_ps_ == t) {
            top_->clk_sys2x = !top_->clk_sys2x;
            next_sys2x_ps_ += kSysHalfPs / 2;
        }
#else
        const uint64_t t = std::min({next_sys_ps_, next_pix_ps_, next_tmds_ps_});
#endif
        bool sys_rose = false, sys_fell = false, tmds_rose = false;
        if (next_sys_ps_ == t) {
            top_->clk_sys = !top_->clk_sys;
            sys_rose = top_->clk_sys;
            sys_fell = !sys_rose;
            next_sys_ps_ += kSysHalfPs;
        }
        if (next_pix_ps_ == t) {
            top_->clk_pix = !top_->clk_pix;
            next_pix_ps_ += kPixHalfPs;
        }
        if (next_tmds_ps_ == t) {
            top_->clk_tmds = !top_->clk_tmds;
            tmds_rose = top_->clk_tmds;
            next_tmds_ps_ += kTmdsHalfPs;
        }
        top_->pll_locked = t >= kLockPs;
        top_->eval();
#ifdef SOCSIM_SDRAM
        if (sys2x_rose) {
            sdram_clock(before);
        }
        if (sys_fell) {
            sdram_busy_ += top_->sdram_busy;
        }
        if (sys_rose) {
            flash_step(t);
        }
#else
        (void)sys_fell;
#endif
#ifdef SOCSIM_USB
        if (sys_rose) {
            usb_step(t);
        }
#endif
        trace_dump(t);
        if (tmds_rose) {
            tmds_clock();
        }
        if (sys_rose) {
            break;
        }
    }
}
#else
// One clock of soc_top, the scan-out's clock tied to the system clock (soc.mk); the VGA pins are
// sampled after the edges where vga_pix_stb was high. With SDRAM, clk2x too: it rises as clk falls
// and as clk rises and falls between, and the chip is clocked at its rising edges.
void SocRun::clock_once()
{
    static constexpr uint64_t kHalfPs = 500000000000ull / SOCSIM_CLK_HZ;
    const uint64_t t0 = 2 * kHalfPs * cycles_;
#ifdef SOCSIM_SDRAM
    SdramPins before = sdram_pins_of(*top_);
    top_->clk2x = 1;
#endif
    top_->clk = top_->clk_pix = 0;
    top_->eval();
#ifdef SOCSIM_SDRAM
    sdram_clock(before);
    sdram_busy_ += top_->sdram_busy;
    trace_dump(t0);
    top_->clk2x = 0;
    top_->eval();
    trace_dump(t0 + kHalfPs / 2);
    before = sdram_pins_of(*top_);
    top_->clk2x = 1;
#else
    trace_dump(t0);
#endif
    const bool pixel_edge = top_->vga_pix_stb;  // outputs change on the edge where it is high
    top_->clk = top_->clk_pix = 1;
    top_->eval();
#ifdef SOCSIM_SDRAM
    sdram_clock(before);
    flash_step(t0 + kHalfPs);
    trace_dump(t0 + kHalfPs);
    top_->clk2x = 0;
    top_->eval();
    trace_dump(t0 + 3 * kHalfPs / 2);
#else
    trace_dump(t0 + kHalfPs);
#endif
#ifdef SOCSIM_USB
    usb_step(t0 + kHalfPs);
#endif
    if (pixel_edge) {
        vga_sample(top_->vga_hsync_n, top_->vga_vsync_n, top_->vga_r, top_->vga_g, top_->vga_b);
    }
}
#endif

#ifdef SOCSIM_SDRAM
// The chip's rising edge, at clk2x's: it samples the pins as they were before the edge (what the
// PHY's output registers set at clk2x's previous rising edge) and drives DQ from now until its next
// edge; the next eval settles it, and the PHY samples it at clk2x's next rising edge.
void SocRun::sdram_clock(const SdramPins &before)
{
    sdram_drive(*top_, sdram_->clock(before));
}

void SocRun::flash_step(uint64_t t_ps)
{
    const SpiFlashOut out = flash_->step(t_ps, top_->flash_cs_n, top_->flash_sck, top_->flash_mosi);
    top_->flash_miso = out.oe && out.miso;  // undriven: the board's pull-up is not modelled, read 0
}
#endif

#ifdef SOCSIM_USB
// The keyboard after a rising edge of the system clock: it sees what the host drives from now on and
// answers until the next edge; the bus's resolved lines go to the host's inputs.
void SocRun::usb_step(uint64_t t_ps)
{
    UsbHostDrive host;
    host.oe = top_->usb_oe;
    host.dp = top_->usb_dp_out;
    host.dm = top_->usb_dn_out;
    const UsbLines lines = UsbKbdDevice::bus(host, kbd_->step(t_ps, host));
    top_->usb_dp_in = lines.dp;
    top_->usb_dn_in = lines.dm;
}
#endif

void SocRun::tick()
{
    top_->uart_rx = tx_.tick();
    clock_once();
    cycles_++;
    uint8_t b;
    if (rx_.sample(top_->uart_tx, &b)) {
        uart_byte(b);
    }
}

#ifdef SOCSIM_BOARD_ULX3S
// A decoded pixel to the monitor, as the VGA pins would give it: ulx3s_system sends each 4-bit
// colour as its nibble twice, so a byte whose halves differ is an error of the video path.
void SocRun::tmds_clock()
{
    TmdsPixel px;
    if (!video_error_.empty() || !tmds_.clock(top_->tmds_d0, top_->tmds_d1, &px)) {
        if (video_error_.empty() && !tmds_.error().empty()) {
            video_error_ = "TMDS: " + tmds_.error();
        }
        return;
    }
    const uint8_t c[3] = {px.r, px.g, px.b};
    for (uint8_t v : c) {
        if ((v >> 4) != (v & 15) && video_error_.empty()) {
            char text[96];
            std::snprintf(text, sizeof text, "colour byte 0x%02X is no 4-bit colour repeated (cycle %llu)", v,
                          static_cast<unsigned long long>(cycles_));
            video_error_ = text;
        }
    }
    vga_sample(px.hsync, px.vsync, px.r >> 4, px.g >> 4, px.b >> 4);
}
#endif

// One pixel to the monitor; the vertical syncs are counted here too, so that a program that never
// swaps (no frame captured) still shows that the scan-out runs.
void SocRun::vga_sample(int hsync_n, int vsync_n, int r, int g, int b)
{
    if (vsync_n_ && !vsync_n) {
        vsyncs_++;
    }
    vsync_n_ = vsync_n != 0;
    vga_monitor_sample(&monitor_, hsync_n, vsync_n, r, g, b);
}

void SocRun::uart_byte(uint8_t b)
{
    replies_.byte(b, &tx_);
    uart_.feed(reinterpret_cast<const char *>(&b), 1);
}

bool SocRun::finish_frame(std::string *error, const char **kind)
{
    capture_pending_ = false;
    // swap: the cycle of the swap, since the previous one; ready: from the previous swap to the
    // doorbell of this frame's last batch (what the frame's work took before its swap waited).
    char detail[320];
    std::snprintf(detail, sizeof detail,
                  "swap at cycle %llu, +%llu | ready +%llu | instructions %llu | refills I$ %llu D$ %llu",
                  static_cast<unsigned long long>(swap_cycle_),
                  static_cast<unsigned long long>(swap_cycle_ - prev_swap_cycle_),
                  static_cast<unsigned long long>(frame_doorbell_cycle_ - prev_swap_cycle_),
                  static_cast<unsigned long long>(instret()),
                  static_cast<unsigned long long>(icache_refills_ - icache_at_frame_),
                  static_cast<unsigned long long>(dcache_refills_ - dcache_at_frame_));
    {
        // Where the core's clocks went beyond one an instruction: its buses' cycles by kind.
        uint64_t bus[5];
        for (unsigned k = 0; k < 5u; k++) {
            bus[k] = bus_clocks(k) - bus_at_frame_[k];
            bus_at_frame_[k] += bus[k];
        }
        const size_t used = std::strlen(detail);
        std::snprintf(detail + used, sizeof detail - used,
                      " | bus clocks I$ %llu D$ %llu stores %llu (%llu) loads %llu",
                      static_cast<unsigned long long>(bus[0]), static_cast<unsigned long long>(bus[1]),
                      static_cast<unsigned long long>(bus[2]), static_cast<unsigned long long>(bus[4]),
                      static_cast<unsigned long long>(bus[3]));
    }
#ifdef SOCSIM_SDRAM
    // The SDRAM's share of the frame's cycles: a request on its port, waiting or being answered.
    const size_t used = std::strlen(detail);
    std::snprintf(detail + used, sizeof detail - used, " | SDRAM busy %llu",
                  static_cast<unsigned long long>(sdram_busy_ - sdram_busy_at_frame_));
    sdram_busy_at_frame_ = sdram_busy_;
#endif
    if (!take_frame(monitor_.rgb, model_, cycles_, detail, error, kind)) {
        return false;
    }
    icache_at_frame_ = icache_refills_;
    dcache_at_frame_ = dcache_refills_;
    last_frame_cycle_ = cycles_;
#if SOCSIM_TRACE
    if (fst_ != nullptr && frames() == hopt_.trace_frame + 1) {
        trace_close();
        std::printf("socsim: trace of frame %u written: %s\n", hopt_.trace_frame, hopt_.trace.c_str());
        std::fflush(stdout);
    }
#endif
    return true;
}

// --trace: see the header. Opened at time 0 (frame 0) or after the swap of frame trace_frame - 1.
bool SocRun::trace_open(std::string *error)
{
#if SOCSIM_TRACE
    fst_.reset(new VerilatedFstC);
    fst_->set_time_unit("1ps");
    fst_->set_time_resolution("1ps");
    top_->trace(fst_.get(), 99);
    fst_->open(hopt_.trace.c_str());
    if (!fst_->isOpen()) {
        fst_.reset();
        *error = "cannot create " + hopt_.trace;
        return false;
    }
    std::printf("socsim: tracing frame %u -> %s\n", hopt_.trace_frame, hopt_.trace.c_str());
    std::fflush(stdout);
    return true;
#else
    *error = "this simulator was built without tracing: use make waves";
    return false;
#endif
}

void SocRun::trace_close()
{
#if SOCSIM_TRACE
    if (fst_ != nullptr) {
        fst_->close();
        fst_.reset();
    }
#endif
}

// The SoC's own keys, after the harness's.
void SocRun::summary_keys(FILE *f) const
{
    std::fprintf(f, "cycles=%llu\ninstructions=%llu\nkeys_late=%u\n", static_cast<unsigned long long>(cycles_),
                 static_cast<unsigned long long>(instret()), keys_late_);
    std::fprintf(f, "registers_model_checked=%llu\n", static_cast<unsigned long long>(regs_checked_));
    std::fprintf(f, "scanout_underflows=%u\nscanout_worst_row_clocks=%u\n", scanout_underflows_, worst_row_fetch_);
    std::fprintf(f, "icache_refills=%llu\ndcache_refills=%llu\nuart_framing_errors=%u\n",
                 static_cast<unsigned long long>(icache_refills_), static_cast<unsigned long long>(dcache_refills_),
                 rx_.framing_errors());
    std::fprintf(f, "exit_valid=%d\nvga_vsyncs=%llu\nuart_replies=%u\n", top_->exit_valid ? 1 : 0,
                 static_cast<unsigned long long>(vsyncs_), replies_.sent());
#ifdef SOCSIM_USB
    if (kbd_) {
        std::fprintf(f, "usb_keys_read=%u\nusb_violations=%zu\nusb_configured=%d\nusb_reports_queued=%zu\n",
                     usb_keys_read_, kbd_->violations().size(), kbd_->configured() ? 1 : 0, kbd_->reports_queued());
        std::fprintf(f, "usb_keyboard=%s\n", kbd_->stats().c_str());
    }
#endif
#ifdef SOCSIM_BOARD_ULX3S
    // No leds= here: the board's pins show SYS LEDS 3:0 only, beside its own status (ulx3s_system).
    std::fprintf(f, "tmds_pixels=%llu\ntmds_data_symbols=%llu\ntmds_control_symbols=%llu\n",
                 static_cast<unsigned long long>(tmds_.pixels()), static_cast<unsigned long long>(tmds_.data_symbols()),
                 static_cast<unsigned long long>(tmds_.control_symbols()));
    std::fprintf(f, "tmds_max_disparity=%d,%d,%d\n", tmds_.max_disparity(0), tmds_.max_disparity(1),
                 tmds_.max_disparity(2));
#else
    std::fprintf(f, "leds=0x%02x\n", static_cast<unsigned>(top_->leds));  // SYS LEDS, soc_top's port
#endif
#ifdef SOCSIM_SDRAM
    if (!sdram_ || !flash_) {
        return;  // a run that failed in its setup, before the chips were made
    }
    const SdramCounters &k = sdram_->counters();
    std::fprintf(f, "sdram_violations=%llu\nsdram_refreshes=%llu\nsdram_words_read=%llu\nsdram_words_written=%llu\n",
                 static_cast<unsigned long long>(sdram_->error_count()), static_cast<unsigned long long>(k.refreshes),
                 static_cast<unsigned long long>(k.words_read), static_cast<unsigned long long>(k.words_written));
    std::fprintf(f, "sdram_init_done=%d\nsdram_busy_cycles=%llu\n", top_->sdram_init_done ? 1 : 0,
                 static_cast<unsigned long long>(sdram_busy_));
    std::fprintf(f, "flash_violations=%llu\nflash_bytes_read=%llu\n",
                 static_cast<unsigned long long>(flash_->error_count()),
                 static_cast<unsigned long long>(flash_->counters().bytes_read));
#endif
}

// The firmware's unfinished last line, the terminal back, and the simulation's speed.
void SocRun::stop_parts()
{
    uart_.finish();
    terminal_.restore();
    const double wall = harness_now_s() - t_start_;
    std::printf("socsim: %llu cycles (%.3f s at %.0f MHz) in %.1f s: %.2f M cycles/s\n",
                static_cast<unsigned long long>(cycles_), cycles_ / static_cast<double>(SOCSIM_CLK_HZ),
                SOCSIM_CLK_HZ / 1e6, wall, wall > 0 ? cycles_ / wall / 1e6 : 0.0);
    std::fflush(stdout);
}

int SocRun::run()
{
    catch_signals();
    t_start_ = harness_now_s();

    const std::string &fw = opt_.harness.firmware.empty() ? opt_.hex : opt_.harness.firmware;
    if (const int status = open_outputs("socsim " + fw.substr(fw.rfind('/') + 1))) {  // npos + 1 = 0
        return status;
    }
    std::string error;
    const char *kind = "none";  // a failed frame's (Harness::take_frame)
    if (!load_ram(&error)) {
        return fail("setup", "%s", error.c_str());
    }
#ifdef SOCSIM_BOARD_ULX3S
    top_->clk_sys = top_->clk_pix = top_->clk_tmds = 0;
#ifdef SOCSIM_SDRAM
    top_->clk_sys2x = 0;
#endif
    top_->pll_locked = 0;
    top_->btn_reset = 0;
#else
    top_->clk = top_->clk_pix = 0;
#ifdef SOCSIM_SDRAM
    top_->clk2x = 0;
#endif
    top_->ext_rst = 0;
#endif
#ifdef SOCSIM_SDRAM
    {
        SdramConfig cfg;  // the -7 grade, as ULX3S boards carry (sdram_chip.h)
        cfg.clock_period_ps = 500000000000ull / SOCSIM_CLK_HZ;   // clk2x's
        cfg.strict_uninitialised_reads = false;  // a cache line refill may read words never written
        cfg.stuck_low_address_pin = opt_.sdram_fault_a;
        sdram_.reset(new SdramChip(cfg));
        top_->chip_dq_oe = 0;
        flash_.reset(new SpiFlash(SpiFlashConfig()));  // erased but for the image
        if (!opt_.flash_image.empty()) {
            if (!flash_->load_file(SOC_BOOT_FLASH_IMAGE_OFFSET, opt_.flash_image, &error)) {
                return fail("setup", "%s", error.c_str());
            }
            std::printf("socsim: %s in the flash at 0x%08x\n", opt_.flash_image.c_str(), SOC_BOOT_FLASH_IMAGE_OFFSET);
        }
        top_->flash_miso = 0;
    }
#endif
#ifdef SOCSIM_USB
    kbd_.reset(new UsbKbdDevice(UsbKbdConfig()));
    if (!opt_.usb_unplugged) {
        kbd_->attach(0);
    }
    top_->usb_dp_in = top_->usb_dn_in = 0;   // detached: the host's pull-downs
#endif
    top_->uart_rx = 1;
    top_->eval();  // initial blocks: soc_ram reads the image
    if (!hopt_.trace.empty() && hopt_.trace_frame == 0 && !trace_open(&error)) {
        return fail("trace", "%s", error.c_str());
    }
    terminal_.enter_raw();

    for (;;) {
        tick();
        if (arm_pending_) {
            arm_pending_ = false;
            if (capture_pending_) {
                return fail("capture", "a second swap before the frame of the first was captured (cycle %llu)",
                            static_cast<unsigned long long>(cycles_));
            }
            vga_monitor_arm(&monitor_);
            capture_pending_ = true;
            swaps_++;
            if (!hopt_.trace.empty() && hopt_.trace_frame != 0 && swaps_ == hopt_.trace_frame && !trace_open(&error)) {
                return fail("trace", "%s", error.c_str());
            }
        }
        if (capture_pending_ && monitor_.frame_ready) {
            if (!finish_frame(&error, &kind)) {
                return fail(kind, "%s", error.c_str());
            }
            if (opt_.stop_frames != 0 && frames() >= opt_.stop_frames) {
                uart_.finish();
                std::printf("socsim: stopped after %u frames (--stop-frames): %u doorbells, %llu cycles\n", frames(),
                            doorbells_, static_cast<unsigned long long>(cycles_));
                return end(0, "none");
            }
        }
        if (monitor_.error[0] != '\0') {
            return fail("capture", "VGA timing: %s", monitor_.error);
        }
        if (!video_error_.empty()) {
            return fail("video", "%s", video_error_.c_str());
        }
        if (!reg_error_.empty()) {
            return fail("model-mismatch", "RTL and golden model disagree: %s", reg_error_.c_str());
        }
#ifdef SOCSIM_SDRAM
        if (sdram_->error_count() != 0) {
            return fail("sdram", "%s", sdram_->errors().front().c_str());
        }
        if (flash_->error_count() != 0) {
            return fail("flash", "%s", flash_->errors().front().c_str());
        }
#endif
#ifdef SOCSIM_USB
        if (!kbd_->violations().empty()) {
            return fail("usb", "%s", kbd_->violations().front().text.c_str());
        }
#endif
        if (top_->exit_valid) {
            firmware_status_ = top_->exit_code;
            // The last swap's frame may still be on its way to the pins (the firmware printed its
            // line and left): the monitor gets it, as co-simulation captures every swapped frame.
            const uint64_t limit = cycles_ + 3ull * 800 * 525 * (SOCSIM_CLK_HZ / 25000000);
            while (capture_pending_ && !monitor_.frame_ready && monitor_.error[0] == '\0' && cycles_ < limit) {
                tick();
            }
            if (capture_pending_) {
                if (!monitor_.frame_ready) {
                    return fail("capture", "the last frame did not reach the VGA pins: %s",
                                monitor_.error[0] ? monitor_.error : "timeout");
                }
                if (!finish_frame(&error, &kind)) {
                    return fail(kind, "%s", error.c_str());
                }
            }
            uart_.finish();
            if (profile_) {
                if (profile_->frames() == 0) {
                    return fail("profile", "no whole frame between the first and the last at --profile-mark 0x%08x "
                                "(it needs three entries; FRAMES >= 3)", opt_.profile_mark);
                }
                if (!profile_->write(opt_.profile.c_str())) {
                    return fail("profile", "cannot write %s", opt_.profile.c_str());
                }
            }
            std::printf("socsim: firmware exited with status %d: %u doorbells, %u frames, %llu cycles, %llu "
                        "instructions\n",
                        firmware_status_, doorbells_, frames(), static_cast<unsigned long long>(cycles_),
                        static_cast<unsigned long long>(instret()));
            return end(firmware_status_, firmware_status_ == 0 ? "none" : "firmware-status");
        }
        if ((cycles_ & 0xFFFF) != 0) {
            continue;
        }
        std::string keys;
        if (stop_requested(&keys)) {
            return fail_signal();
        }
        tx_.queue(keys);
        // "q" once it is closed: the firmware quits as on Q, with its status (on the UART: the
        // keyboard may not be enumerated yet).
#ifdef SOCSIM_USB
        if (opt_.usb_window) {
            std::string quit;
            type_on_usb(usb_text_from_terminal(window_keys(&quit)));
            tx_.queue(quit);
        } else {
            tx_.queue(window_keys());
        }
#else
        tx_.queue(window_keys());
#endif
        if (window_given_up(10.0)) {
            return end_by_window();
        }
        if (tx_.queued() < kPtyQueue) {
            tx_.queue(pty_.read(kPtyQueue - tx_.queued()));
        }
        if (cycles_ >= opt_.max_cycles) {
            return fail("cycle-limit", "the firmware did not exit within %llu cycles",
                        static_cast<unsigned long long>(opt_.max_cycles));
        }
        // Slow frames: a line every progress_cycles without one.
        if (cycles_ - std::max(last_frame_cycle_, last_progress_cycle_) >= opt_.progress_cycles) {
            std::printf("socsim: %u frames, %llu M cycles\n", frames(),
                        static_cast<unsigned long long>(cycles_ / 1000000));
            std::fflush(stdout);
            last_progress_cycle_ = cycles_;
        }
    }
}

}  // namespace

// ---- DPI imports of socsim_taps.sv -------------------------------------------------------------
extern "C" void socsim_gpu_write(unsigned offset, unsigned value)
{
    if (g_run != nullptr) {
        g_run->on_gpu_write(offset, value);
    }
}

extern "C" void socsim_gpu_read(unsigned offset, unsigned value)
{
    if (g_run != nullptr) {
        g_run->on_gpu_read(offset, value);
    }
}

extern "C" void socsim_gpu_swap(unsigned frame_count)
{
    if (g_run != nullptr) {
        g_run->on_gpu_swap(frame_count);
    }
}

extern "C" void socsim_gpu_underflows(unsigned count)
{
    if (g_run != nullptr) {
        g_run->on_gpu_underflows(count);
    }
}

extern "C" void socsim_row_fetch(unsigned clocks)
{
    if (g_run != nullptr) {
        g_run->on_row_fetch(clocks);
    }
}

extern "C" void socsim_bus_cycle(unsigned ibus, unsigned word_addr, unsigned write)
{
    if (g_run != nullptr) {
        g_run->on_bus_cycle(ibus != 0, word_addr, write != 0);
    }
}

extern "C" unsigned socsim_profiling()
{
    return g_profiling ? 1u : 0u;
}

extern "C" void socsim_retire(unsigned pc)
{
    if (g_run != nullptr) {
        g_run->on_retire(pc);
    }
}

extern "C" void socsim_uart_data_read()
{
    if (g_run != nullptr) {
        g_run->on_uart_data_read();
    }
}

extern "C" void socsim_usb_key_read(unsigned value)
{
    if (g_run != nullptr) {
        g_run->on_usb_key_read(value);
    }
}

extern "C" void socsim_cpu_scope()
{
    g_cpu_scope = svGetScope();
}

int main(int argc, char **argv)
{
    Verilated::commandArgs(1, argv);
    Options o;
    if (!parse(argc, argv, o)) {
        return usage();
    }
    SocRun run(o);
    return run.run();
}
