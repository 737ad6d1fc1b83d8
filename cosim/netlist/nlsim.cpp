// nlsim: a board's netlist simulated at its pins (make netlist-sim, cosim/netlist/netlist.mk). The
// Verilated model is the netlist yosys or nextpnr made for the bitstream, written back to Verilog,
// with yosys' ECP5 cell models and ours (cosim/netlist/ecp5); its top is the board's (ulx3s_top).
// Nothing inside it is tapped: what this harness sees is what a monitor and a terminal would.
//
//   nlsim --frames DIR --count N [--expect DIR] [--uart-log FILE] [--summary FILE] [--max-ms T]
//
// Clocks: the harness drives only the board's 25 MHz oscillator (clk_25mhz); the netlist's own PLL
// (the EHXPLLL model) makes the system, pixel and TMDS clocks from it at the ratios its dividers
// give. FIRE1 stays released; ftdi_txd idles high.
// Video: a DVI receiver on the GPDI pins (gpdi_dp[3:0]: blue, green, red, clock): it takes the bit
// period from the clock channel (one pixel a period of it, ten bits: a rising edge starts a pixel),
// samples each channel in the middle of each of the ten bits, and hands the bits, two at a time as
// the ODDRX1Fs sent them, to cosim/soc/tmds_decoder, which checks every symbol (DVI encoding, DC
// balance, control periods) and gives pixels; cosim/vga_monitor checks the 640x480@60 timing and
// gives frames. Each colour byte must be a 4-bit colour repeated, as ulx3s_system sends it.
// Frames: the first frame on the screen is the power-up framebuffer (the EBRs' initial contents),
// written as DIR/power-up.png; after it, each change of the picture is a frame, DIR/NNNN.png from
// 0000 — the frames the firmware swapped, as socsim writes them, when the netlist draws as the RTL
// does. With --expect DIR, each is compared with DIR/NNNN.png (socsim's, each checked against the
// golden model): the first difference names the frame, the first differing pixel and how many
// differ, and fails the run. The run ends after N frames (status 0), or fails on a video error, a
// difference, or --max-ms milliseconds of board time (default 1000) without N frames.
// The firmware's text (ftdi_rxd, 115200 8N1, sampled at the oscillator) goes to --uart-log.
// --summary FILE: key=value lines (frames, tmds_pixels, board_ps, wall_s, ...).
#include <png.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "Vnetlist.h"
#include "verilated.h"

// The C files are compiled as C++ here (Verilator's make), so their headers are not extern "C".
#include "png_write.h"
#include "tmds_decoder.h"
#include "uart_line.h"
#include "vga_monitor.h"

namespace {

constexpr uint64_t kOscHalfPs = 20000;  // the ULX3S's 25 MHz oscillator
constexpr uint32_t kBaud = 115200;

struct Options {
    std::string frames_dir, expect_dir, uart_log, summary;
    uint32_t count = 0;
    double max_ms = 1000.0;
};

int usage()
{
    std::fprintf(stderr,
                 "usage: nlsim --frames DIR --count N [--expect DIR] [--uart-log FILE] [--summary FILE]\n"
                 "             [--max-ms T]\n"
                 "  --frames DIR   DIR/power-up.png, then each new picture as DIR/NNNN.png\n"
                 "  --count N      end after N pictures after the power-up one (status 0)\n"
                 "  --expect DIR   each must equal DIR/NNNN.png (socsim's frames)\n"
                 "  --max-ms T     fail after T ms of board time (default 1000)\n");
    return 2;
}

bool parse(int argc, char **argv, Options *o)
{
    for (int i = 1; i < argc; i++) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--frames" && has_value) {
            o->frames_dir = argv[++i];
        } else if (a == "--count" && has_value) {
            o->count = static_cast<uint32_t>(std::strtoul(argv[++i], nullptr, 0));
        } else if (a == "--expect" && has_value) {
            o->expect_dir = argv[++i];
        } else if (a == "--uart-log" && has_value) {
            o->uart_log = argv[++i];
        } else if (a == "--summary" && has_value) {
            o->summary = argv[++i];
        } else if (a == "--max-ms" && has_value) {
            o->max_ms = std::strtod(argv[++i], nullptr);
        } else {
            std::fprintf(stderr, "nlsim: unknown or incomplete option '%s'\n", a.c_str());
            return false;
        }
    }
    return !o->frames_dir.empty() && o->count > 0 && o->max_ms > 0;
}

// A DVI receiver on the four GPDI lines: records each change with its time, and at every rising edge
// of the clock channel samples the ten bits of the pixel period that just ended.
class DviReceiver {
public:
    // The lines after an eval at time t (ps). Returns false on a link error (in error()).
    bool pins(uint64_t t, uint8_t dp, std::vector<TmdsPixel> *pixels)
    {
        dp &= 15;
        if (dp == level_) {
            return true;
        }
        const bool clock_rose = (dp & 8) != 0 && (level_ & 8) == 0;
        if (clock_rose) {
            if (period_start_ != kNone && !sample_period(t, pixels)) {
                return false;
            }
            period_start_ = t;
            changes_.clear();
            changes_.push_back({t, dp});
        } else if (period_start_ != kNone) {
            changes_.push_back({t, dp});
        }
        level_ = dp;
        return true;
    }
    const std::string &error() const { return error_; }
    const TmdsDecoder &decoder() const { return tmds_; }
    uint64_t pixel_period_ps() const { return period_ps_; }

private:
    struct Change {
        uint64_t t;
        uint8_t level;
    };
    static constexpr uint64_t kNone = ~0ull;

    // The lines' level at time t of the period being closed.
    uint8_t level_at(uint64_t t) const
    {
        uint8_t v = changes_.front().level;
        for (const Change &c : changes_) {
            if (c.t > t) {
                break;
            }
            v = c.level;
        }
        return v;
    }

    bool sample_period(uint64_t t_end, std::vector<TmdsPixel> *pixels)
    {
        const uint64_t period = t_end - period_start_;
        if (period_ps_ != 0 && period != period_ps_) {
            char text[128];
            std::snprintf(text, sizeof text, "the clock channel's period changed from %llu to %llu ps",
                          static_cast<unsigned long long>(period_ps_), static_cast<unsigned long long>(period));
            error_ = text;
            return false;
        }
        period_ps_ = period;
        uint8_t bits[10];
        for (int j = 0; j < 10; j++) {
            bits[j] = level_at(period_start_ + (2 * j + 1) * period / 20);
        }
        for (int j = 0; j < 10; j += 2) {
            TmdsPixel px;
            if (tmds_.clock(bits[j], bits[j + 1], &px)) {
                pixels->push_back(px);
            }
            if (!tmds_.ok()) {
                error_ = "TMDS: " + tmds_.error();
                return false;
            }
        }
        return true;
    }

    uint8_t level_ = 0;
    uint64_t period_start_ = kNone;
    uint64_t period_ps_ = 0;
    std::vector<Change> changes_;
    TmdsDecoder tmds_;
    std::string error_;
};

// A PNG as RGB888 (libpng's simplified API); empty on failure.
std::vector<uint8_t> read_png(const std::string &path, std::string *error)
{
    png_image img;
    std::memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path.c_str())) {
        *error = path + ": " + img.message;
        return {};
    }
    img.format = PNG_FORMAT_RGB;
    if (img.width != VGA_W || img.height != VGA_H) {
        *error = path + ": not a 640x480 frame";
        png_image_free(&img);
        return {};
    }
    std::vector<uint8_t> rgb(PNG_IMAGE_SIZE(img));
    if (!png_image_finish_read(&img, nullptr, rgb.data(), 0, nullptr)) {
        *error = path + ": " + img.message;
        return {};
    }
    return rgb;
}

double now_s()
{
    return static_cast<double>(std::chrono::duration_cast<std::chrono::microseconds>(
                                   std::chrono::steady_clock::now().time_since_epoch())
                                   .count()) /
           1e6;
}

class NetlistRun {
public:
    explicit NetlistRun(const Options &o) : opt_(o), top_(new Vnetlist(context_.get())), rx_(kUartCpb)
    {
        vga_monitor_reset(&monitor_);
        vga_monitor_arm(&monitor_);  // the first whole frame, then each one after it
    }
    ~NetlistRun() { top_->final(); }
    int run();

private:
    // Oscillator periods a bit: 217 (soc_uart's divider rounds the system clock's; the sampling in
    // each bit's middle takes the difference, under 1 %).
    static constexpr uint32_t kUartCpb =
        static_cast<uint32_t>((1000000000000ull / kBaud + kOscHalfPs) / (2 * kOscHalfPs));
    int fail(const char *kind, const std::string &what);
    bool pixel(const TmdsPixel &px, std::string *error);
    bool picture(std::string *error);
    void write_outputs(const char *failure);

    const Options &opt_;
    std::unique_ptr<VerilatedContext> context_{new VerilatedContext};
    std::unique_ptr<Vnetlist> top_;
    DviReceiver dvi_;
    vga_monitor monitor_;
    UartLineDecoder rx_;
    std::string uart_text_;
    std::vector<uint8_t> last_;   // the picture on the screen
    bool power_up_seen_ = false;
    uint32_t frames_ = 0;         // pictures after the power-up one
    uint64_t screens_ = 0;        // frames the monitor captured (a picture shown once or more)
    uint64_t t_ps_ = 0;
    double wall_start_ = 0;
};


bool NetlistRun::pixel(const TmdsPixel &px, std::string *error)
{
    const uint8_t c[3] = {px.r, px.g, px.b};
    for (const uint8_t v : c) {
        if ((v >> 4) != (v & 15)) {
            char text[96];
            std::snprintf(text, sizeof text, "colour byte 0x%02X is no 4-bit colour repeated", v);
            *error = text;
            return false;
        }
    }
    vga_monitor_sample(&monitor_, px.hsync, px.vsync, px.r >> 4, px.g >> 4, px.b >> 4);
    if (monitor_.error[0] != '\0') {
        *error = std::string("VGA timing: ") + monitor_.error;
        return false;
    }
    if (monitor_.frame_ready) {
        screens_++;
        const bool ok = picture(error);
        vga_monitor_arm(&monitor_);
        return ok;
    }
    return true;
}

// A frame the monitor captured: the power-up picture, the same picture again, or a new one.
bool NetlistRun::picture(std::string *error)
{
    const std::vector<uint8_t> rgb(monitor_.rgb, monitor_.rgb + sizeof monitor_.rgb);
    if (power_up_seen_ && rgb == last_) {
        return true;
    }
    char name[32];
    if (!power_up_seen_) {
        std::snprintf(name, sizeof name, "power-up.png");
    } else {
        std::snprintf(name, sizeof name, "%04u.png", frames_);
    }
    const std::string path = opt_.frames_dir + "/" + name;
    if (png_write_rgb(path.c_str(), rgb.data(), VGA_W, VGA_H) != 0) {
        *error = "cannot write " + path;
        return false;
    }
    std::printf("nlsim: %s at %.3f ms of board time (%.0f s)\n", path.c_str(), static_cast<double>(t_ps_) / 1e9,
                now_s() - wall_start_);
    std::fflush(stdout);
    last_ = rgb;
    if (!power_up_seen_) {
        power_up_seen_ = true;
        return true;
    }
    if (!opt_.expect_dir.empty()) {
        const std::string ref_path = opt_.expect_dir + "/" + name;
        const std::vector<uint8_t> ref = read_png(ref_path, error);
        if (ref.empty()) {
            *error = "frame " + std::string(name) + ": the reference: " + *error;
            return false;
        }
        size_t first = ref.size(), differing = 0;
        for (size_t i = 0; i < ref.size(); i += 3) {
            if (std::memcmp(&ref[i], &rgb[i], 3) != 0) {
                first = std::min(first, i);
                differing++;
            }
        }
        if (differing != 0) {
            char text[256];
            const size_t p = first / 3;
            std::snprintf(text, sizeof text,
                          "frame %s differs from %s: first at pixel (%zu, %zu), netlist #%02x%02x%02x, "
                          "reference #%02x%02x%02x; %zu pixels differ",
                          name, ref_path.c_str(), p % VGA_W, p / VGA_W, rgb[first], rgb[first + 1], rgb[first + 2],
                          ref[first], ref[first + 1], ref[first + 2], differing);
            *error = text;
            return false;
        }
        std::printf("nlsim: frame %s equals %s\n", name, ref_path.c_str());
    }
    frames_++;
    return true;
}

// The UART log and the summary, at the end of a run as at a failure.
void NetlistRun::write_outputs(const char *failure)
{
    if (!opt_.uart_log.empty()) {
        FILE *u = std::fopen(opt_.uart_log.c_str(), "w");
        if (u == nullptr || std::fwrite(uart_text_.data(), 1, uart_text_.size(), u) != uart_text_.size()) {
            std::fprintf(stderr, "nlsim: cannot write %s\n", opt_.uart_log.c_str());
        }
        if (u != nullptr) {
            std::fclose(u);
        }
    }
    if (opt_.summary.empty()) {
        return;
    }
    FILE *f = std::fopen(opt_.summary.c_str(), "w");
    if (f == nullptr) {
        std::fprintf(stderr, "nlsim: cannot write %s\n", opt_.summary.c_str());
        return;
    }
    const TmdsDecoder &d = dvi_.decoder();
    std::fprintf(f, "failure=%s\nframes=%u\nscreens=%llu\nboard_ps=%llu\nwall_s=%.1f\n", failure, frames_,
                 static_cast<unsigned long long>(screens_), static_cast<unsigned long long>(t_ps_),
                 now_s() - wall_start_);
    std::fprintf(f, "pixel_period_ps=%llu\ntmds_pixels=%llu\ntmds_data_symbols=%llu\ntmds_control_symbols=%llu\n",
                 static_cast<unsigned long long>(dvi_.pixel_period_ps()), static_cast<unsigned long long>(d.pixels()),
                 static_cast<unsigned long long>(d.data_symbols()),
                 static_cast<unsigned long long>(d.control_symbols()));
    std::fprintf(f, "tmds_max_disparity=%d,%d,%d\nuart_bytes=%zu\nuart_framing_errors=%u\n", d.max_disparity(0),
                 d.max_disparity(1), d.max_disparity(2), uart_text_.size(), rx_.framing_errors());
    std::fclose(f);
}

int NetlistRun::fail(const char *kind, const std::string &what)
{
    std::fprintf(stderr, "nlsim: error: %s (at %.3f ms of board time)\n", what.c_str(),
                 static_cast<double>(t_ps_) / 1e9);
    write_outputs(kind);
    return 1;
}

int NetlistRun::run()
{
    wall_start_ = now_s();
    top_->clk_25mhz = 0;
    top_->ftdi_txd = 1;
    top_->btn_fire1 = 0;
    context_->time(0);
    top_->eval();
    const uint64_t limit_ps = static_cast<uint64_t>(opt_.max_ms * 1e9);
    uint64_t next_osc = kOscHalfPs;
    double next_progress = wall_start_ + 10.0;
    std::vector<TmdsPixel> pixels;
    std::string error;
    while (frames_ < opt_.count) {
        uint64_t t = next_osc;
        if (top_->eventsPending()) {
            t = std::min(t, top_->nextTimeSlot());
        }
        t_ps_ = t;
        context_->time(t);
        bool osc_rose = false;
        if (t == next_osc) {
            top_->clk_25mhz = !top_->clk_25mhz;
            osc_rose = top_->clk_25mhz;
            next_osc += kOscHalfPs;
        }
        top_->eval();
        if (context_->gotFinish()) {
            return fail("model", "the netlist's models stopped the simulation ($finish or $fatal)");
        }
        pixels.clear();
        if (!dvi_.pins(t, top_->gpdi_dp, &pixels)) {
            return fail("video", dvi_.error());
        }
        for (const TmdsPixel &px : pixels) {
            if (!pixel(px, &error)) {
                return fail("frame", error);
            }
        }
        if (osc_rose) {
            uint8_t b;
            if (rx_.sample(top_->ftdi_rxd, &b)) {
                uart_text_.push_back(static_cast<char>(b));
            }
            if ((next_osc & 0xFFFFF) < 2 * kOscHalfPs && now_s() >= next_progress) {
                std::printf("nlsim: %.3f ms of board time, %u frames, %llu screens (%.0f s)\n",
                            static_cast<double>(t) / 1e9, frames_, static_cast<unsigned long long>(screens_),
                            now_s() - wall_start_);
                std::fflush(stdout);
                next_progress = now_s() + 10.0;
            }
        }
        if (t >= limit_ps) {
            char text[128];
            std::snprintf(text, sizeof text, "%u of %u frames within %.0f ms of board time (--max-ms)", frames_,
                          opt_.count, opt_.max_ms);
            return fail("time-limit", text);
        }
    }
    std::printf("nlsim: %u frames after the power-up picture in %.3f ms of board time, %.0f s; %llu TMDS pixels, "
                "pixel period %llu ps\n",
                frames_, static_cast<double>(t_ps_) / 1e9, now_s() - wall_start_,
                static_cast<unsigned long long>(dvi_.decoder().pixels()),
                static_cast<unsigned long long>(dvi_.pixel_period_ps()));
    write_outputs("none");
    return 0;
}

}  // namespace

int main(int argc, char **argv)
{
    Options opt;
    if (!parse(argc, argv, &opt)) {
        return usage();
    }
    NetlistRun run(opt);
    return run.run();
}
