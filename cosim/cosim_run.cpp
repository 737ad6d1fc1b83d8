// cosim_run: `gpusim cosim` — the co-simulation's run loop. QEMU runs the firmware with its RAM in a
// shared-memory file (shared_ram, qemu_process); this process maps the same file, and whenever the
// firmware rings the GPU's DOORBELL the batch bridge (batch_bridge) forwards the firmware's stores to
// the Verilated GPU, runs it, checks it against the golden model, writes the frame as a PNG and
// copies the read-only registers back so the firmware sees DONE_SEQ. Between batches the loop pumps
// the firmware's UART output and forwards typed or scripted keys (uart_pump, uart_terminal). With
// --uart-pty LINK the UART is also a pseudo-terminal (uart_pty): what a client writes there goes
// the keys' way, and the firmware's output goes to it raw, as a board's serial port would carry it.
// With --window the frames are shown in a window (sdl_window) as they are captured, its keystrokes
// go the keys' way too, and closing it ends the run as Q does; PNG files are then written only when
// --frames is given. A simulator built for the fast display path (gpu_sim.h) makes that window
// playable: no VGA scan is simulated.
//
// Determinism: simulated time advances only while a batch is serviced, so the same firmware gives
// the same frames byte for byte whatever the host's timing. Robustness: the shared-memory file is
// unlinked as soon as it is created, QEMU dies with this process (PR_SET_PDEATHSIG), and this process
// notices QEMU's death, SIGINT/SIGTERM/SIGHUP (and Ctrl-C on a raw terminal), a GPU timeout and a
// silent firmware (unless a debugger holds it: --gdb). Every failure prints one "cosim: error: ..."
// line on stderr, stops QEMU, restores the terminal, flushes the UART's last output and returns 1;
// usage errors return 2; a firmware that ends with status 0, and a run stopped by
// --stop-after-frames, return 0. With --summary FILE the run's outcome is also written as key=value
// lines (result, error, firmware_status, batches, doorbells_dropped, gpu_resets, frames,
// frames_model_checked, gpu_cycles, frame_wall_first_s and frame_wall_last_s (the monotonic clock
// when the first and the last frame were captured), frame_cycles_first and frame_cycles_last (the
// GPU clocks simulated by then), uart_pty_in, uart_pty_dropped) for tests and scripts to read
// instead of the prose.
#include <cerrno>
#include <climits>
#include <cstdarg>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include <poll.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "batch_bridge.h"
#include "keys_at.h"
#include "qemu_process.h"
#include "sdl_window.h"
#include "shared_ram.h"
#include "uart_pty.h"
#include "uart_pump.h"
#include "uart_terminal.h"

namespace {

volatile sig_atomic_t g_signal = 0;
void on_signal(int sig) { g_signal = sig; }

struct Options {
    std::string firmware;
    std::string qemu = "qemu-system-riscv32";
    std::string uart_log;
    std::string summary;
    std::string uart_pty;  // the pseudo-terminal's link, or empty
    uint32_t stop_after_frames = 0;  // end the run (status 0) after this many frames; 0: never
    bool window = false;
    double window_fps = 60.0;  // the window's frame-rate cap (0: none)
    double idle_timeout_s = 60.0;
    int gdb_port = 0;  // QEMU's GDB stub (--gdb), or 0
    KeysAt keys_at;  // (batch number, text) to type
    BridgeOptions bridge;
};

double now_s()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

int usage()
{
    std::fprintf(stderr,
                 "usage: gpusim cosim --fw FIRMWARE.elf [--frames DIR] [--qemu PATH] [--uart-log FILE]\n"
                 "                    [--idle-timeout SECONDS] [--max-batch-cycles N] [--no-model-check]\n"
                 "                    [--keys-at N:TEXT]... [--drop-doorbell N] [--dump-lists DIR] [--summary FILE]\n"
                 "                    [--uart-pty LINK] [--window] [--window-fps N] [--gdb PORT]\n"
                 "                    [--stop-after-frames N] [--trace FILE.fst [--trace-frame N]]\n"
                 "  --keys-at N:TEXT   type TEXT into the firmware's UART just before servicing doorbell N (from 1)\n"
                 "  --drop-doorbell N  ignore doorbell N, as a hung GPU would (the firmware's watchdog must RESET)\n"
                 "  --dump-lists DIR   write each batch as DIR/batchNNNN.txt in the `make raster` list format\n"
                 "  --summary FILE     write the run's outcome and counts as key=value lines\n"
                 "  --uart-pty LINK    also offer the UART as a pseudo-terminal, LINK a symlink to it (raw, 8 bits):\n"
                 "                     what a client writes there is typed, the firmware's output is sent there\n"
                 "  --window           show the frames in a window (no PNG files unless --frames is given); its keys\n"
                 "                     go to the firmware's UART, closing it ends the run as Q does\n"
                 "  --window-fps N     at most N frames a second in the window, as a board shows them (default 60,\n"
                 "                     0: as fast as the simulation goes)\n"
                 "  --stop-after-frames N  end the run after N frames, with status 0 (benchmarks)\n"
                 "  --gdb PORT         QEMU's GDB stub on tcp:127.0.0.1:PORT, the firmware halted at reset until a\n"
                 "                     debugger continues it; no idle timeout (make debug)\n"
                 "  --trace FILE.fst   the GPU's waves over frame N (default 0): its batches, swap and scan-out\n"
                 "  --trace-frame N    (a simulator built for tracing: make waves)\n"
                 "  With a terminal on stdin, keystrokes go to the firmware's UART; Ctrl-C ends the run.\n");
    return 2;
}

bool parse(int argc, char **argv, Options &o)
{
    bool frames_given = false;
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--fw" && has_value) {
            o.firmware = argv[++i];
        } else if (a == "--frames" && has_value) {
            o.bridge.frames_dir = argv[++i];
            frames_given = true;
        } else if (a == "--qemu" && has_value) {
            o.qemu = argv[++i];
        } else if (a == "--uart-log" && has_value) {
            o.uart_log = argv[++i];
        } else if (a == "--summary" && has_value) {
            o.summary = argv[++i];
        } else if (a == "--uart-pty" && has_value) {
            o.uart_pty = argv[++i];
        } else if (a == "--gdb" && has_value) {
            o.gdb_port = std::atoi(argv[++i]);
            if (o.gdb_port <= 0 || o.gdb_port > 65535) {
                std::fprintf(stderr, "cosim: --gdb expects a TCP port (1-65535)\n");
                return false;
            }
        } else if (a == "--idle-timeout" && has_value) {
            o.idle_timeout_s = std::atof(argv[++i]);
        } else if (a == "--max-batch-cycles" && has_value) {
            o.bridge.max_batch_cycles = std::strtoull(argv[++i], nullptr, 0);
        } else if (a == "--keys-at" && has_value) {
            if (!parse_keys_at("cosim", argv[++i], &o.keys_at)) {
                return false;
            }
        } else if (a == "--dump-lists" && has_value) {
            o.bridge.dump_lists = argv[++i];
        } else if (a == "--drop-doorbell" && has_value) {
            o.bridge.drop_doorbell = static_cast<uint32_t>(std::strtoul(argv[++i], nullptr, 10));
        } else if (a == "--stop-after-frames" && has_value) {
            o.stop_after_frames = static_cast<uint32_t>(std::strtoul(argv[++i], nullptr, 10));
        } else if (a == "--window") {
            o.window = true;
        } else if (a == "--window-fps" && has_value) {
            o.window_fps = std::atof(argv[++i]);
        } else if (a == "--trace" && has_value) {
            o.bridge.trace = argv[++i];
            if (!GpuSim::trace_supported()) {
                std::fprintf(stderr, "cosim: --trace: this simulator was built without tracing: use make waves\n");
                return false;
            }
        } else if (a == "--trace-frame" && has_value) {
            o.bridge.trace_frame = static_cast<uint32_t>(std::strtoul(argv[++i], nullptr, 10));
        } else if (a == "--no-model-check") {
            o.bridge.check_model = false;
        } else {
            std::fprintf(stderr, "cosim: unknown or incomplete option '%s'\n", a.c_str());
            return false;
        }
    }
    if (o.window && !frames_given) {
        o.bridge.frames_dir.clear();
    }
    return !o.firmware.empty();
}

// One run: the parts in the order they are set up; shutdown() takes them down in an order that
// keeps the guarantees (QEMU first, the terminal restored, the UART's last output shown).
class CosimRun {
public:
    explicit CosimRun(const Options &o) : opt_(o), bridge_(o.bridge) {}
    ~CosimRun() { shutdown(); }
    int run();

private:
    int fail(const char *kind, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
    void write_summary(const char *error);
    void shutdown();
    void pump_uart(bool final) { uart_.pump(qemu_.uart_out_fd(), final); }
    void forward_pty();
    void poll_window();

    const Options &opt_;
    BatchBridge bridge_;
    SharedRam ram_;
    QemuProcess qemu_;
    UartPump uart_;
    UartTerminal terminal_;
    UartPty pty_;
    SdlWindow window_;
    double window_polled_at_ = 0;
    double window_closed_at_ = -1;  // when the window was closed (the run is ending), or -1
    int firmware_status_ = -1;  // QEMU's exit status once it has ended
    // When the first and the last frame were captured: wall time, simulated GPU clocks.
    double first_frame_s_ = 0, last_frame_s_ = 0;
    uint64_t first_frame_cycles_ = 0, last_frame_cycles_ = 0;
};

// The outcome for --summary: error "none" on success; firmware_status -1 while QEMU had not ended.
void CosimRun::write_summary(const char *error)
{
    if (opt_.summary.empty()) {
        return;
    }
    FILE *f = std::fopen(opt_.summary.c_str(), "w");
    if (f == nullptr) {
        std::fprintf(stderr, "cosim: warning: cannot write %s: %s\n", opt_.summary.c_str(), std::strerror(errno));
        return;
    }
    std::fprintf(f, "result=%s\nerror=%s\nfirmware_status=%d\n", std::strcmp(error, "none") ? "error" : "ok",
                 error, firmware_status_);
    std::fprintf(f, "batches=%u\ndoorbells_dropped=%u\ngpu_resets=%u\n", bridge_.batches(),
                 bridge_.doorbells_dropped(), bridge_.resets());
    std::fprintf(f, "frames=%u\nframes_model_checked=%u\ngpu_cycles=%llu\n", bridge_.frames(),
                 bridge_.frames_model_checked(), static_cast<unsigned long long>(bridge_.cycles()));
    std::fprintf(f, "frame_wall_first_s=%.6f\nframe_wall_last_s=%.6f\n", first_frame_s_, last_frame_s_);
    std::fprintf(f, "frame_cycles_first=%llu\nframe_cycles_last=%llu\n",
                 static_cast<unsigned long long>(first_frame_cycles_),
                 static_cast<unsigned long long>(last_frame_cycles_));
    std::fprintf(f, "uart_pty_in=%llu\nuart_pty_dropped=%llu\n", static_cast<unsigned long long>(pty_.bytes_in()),
                 static_cast<unsigned long long>(pty_.bytes_dropped()));
    std::fclose(f);
}

// The pty's bytes, as many as the UART's input pipe takes without blocking (POLLOUT: room for
// PIPE_BUF): the rest wait in the pty, which then holds its client back, instead of this loop
// blocking on a full pipe while the firmware waits for its batch.
void CosimRun::forward_pty()
{
    if (!pty_.is_open() || qemu_.uart_in_fd() < 0) {
        return;
    }
    pollfd p = {qemu_.uart_in_fd(), POLLOUT, 0};
    if (poll(&p, 1, 0) == 1 && (p.revents & POLLOUT) != 0) {
        uart_.type(qemu_.uart_in_fd(), pty_.read(PIPE_BUF));
    }
}

// The window's keys go to the firmware; its closing asks the firmware to quit (Q), as a user would.
void CosimRun::poll_window()
{
    if (!window_.is_open()) {
        return;
    }
    const double now = now_s();
    if (now - window_polled_at_ < 0.01) {  // 100 times a second is enough
        return;
    }
    window_polled_at_ = now;
    bool closed = false;
    const std::string keys = window_.poll(&closed);
    uart_.type(qemu_.uart_in_fd(), keys);
    if (closed && window_closed_at_ < 0) {
        window_closed_at_ = now;
        uart_.type(qemu_.uart_in_fd(), "q");
    }
}

int CosimRun::fail(const char *kind, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    std::fputs("cosim: error: ", stderr);
    std::vfprintf(stderr, fmt, ap);
    std::fputc('\n', stderr);
    va_end(ap);
    shutdown();
    write_summary(kind);
    return 1;
}

int CosimRun::run()
{
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    std::signal(SIGHUP, on_signal);
    std::signal(SIGPIPE, SIG_IGN);

    const std::string &frames_dir = opt_.bridge.frames_dir;
    if (!frames_dir.empty() && mkdir(frames_dir.c_str(), 0755) != 0 && errno != EEXIST) {
        return fail("setup", "cannot create %s: %s", frames_dir.c_str(), std::strerror(errno));
    }
    if (!opt_.uart_log.empty() && !uart_.open_log(opt_.uart_log)) {
        return fail("setup", "cannot create %s: %s", opt_.uart_log.c_str(), std::strerror(errno));
    }
    if (!ram_.create()) {
        return fail("setup", "shared RAM setup failed");
    }
    if (!opt_.uart_pty.empty()) {
        std::string error;
        if (!pty_.open(opt_.uart_pty, &error)) {
            return fail("setup", "--uart-pty %s: %s", opt_.uart_pty.c_str(), error.c_str());
        }
        uart_.tee_to(&pty_);
        std::printf("cosim: UART on %s (%s)\n", pty_.link().c_str(), pty_.slave_path().c_str());
        std::fflush(stdout);
    }
    if (opt_.window) {
        std::string error;
        const size_t slash = opt_.firmware.rfind('/');
        if (!window_.open("gpusim " + opt_.firmware.substr(slash == std::string::npos ? 0 : slash + 1), &error)) {
            return fail("setup", "--window: %s", error.c_str());
        }
        window_.set_max_fps(opt_.window_fps);
        uart_.on_line([this](const std::string &line) {
            const std::string status = frame_line_status(line);
            if (!status.empty()) {
                window_.set_status(status);
            }
        });
    }
    if (pty_.is_open() || window_.is_open()) {
        // A client or the window's user talks to the firmware while a batch simulates too (on the
        // pin path a frame is seconds of wall time): their bytes go in, the firmware's answers come
        // out and the window stays responsive every 50k GPU clocks (about 40 ms), not only between
        // batches. Runs without either keep their exact order.
        bridge_.set_background([this] { pump_uart(false); forward_pty(); poll_window(); }, 50000);
    }
    bridge_.attach(ram_.gpu_window());
    bridge_.publish_registers();  // ID, VERSION, CAPS ... are readable before the first doorbell
    if (!qemu_.start(opt_.qemu, opt_.firmware, ram_.fd(), opt_.gdb_port)) {
        return fail("setup", "cannot start QEMU: %s", std::strerror(errno));
    }
    terminal_.enter_raw();

    double last_activity = now_s();
    for (;;) {
        if (g_signal) {
            return fail("signal", "stopped by signal %d", static_cast<int>(g_signal));
        }
        int status = 0;
        if (qemu_.reap(&status)) {
            pump_uart(true);
            std::string error;
            if (!bridge_.finish_frames(&error)) {  // the last swapped frame is on its way to the pins
                return fail(bridge_.error_kind(), "%s", error.c_str());
            }
            if (WIFSIGNALED(status)) {
                return fail("qemu-died", "QEMU was killed by signal %d", WTERMSIG(status));
            }
            if (WEXITSTATUS(status) != 0) {
                firmware_status_ = WEXITSTATUS(status);
                return fail("firmware-status", "firmware ended with exit status %d", firmware_status_);
            }
            std::printf("cosim: firmware finished: %u batches, %u frames, %llu GPU cycles simulated\n",
                        bridge_.batches(), bridge_.frames(), static_cast<unsigned long long>(bridge_.cycles()));
            firmware_status_ = 0;
            shutdown();
            write_summary("none");
            return 0;
        }
        pump_uart(false);
        bool ctrl_c = false;
        const std::string keys = terminal_.read_keys(&ctrl_c);
        if (ctrl_c) {
            g_signal = SIGINT;
        } else {
            uart_.type(qemu_.uart_in_fd(), keys);
        }
        forward_pty();
        poll_window();
        if (window_closed_at_ >= 0 && now_s() - window_closed_at_ > 3.0) {
            std::printf("cosim: the window was closed and the firmware did not quit: stopped\n");
            firmware_status_ = 0;
            shutdown();
            write_summary("none");
            return 0;
        }
        uint32_t reset;
        if (bridge_.pending_reset(&reset)) {
            std::string error;
            if (!bridge_.service_reset(reset, &error)) {
                return fail(bridge_.error_kind(), "%s", error.c_str());
            }
            last_activity = now_s();
        }
        uint32_t tag;
        if (bridge_.pending_doorbell(&tag)) {
            pump_uart(false);  // what the firmware printed before ringing comes first
            for (const auto &k : opt_.keys_at) {
                if (k.first == bridge_.batches() + 1) {
                    uart_.type(qemu_.uart_in_fd(), k.second);
                }
            }
            std::string error;
            const uint32_t frames_before = bridge_.frames();
            if (!bridge_.service_batch(tag, &error)) {
                return fail(bridge_.error_kind(), "%s", error.c_str());
            }
            if (bridge_.frames() != frames_before) {
                window_.show(bridge_.frame_rgb());
                last_frame_s_ = now_s();
                last_frame_cycles_ = bridge_.cycles();
                if (frames_before == 0) {
                    first_frame_s_ = last_frame_s_;
                    first_frame_cycles_ = last_frame_cycles_;
                }
                if (opt_.stop_after_frames != 0 && bridge_.frames() >= opt_.stop_after_frames) {
                    std::printf("cosim: stopped after %u frames (--stop-after-frames)\n", bridge_.frames());
                    shutdown();
                    write_summary("none");
                    return 0;
                }
            }
            last_activity = now_s();
        } else {
            // A debugger may hold the firmware for any time: no idle timeout under --gdb.
            if (opt_.gdb_port == 0 && now_s() - last_activity > opt_.idle_timeout_s) {
                return fail("idle", "the firmware rang no doorbell for %.0f s: giving up", opt_.idle_timeout_s);
            }
            usleep(20);
        }
    }
}

void CosimRun::shutdown()
{
    qemu_.kill();
    terminal_.restore();
    qemu_.close_uart_in();
    if (qemu_.uart_out_fd() >= 0) {
        pump_uart(true);
        qemu_.close_uart_out();
    }
    uart_.tee_to(nullptr);
    uart_.on_line(nullptr);
    window_.close();
    pty_.close();
    uart_.close_log();
    ram_.close();
}

}  // namespace

int cosim_main(int argc, char **argv)
{
    Options o;
    if (!parse(argc, argv, o)) {
        return usage();
    }
    CosimRun run(o);
    return run.run();
}
