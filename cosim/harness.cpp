// harness: see harness.h.
#include "harness.h"

#include <cerrno>
#include <cstdarg>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include <sys/stat.h>

#include "model_check.h"

extern "C" {
#include "png_write.h"
#include "vga_monitor.h"
}

volatile sig_atomic_t Harness::signal_ = 0;

double harness_now_s()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

namespace {

// argv[*i] if it is a shared option (Taken, *i moved past its value), else Other; Bad after a message.
HarnessArg shared_option(const char *prog, int argc, char **argv, int *i, bool trace_built, HarnessOptions *o)
{
    const std::string a = argv[*i];
    const bool has_value = *i + 1 < argc;
    const auto value = [&]() -> const char * { return argv[++*i]; };
    if (a == "--no-model-check") {
        o->check_model = false;
    } else if (a == "--window") {
        o->window = true;
    } else if (!has_value) {
        return HarnessArg::Other;
    } else if (a == "--fw") {
        o->firmware = value();
    } else if (a == "--frames") {
        o->frames_dir = value();
        o->frames_given = true;
    } else if (a == "--uart-log") {
        o->uart_log = value();
    } else if (a == "--summary") {
        o->summary = value();
    } else if (a == "--uart-pty") {
        o->uart_pty = value();
    } else if (a == "--window-fps") {
        o->window_fps = std::atof(value());
    } else if (a == "--keys-at") {
        if (!parse_keys_at(prog, value(), &o->keys_at)) {
            return HarnessArg::Bad;
        }
    } else if (a == "--trace") {
        o->trace = value();
        if (!trace_built) {
            std::fprintf(stderr, "%s: --trace: this simulator was built without tracing: use make waves\n", prog);
            return HarnessArg::Bad;
        }
    } else if (a == "--trace-frame") {
        o->trace_frame = static_cast<uint32_t>(std::strtoul(value(), nullptr, 10));
    } else {
        return HarnessArg::Other;
    }
    return HarnessArg::Taken;
}

}  // namespace

bool harness_parse(const char *prog, int argc, char **argv, int first, bool trace_built, HarnessOptions *o,
                   const HarnessOwnOption &own)
{
    for (int i = first; i < argc; i++) {
        HarnessArg taken = shared_option(prog, argc, argv, &i, trace_built, o);
        if (taken == HarnessArg::Other) {
            taken = own(argv[i], i + 1 < argc, &i);
        }
        if (taken == HarnessArg::Bad) {
            return false;
        }
        if (taken == HarnessArg::Other) {
            std::fprintf(stderr, "%s: unknown or incomplete option '%s'\n", prog, argv[i]);
            return false;
        }
    }
    if (o->window && !o->frames_given) {
        o->frames_dir.clear();
    }
    return true;
}

int harness_usage(const char *own)
{
    std::fputs(own, stderr);
    std::fprintf(stderr,
                 "  --frames DIR       write each frame as DIR/NNNN.png (default out/frames)\n"
                 "  --uart-log FILE    the firmware's UART output, line by line\n"
                 "  --keys-at N:TEXT   type TEXT into the firmware's UART when the GPU takes DOORBELL write N\n"
                 "                     (counted from 1); fF:TEXT: the doorbell that starts frame F (from 0)\n"
                 "  --no-model-check   no comparison with the golden model\n"
                 "  --summary FILE     write the run's outcome and counts as key=value lines\n"
                 "  --uart-pty LINK    also offer the UART as a pseudo-terminal, LINK a symlink to it (raw, 8 bits):\n"
                 "                     what a client writes there is typed, the firmware's output is sent there\n"
                 "  --window           show the frames in a window (no PNG files unless --frames is given); its keys\n"
                 "                     go to the firmware's UART, closing it ends the run as Q does\n"
                 "  --window-fps N     at most N frames a second in the window, as a board shows them (default 60,\n"
                 "                     0: as fast as the simulation goes)\n"
                 "  --trace FILE.fst   the waves of frame N (--trace-frame N, default 0): its work, swap and scan-out\n"
                 "  --trace-frame N    (a simulator built for tracing: make waves)\n"
                 "  With a terminal on stdin, keystrokes go to the firmware's UART; Ctrl-C ends the run.\n");
    return 2;
}

void Harness::catch_signals()
{
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    std::signal(SIGHUP, on_signal);
    std::signal(SIGPIPE, SIG_IGN);
}

// mkdir -p: the default out/frames must work in a fresh checkout, where out/ does not exist yet.
static bool make_dirs(const std::string &path)
{
    for (size_t slash = path.find('/', 1); slash != std::string::npos; slash = path.find('/', slash + 1)) {
        if (mkdir(path.substr(0, slash).c_str(), 0755) != 0 && errno != EEXIST) {
            return false;
        }
    }
    return mkdir(path.c_str(), 0755) == 0 || errno == EEXIST;
}

int Harness::open_outputs(const std::string &window_title)
{
    const std::string &frames_dir = hopt_.frames_dir;
    if (!frames_dir.empty() && !make_dirs(frames_dir)) {
        return fail("setup", "cannot create %s: %s", frames_dir.c_str(), std::strerror(errno));
    }
    if (!hopt_.uart_log.empty() && !uart_.open_log(hopt_.uart_log)) {
        return fail("setup", "cannot create %s: %s", hopt_.uart_log.c_str(), std::strerror(errno));
    }
    std::string error;
    if (!hopt_.uart_pty.empty()) {
        if (!pty_.open(hopt_.uart_pty, &error)) {
            return fail("setup", "--uart-pty %s: %s", hopt_.uart_pty.c_str(), error.c_str());
        }
        uart_.tee_to(&pty_);
        std::printf("%s: UART on %s (%s)\n", prog_, pty_.link().c_str(), pty_.slave_path().c_str());
        std::fflush(stdout);
    }
    if (hopt_.window) {
        if (!window_.open(window_title, &error)) {
            return fail("setup", "--window: %s", error.c_str());
        }
        window_.set_max_fps(hopt_.window_fps);
        uart_.on_line([this](const std::string &line) {
            const std::string status = frame_line_status(line);
            if (!status.empty()) {
                window_.set_status(status);
            }
        });
    }
    return 0;
}

void Harness::close_outputs()
{
    uart_.tee_to(nullptr);
    uart_.on_line(nullptr);
    window_.close();
    pty_.close();
    uart_.close_log();
}

bool Harness::stop_requested(std::string *keys)
{
    bool ctrl_c = false;
    *keys = terminal_.read_keys(&ctrl_c);
    if (ctrl_c) {
        signal_ = SIGINT;
    }
    return signal_ != 0;
}

std::string Harness::window_keys(std::string *quit)
{
    if (!window_.is_open()) {  // before the clock: the loops call this at every turn
        return "";
    }
    const double now = harness_now_s();
    if (now - window_polled_at_ < 0.01) {  // 100 times a second is enough
        return "";
    }
    window_polled_at_ = now;
    bool closed = false;
    std::string keys = window_.poll(&closed);
    if (closed && window_closed_at_ < 0) {
        window_closed_at_ = now;
        (quit != nullptr ? *quit : keys) += "q";
    }
    return keys;
}

bool Harness::window_given_up(double grace_s) const
{
    return window_closed_at_ >= 0 && harness_now_s() - window_closed_at_ > grace_s;
}

int Harness::end_by_window()
{
    std::printf("%s: the window was closed and the firmware did not quit: stopped\n", prog_);
    return end(0, "none");
}

bool Harness::take_frame(const uint8_t *rgb, ModelCheck &model, uint64_t cycles, const std::string &detail,
                         std::string *error, const char **kind)
{
    char text[512];
    if (hopt_.check_model) {
        const std::string diff = model.compare_frame(rgb);
        if (!diff.empty()) {
            *kind = "model-mismatch";
            *error = "frame " + std::to_string(frames_) + ": VGA output differs from the golden model: " + diff;
            return false;
        }
        model.release_writes();  // the model may now draw the next frame
    }
    std::snprintf(text, sizeof text, "(not written)");
    if (!hopt_.frames_dir.empty()) {
        std::snprintf(text, sizeof text, "%s/%04u.png", hopt_.frames_dir.c_str(), frames_);
        if (png_write_rgb(text, rgb, VGA_W, VGA_H) != 0) {
            *kind = "write";
            *error = std::string("cannot write ") + text;
            return false;
        }
    }
    window_.show(rgb);
    std::printf("%s: frame %04u -> %s | %s%s\n", prog_, frames_, text, detail.c_str(),
                hopt_.check_model ? " | equals golden model" : "");
    std::fflush(stdout);
    frame_clock_.last_s = harness_now_s();
    frame_clock_.last_cycles = cycles;
    if (frames_ == 0) {
        frame_clock_.first_s = frame_clock_.last_s;
        frame_clock_.first_cycles = cycles;
    }
    frames_++;
    frames_checked_ += hopt_.check_model ? 1 : 0;
    return true;
}

int Harness::fail(const char *kind, const char *fmt, ...)
{
    std::fflush(stdout);
    va_list ap;
    va_start(ap, fmt);
    std::fprintf(stderr, "%s: error: ", prog_);
    std::vfprintf(stderr, fmt, ap);
    std::fputc('\n', stderr);
    va_end(ap);
    return end(1, kind);
}

int Harness::end(int status, const char *kind)
{
    stop_parts();
    write_summary(kind);
    return status;
}

void Harness::write_summary(const char *error) const
{
    if (hopt_.summary.empty()) {
        return;
    }
    FILE *f = std::fopen(hopt_.summary.c_str(), "w");
    if (f == nullptr) {
        std::fprintf(stderr, "%s: warning: cannot write %s: %s\n", prog_, hopt_.summary.c_str(), std::strerror(errno));
        return;
    }
    const HarnessCounts c = counts();
    std::fprintf(f, "result=%s\nerror=%s\nfirmware_status=%d\n", std::strcmp(error, "none") ? "error" : "ok",
                 error, firmware_status_);
    std::fprintf(f, "batches=%u\ndoorbells_dropped=%u\ngpu_resets=%u\n", c.batches, c.doorbells_dropped,
                 c.gpu_resets);
    std::fprintf(f, "frames=%u\nframes_model_checked=%u\ngpu_cycles=%llu\n", frames_, frames_checked_,
                 static_cast<unsigned long long>(c.gpu_cycles));
    std::fprintf(f, "uart_pty_in=%llu\nuart_pty_dropped=%llu\n", static_cast<unsigned long long>(pty_.bytes_in()),
                 static_cast<unsigned long long>(pty_.bytes_dropped()));
    summary_keys(f);
    std::fclose(f);
}
