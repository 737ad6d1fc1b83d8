// harness: what the two simulators' harnesses share, written once — `gpusim cosim` (cosim_run.cpp:
// the firmware in QEMU, the GPU behind the shared-RAM mailbox) and socsim (soc/socsim.cpp: the
// whole SoC in RTL, on one board or the other). Each adds only what differs: how the firmware runs,
// how its GPU writes reach the golden model, how the frame comes off the pins.
//
// Contract:
//   - HarnessOptions, harness_parse(): the options both take, with one name and one meaning:
//     --fw FILE.elf, --frames DIR (default out/frames), --uart-log FILE, --summary FILE,
//     --uart-pty LINK, --window, --window-fps N, --keys-at N:TEXT (keys_at.h), --no-model-check,
//     --trace FILE.fst, --trace-frame N; --window without --frames writes no PNG files.
//     harness_parse() reads argv from argv[first]: each argument is one of these, or the
//     simulator's own (own(arg, has_value, &i): Taken, with i moved past a value it takes; Bad
//     after its message), or "<prog>: unknown or incomplete option '...'" and false.
//     harness_usage(own) prints the simulator's usage text, then the shared options' help lines,
//     and returns 2 (the usage error's exit status).
//   - Signals: Harness::catch_signals() makes SIGINT, SIGTERM and SIGHUP ask the run to stop (the
//     loop polls stop_requested(), which adds Ctrl-C on a raw terminal) and ignores SIGPIPE;
//     fail_signal() is the failure the loop then returns.
//   - Harness: one run's shared parts — the UART's line output and log (uart_pump), the pty, the
//     terminal, the window — and its ends. open_outputs() creates the frames' folder and the log,
//     opens the pty ("<prog>: UART on LINK (PATH)") and the window, each failure a fail("setup").
//     fail(kind, ...) prints one "<prog>: error: ..." line on stderr, then ends the run as end(1,
//     kind) does; end(status, kind) stops the simulator's parts (stop_parts(), the subclass's: its
//     CPU, its last UART output, the terminal), writes the summary with error = kind ("none": a
//     success) and returns status: 1 on a harness failure, 2 is usage's, else the firmware's.
//   - take_frame(): a frame captured from the pins — compared with the golden model's front buffer
//     (unless --no-model-check), whose held writes (ModelCheck::hold_writes) are then released;
//     written as FRAMES_DIR/NNNN.png (none without a folder); shown in the window; reported in one
//     line "<prog>: frame NNNN -> PATH | DETAIL[ | equals golden model]"; counted. False with
//     *error and *kind (model-mismatch, write) set.
//   - The summary (--summary FILE) holds key=value lines: result, error, firmware_status, batches,
//     doorbells_dropped, gpu_resets, frames, frames_model_checked, gpu_cycles (counts(), the
//     subclass's), uart_pty_in, uart_pty_dropped, then the subclass's own (summary_keys()). Every
//     key is a function of the run's input alone (socsim's determinism compares whole summaries)
//     but the subclass's wall-clock ones: frame_clock() says when the first and the last frame
//     were taken, on the monotonic clock and in clocks simulated by then.
// The virtual calls are on these ends and per frame only, never per simulated clock.
#ifndef HARNESS_H
#define HARNESS_H

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>

#include "keys_at.h"
#include "no_copy.h"
#include "sdl_window.h"
#include "uart_pty.h"
#include "uart_pump.h"
#include "uart_terminal.h"

class ModelCheck;

struct HarnessOptions {
    std::string firmware;                   // --fw FILE.elf
    std::string frames_dir = "out/frames";  // --frames DIR; empty: no PNG files
    std::string uart_log;                   // --uart-log FILE
    std::string summary;                    // --summary FILE
    std::string uart_pty;                   // --uart-pty LINK, or empty
    bool window = false;                    // --window
    double window_fps = 60.0;               // --window-fps N: the window's frame-rate cap (0: none)
    bool check_model = true;                // cleared by --no-model-check
    KeysAt keys_at;                         // --keys-at N:TEXT or fF:TEXT (keys_at.h)
    std::string trace;                      // --trace FILE.fst, or empty
    uint32_t trace_frame = 0;               // --trace-frame N
    bool frames_given = false;              // --frames was on the command line
};

enum class HarnessArg { Taken, Other, Bad };
using HarnessOwnOption = std::function<HarnessArg(const std::string &arg, bool has_value, int *i)>;

// trace_built: this simulator was built for waves (otherwise --trace is refused).
bool harness_parse(const char *prog, int argc, char **argv, int first, bool trace_built, HarnessOptions *o,
                   const HarnessOwnOption &own);
int harness_usage(const char *own);

double harness_now_s();  // the monotonic clock, in seconds

// What the summary's first keys count; the subclass's numbers.
struct HarnessCounts {
    uint32_t batches = 0;  // DOORBELL writes taken (dropped ones included)
    uint32_t doorbells_dropped = 0;
    uint32_t gpu_resets = 0;
    uint64_t gpu_cycles = 0;  // the clocks simulated
};

class Harness : NoCopy {
public:
    Harness(const char *prog, const HarnessOptions &o) : prog_(prog), hopt_(o) {}
    virtual ~Harness() = default;

    static void catch_signals();
    const HarnessOptions &options() const { return hopt_; }

    bool take_frame(const uint8_t *rgb, ModelCheck &model, uint64_t cycles, const std::string &detail,
                    std::string *error, const char **kind);
    uint32_t frames() const { return frames_; }
    struct FrameClock {
        double first_s = 0, last_s = 0;
        uint64_t first_cycles = 0, last_cycles = 0;
    };
    const FrameClock &frame_clock() const { return frame_clock_; }

protected:
    int open_outputs(const std::string &window_title);
    void close_outputs();
    // The run asks to stop: a signal caught, or Ctrl-C typed on the raw terminal. The keys typed
    // otherwise go to *keys.
    bool stop_requested(std::string *keys);
    // The window's keys for the firmware, "q" when it has just been closed (the firmware quits as
    // on Q; into *quit instead where given, for a harness that types the keys elsewhere); throttled
    // to 100 polls a second. window_given_up(grace_s): closed more than grace_s ago and the
    // firmware still runs.
    std::string window_keys(std::string *quit = nullptr);
    bool window_given_up(double grace_s) const;
    int end_by_window();  // "<prog>: the window was closed and the firmware did not quit: stopped", 0

    int fail(const char *kind, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
    int fail_signal() { return fail("signal", "stopped by signal %d", static_cast<int>(signal_)); }
    int end(int status, const char *kind);

    virtual void stop_parts() = 0;
    virtual HarnessCounts counts() const = 0;
    virtual void summary_keys(FILE *f) const = 0;

    const char *const prog_;
    const HarnessOptions &hopt_;
    UartPump uart_;
    UartPty pty_;
    UartTerminal terminal_;
    SdlWindow window_;
    int firmware_status_ = -1;  // once the firmware has ended

private:
    void write_summary(const char *error) const;
    static void on_signal(int sig) { signal_ = sig; }

    static volatile sig_atomic_t signal_;
    double window_polled_at_ = 0;
    double window_closed_at_ = -1;  // when the window was closed (the run is ending), or -1
    uint32_t frames_ = 0, frames_checked_ = 0;
    FrameClock frame_clock_;
};

#endif
