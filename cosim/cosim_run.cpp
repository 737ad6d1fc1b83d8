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
// playable: no VGA scan is simulated. The options, the frames' path, the failures and the summary
// are the harness core's (harness.h), shared with socsim; this file adds QEMU and the mailbox.
//
// Determinism: simulated time advances only while a batch is serviced, so the same firmware gives
// the same frames byte for byte whatever the host's timing. Robustness: the shared-memory file is
// unlinked as soon as it is created, QEMU dies with this process (PR_SET_PDEATHSIG), and this process
// notices QEMU's death, SIGINT/SIGTERM/SIGHUP (and Ctrl-C on a raw terminal), a GPU timeout and a
// silent firmware (unless a debugger holds it: --gdb). Every failure prints one "cosim: error: ..."
// line on stderr, stops QEMU, restores the terminal, flushes the UART's last output and returns 1;
// usage errors return 2; a firmware that ends with status 0, and a run stopped by
// --stop-after-frames, return 0. With --summary FILE the run's outcome is also written as key=value
// lines (harness.h's keys, then frame_wall_first_s and frame_wall_last_s, the monotonic clock when the
// first and the last frame were captured, and frame_cycles_first and frame_cycles_last, the GPU
// clocks simulated by then) for tests and scripts to read instead of the prose.
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include "batch_bridge.h"
#include "harness.h"
#include "qemu_process.h"
#include "shared_ram.h"

namespace {

struct Options {
    HarnessOptions harness;
    std::string qemu = "qemu-system-riscv32";
    uint32_t stop_after_frames = 0;  // end the run (status 0) after this many frames; 0: never
    double idle_timeout_s = 60.0;
    int gdb_port = 0;  // QEMU's GDB stub (--gdb), or 0
    BridgeOptions bridge;
};

int usage()
{
    return harness_usage(
        "usage: gpusim cosim --fw FIRMWARE.elf [--frames DIR] [--qemu PATH] [--uart-log FILE]\n"
        "                    [--idle-timeout SECONDS] [--max-batch-cycles N] [--no-model-check]\n"
        "                    [--keys-at N:TEXT]... [--drop-doorbell N] [--dump-lists DIR] [--summary FILE]\n"
        "                    [--uart-pty LINK] [--window] [--window-fps N] [--gdb PORT]\n"
        "                    [--stop-after-frames N] [--trace FILE.fst [--trace-frame N]]\n"
        "  --drop-doorbell N  ignore doorbell N, as a hung GPU would (the firmware's watchdog must RESET)\n"
        "  --dump-lists DIR   write each batch as DIR/batchNNNN.txt in the `make raster` list format\n"
        "  --stop-after-frames N  end the run after N frames, with status 0 (benchmarks)\n"
        "  --gdb PORT         QEMU's GDB stub on tcp:127.0.0.1:PORT, the firmware halted at reset until a\n"
        "                     debugger continues it; no idle timeout (make debug)\n");
}

bool parse(int argc, char **argv, Options &o)
{
    const auto own = [&](const std::string &a, bool has_value, int *i) {
        if (a == "--qemu" && has_value) {
            o.qemu = argv[++*i];
        } else if (a == "--gdb" && has_value) {
            o.gdb_port = std::atoi(argv[++*i]);
            if (o.gdb_port <= 0 || o.gdb_port > 65535) {
                std::fprintf(stderr, "cosim: --gdb expects a TCP port (1-65535)\n");
                return HarnessArg::Bad;
            }
        } else if (a == "--idle-timeout" && has_value) {
            o.idle_timeout_s = std::atof(argv[++*i]);
        } else if (a == "--max-batch-cycles" && has_value) {
            o.bridge.max_batch_cycles = std::strtoull(argv[++*i], nullptr, 0);
        } else if (a == "--dump-lists" && has_value) {
            o.bridge.dump_lists = argv[++*i];
        } else if (a == "--drop-doorbell" && has_value) {
            o.bridge.drop_doorbell = static_cast<uint32_t>(std::strtoul(argv[++*i], nullptr, 10));
        } else if (a == "--stop-after-frames" && has_value) {
            o.stop_after_frames = static_cast<uint32_t>(std::strtoul(argv[++*i], nullptr, 10));
        } else {
            return HarnessArg::Other;
        }
        return HarnessArg::Taken;
    };
    return harness_parse("cosim", argc, argv, 0, GpuSim::trace_supported(), &o.harness, own) &&
           !o.harness.firmware.empty();
}

// One run: the parts in the order they are set up; shutdown() takes them down in an order that
// keeps the guarantees (QEMU first, the terminal restored, the UART's last output shown).
class CosimRun : public Harness {
public:
    explicit CosimRun(const Options &o) : Harness("cosim", o.harness), opt_(o), bridge_(o.bridge, *this) {}
    ~CosimRun() override { shutdown(); }
    int run();

private:
    void stop_parts() override { shutdown(); }
    HarnessCounts counts() const override
    {
        HarnessCounts c;
        c.batches = bridge_.batches();
        c.doorbells_dropped = bridge_.doorbells_dropped();
        c.gpu_resets = bridge_.resets();
        c.gpu_cycles = bridge_.cycles();
        return c;
    }
    void summary_keys(FILE *f) const override;
    void shutdown();
    void pump_uart(bool final) { uart_.pump(qemu_.uart_out_fd(), final); }
    void forward_pty();

    const Options &opt_;
    BatchBridge bridge_;
    KeysSchedule keys_{opt_.harness.keys_at};  // --keys-at
    SharedRam ram_;
    QemuProcess qemu_;
};

// When the first and the last frame were captured (bench/bench_sim.sh's speeds).
void CosimRun::summary_keys(FILE *f) const
{
    const FrameClock &c = frame_clock();
    std::fprintf(f, "frame_wall_first_s=%.6f\nframe_wall_last_s=%.6f\n", c.first_s, c.last_s);
    std::fprintf(f, "frame_cycles_first=%llu\nframe_cycles_last=%llu\n",
                 static_cast<unsigned long long>(c.first_cycles), static_cast<unsigned long long>(c.last_cycles));
    // The frames in external memory (FRAME_DRAM; 0 elsewhere): native words through the port, and
    // their bytes (the port's width); and the clocks of one display scan on the pin path (0 on the
    // fast path: no scan is simulated).
    std::fprintf(f, "scan_clocks=%llu\n",
                 static_cast<unsigned long long>(GpuSim::fast_display() ? 0 : GpuSim::kScanClocks));
    std::fprintf(f, "scanout_underflows=%u\nframe_memory_words_written=%llu\nframe_memory_words_read=%llu\n"
                 "frame_memory_word_bytes=%u\n",
                 bridge_.scanout_underflows(), static_cast<unsigned long long>(bridge_.memory_words_written()),
                 static_cast<unsigned long long>(bridge_.memory_words_read()), GpuSim::memory_word_bytes());
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

int CosimRun::run()
{
    catch_signals();
    const std::string &fw = opt_.harness.firmware;
    if (const int status = open_outputs("gpusim " + fw.substr(fw.rfind('/') + 1))) {  // npos + 1 = 0
        return status;
    }
    if (!ram_.create()) {
        return fail("setup", "shared RAM setup failed");
    }
    if (pty_.is_open() || window_.is_open()) {
        // A client or the window's user talks to the firmware while a batch simulates too (on the
        // pin path a frame is seconds of wall time): their bytes go in, the firmware's answers come
        // out and the window stays responsive every 50k GPU clocks (about 40 ms), not only between
        // batches. Runs without either keep their exact order.
        bridge_.set_background(
            [this] {
                pump_uart(false);
                forward_pty();
                uart_.type(qemu_.uart_in_fd(), window_keys());
            },
            50000);
    }
    bridge_.attach(ram_.gpu_window());
    bridge_.publish_registers();  // ID, VERSION, CAPS ... are readable before the first doorbell
    if (!qemu_.start(opt_.qemu, fw, ram_.fd(), opt_.gdb_port)) {
        return fail("setup", "cannot start QEMU: %s", std::strerror(errno));
    }
    terminal_.enter_raw();

    double last_activity = harness_now_s();
    std::string keys;
    for (;;) {
        if (stop_requested(&keys)) {
            return fail_signal();
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
                        bridge_.batches(), frames(), static_cast<unsigned long long>(bridge_.cycles()));
            firmware_status_ = 0;
            return end(0, "none");
        }
        pump_uart(false);
        uart_.type(qemu_.uart_in_fd(), keys);
        forward_pty();
        uart_.type(qemu_.uart_in_fd(), window_keys());
        if (window_given_up(3.0)) {
            firmware_status_ = 0;
            return end_by_window();
        }
        uint32_t reset;
        if (bridge_.pending_reset(&reset)) {
            std::string error;
            if (!bridge_.service_reset(reset, &error)) {
                return fail(bridge_.error_kind(), "%s", error.c_str());
            }
            last_activity = harness_now_s();
        }
        uint32_t tag;
        if (bridge_.pending_doorbell(&tag)) {
            pump_uart(false);  // what the firmware printed before ringing comes first
            keys_.doorbell(bridge_.pending_swaps(), [this](const std::string &text) {
                uart_.type(qemu_.uart_in_fd(), text);
                // In QEMU's UART before the batch is done: the firmware, waiting for it, reads
                // the keys at its next frame on any host load (scripted runs reproducible).
                if (!uart_.wait_taken(qemu_.uart_in_fd(), 5.0)) {
                    std::fprintf(stderr, "cosim: warning: QEMU took the keys for doorbell %u late\n",
                                 bridge_.batches() + 1);
                }
            });
            std::string error;
            if (!bridge_.service_batch(tag, &error)) {
                return fail(bridge_.error_kind(), "%s", error.c_str());
            }
            if (opt_.stop_after_frames != 0 && frames() >= opt_.stop_after_frames) {
                std::printf("cosim: stopped after %u frames (--stop-after-frames)\n", frames());
                return end(0, "none");
            }
            last_activity = harness_now_s();
        } else {
            // A debugger may hold the firmware for any time: no idle timeout under --gdb.
            if (opt_.gdb_port == 0 && harness_now_s() - last_activity > opt_.idle_timeout_s) {
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
    close_outputs();
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
