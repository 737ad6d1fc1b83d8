// cosim_run: the co-simulation bridge. QEMU runs the firmware with its RAM in a shared-memory file;
// this process maps the same file, and whenever the firmware rings the GPU's DOORBELL it forwards the
// firmware's stores to the Verilated GPU through the GPU's own bus port, runs the GPU, captures the
// frame from the VGA pins, checks it against the golden model, writes it as a PNG, and copies the
// read-only registers back so the firmware sees DONE_SEQ.
//
// Determinism: simulated time advances only while a batch is serviced, so the same firmware gives
// the same frames byte for byte whatever the host's timing. Robustness: the shared-memory file is
// unlinked as soon as it is created (QEMU opens it through /proc/self/fd), QEMU dies with this process
// (PR_SET_PDEATHSIG), and this process notices QEMU's death, signals and a silent firmware.
#include <cerrno>
#include <cstdarg>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include "gpu_sim.h"
#include "model_check.h"

extern "C" {
#include "gpu_regs.h"
#include "platform.h"
#include "png_write.h"
}

namespace {

volatile sig_atomic_t g_signal = 0;
void on_signal(int sig) { g_signal = sig; }

struct Options {
    std::string firmware;
    std::string frames_dir = "out/frames";
    std::string qemu = "qemu-system-riscv32";
    std::string uart_log;
    double idle_timeout_s = 60.0;
    uint64_t max_batch_cycles = 100000000;  // 1 s of GPU time at 100 MHz
    bool check_model = true;
    std::vector<std::pair<uint32_t, std::string>> keys_at;  // (batch number, text) to type
    uint32_t drop_doorbell = 0;                              // batch number never serviced (0: none)
    std::string dump_lists;                                  // directory for each batch as a primitive list
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
                 "                    [--keys-at N:TEXT]... [--drop-doorbell N] [--dump-lists DIR]\n"
                 "  --keys-at N:TEXT   type TEXT into the firmware's UART just before servicing doorbell N (from 1)\n"
                 "  --drop-doorbell N  ignore doorbell N, as a hung GPU would (the firmware's watchdog must RESET)\n"
                 "  --dump-lists DIR   write each batch as DIR/batchNNNN.txt in the `make raster` list format\n"
                 "  With a terminal on stdin, keystrokes go to the firmware's UART; Ctrl-C ends the run.\n");
    return 2;
}

bool parse(int argc, char **argv, Options &o)
{
    for (int i = 0; i < argc; i++) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--fw" && has_value) {
            o.firmware = argv[++i];
        } else if (a == "--frames" && has_value) {
            o.frames_dir = argv[++i];
        } else if (a == "--qemu" && has_value) {
            o.qemu = argv[++i];
        } else if (a == "--uart-log" && has_value) {
            o.uart_log = argv[++i];
        } else if (a == "--idle-timeout" && has_value) {
            o.idle_timeout_s = std::atof(argv[++i]);
        } else if (a == "--max-batch-cycles" && has_value) {
            o.max_batch_cycles = std::strtoull(argv[++i], nullptr, 0);
        } else if (a == "--keys-at" && has_value) {
            const std::string spec = argv[++i];
            const size_t colon = spec.find(':');
            if (colon == std::string::npos || colon == 0) {
                std::fprintf(stderr, "cosim: --keys-at wants N:TEXT, got '%s'\n", spec.c_str());
                return false;
            }
            o.keys_at.emplace_back(static_cast<uint32_t>(std::strtoul(spec.c_str(), nullptr, 10)), spec.substr(colon + 1));
        } else if (a == "--dump-lists" && has_value) {
            o.dump_lists = argv[++i];
        } else if (a == "--drop-doorbell" && has_value) {
            o.drop_doorbell = static_cast<uint32_t>(std::strtoul(argv[++i], nullptr, 10));
        } else if (a == "--no-model-check") {
            o.check_model = false;
        } else {
            std::fprintf(stderr, "cosim: unknown or incomplete option '%s'\n", a.c_str());
            return false;
        }
    }
    return !o.firmware.empty();
}

class Bridge {
public:
    explicit Bridge(const Options &o) : opt_(o), model_(sim_.read(GPU_REG_CAPS)) {}
    ~Bridge() { shutdown(); }
    int run();

private:
    bool create_shared_ram();
    bool start_qemu();
    void pump_uart(bool final);
    void forward_keyboard();
    void type_keys(const std::string &text);
    void service_reset(uint32_t value);
    bool service_batch(uint32_t tag);
    void publish_registers();
    void dump_list();
    int fail(const char *fmt, ...) __attribute__((format(printf, 2, 3)));
    void shutdown();

    volatile uint32_t *aperture() const
    {
        return reinterpret_cast<volatile uint32_t *>(ram_ + (PLATFORM_GPU_BASE - PLATFORM_RAM_BASE));
    }

    const Options &opt_;
    GpuSim sim_;
    ModelCheck model_;
    int ram_fd_ = -1;
    uint8_t *ram_ = nullptr;
    pid_t qemu_pid_ = -1;
    int uart_fd_ = -1;     // firmware -> us (QEMU's stdout)
    int uart_in_fd_ = -1;  // us -> firmware (QEMU's stdin)
    bool raw_tty_ = false;
    termios saved_tty_{};
    FILE *uart_log_ = nullptr;
    std::string uart_line_;
    std::vector<uint32_t> shadow_ = std::vector<uint32_t>(GPU_APERTURE_BYTES / 4, 0);
    uint32_t frames_written_ = 0;
    uint32_t batches_ = 0;
};

int Bridge::fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    std::fputs("cosim: error: ", stderr);
    std::vfprintf(stderr, fmt, ap);
    std::fputc('\n', stderr);
    va_end(ap);
    shutdown();
    return 1;
}

bool Bridge::create_shared_ram()
{
    char name[96];
    unsigned nonce = static_cast<unsigned>(now_s() * 1e6) ^ static_cast<unsigned>(getpid() << 12);
    std::snprintf(name, sizeof name, "/dev/shm/gpu-cosim-%d-%08x", static_cast<int>(getpid()), nonce);
    ram_fd_ = open(name, O_RDWR | O_CREAT | O_EXCL, 0600);
    if (ram_fd_ < 0) {
        std::fprintf(stderr, "cosim: error: cannot create %s: %s\n", name, std::strerror(errno));
        return false;
    }
    // Unlink at once: QEMU reaches the file through our inherited descriptor, and nothing is left
    // behind however either process ends.
    unlink(name);
    if (ftruncate(ram_fd_, PLATFORM_RAM_BYTES) != 0) {
        std::fprintf(stderr, "cosim: error: cannot size shared RAM: %s\n", std::strerror(errno));
        return false;
    }
    void *p = mmap(nullptr, PLATFORM_RAM_BYTES, PROT_READ | PROT_WRITE, MAP_SHARED, ram_fd_, 0);
    if (p == MAP_FAILED) {
        std::fprintf(stderr, "cosim: error: cannot map shared RAM: %s\n", std::strerror(errno));
        return false;
    }
    ram_ = static_cast<uint8_t *>(p);
    return true;
}

bool Bridge::start_qemu()
{
    int pipe_fds[2];
    int in_fds[2];
    if (pipe2(pipe_fds, O_CLOEXEC) != 0 || pipe2(in_fds, O_CLOEXEC) != 0) {
        return false;
    }
    const pid_t parent = getpid();
    char ram_size[32], backend[160];
    std::snprintf(ram_size, sizeof ram_size, "%uM", PLATFORM_RAM_BYTES >> 20);
    std::snprintf(backend, sizeof backend,
                  "memory-backend-file,id=mem,size=%uM,mem-path=/proc/self/fd/%d,share=on",
                  PLATFORM_RAM_BYTES >> 20, ram_fd_);
    std::vector<const char *> args = {
        opt_.qemu.c_str(), "-machine", "virt,memory-backend=mem", "-m", ram_size, "-object", backend,
        "-bios", "none", "-kernel", opt_.firmware.c_str(), "-display", "none", "-serial", "stdio",
        "-monitor", "none", "-icount", "shift=0", "-no-reboot", nullptr};

    qemu_pid_ = fork();
    if (qemu_pid_ < 0) {
        return false;
    }
    if (qemu_pid_ == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL);  // the GPU side died: so does the CPU side
        if (getppid() != parent) {
            _exit(127);
        }
        dup2(pipe_fds[1], STDOUT_FILENO);
        dup2(in_fds[0], STDIN_FILENO);  // the UART's receive side: scripted or forwarded keys
        execvp(args[0], const_cast<char *const *>(args.data()));
        std::fprintf(stderr, "cosim: error: cannot run %s: %s\n", args[0], std::strerror(errno));
        _exit(127);
    }
    close(pipe_fds[1]);
    close(in_fds[0]);
    uart_fd_ = pipe_fds[0];
    uart_in_fd_ = in_fds[1];
    fcntl(uart_fd_, F_SETFL, O_NONBLOCK);
    if (isatty(STDIN_FILENO) && tcgetattr(STDIN_FILENO, &saved_tty_) == 0) {
        termios raw = saved_tty_;
        raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO | ISIG);
        raw.c_cc[VMIN] = 0;
        raw.c_cc[VTIME] = 0;
        raw_tty_ = tcsetattr(STDIN_FILENO, TCSANOW, &raw) == 0;
    }
    return true;
}

void Bridge::pump_uart(bool final)
{
    char buf[4096];
    for (;;) {
        ssize_t n = read(uart_fd_, buf, sizeof buf);
        if (n <= 0) {
            break;
        }
        for (ssize_t i = 0; i < n; i++) {
            if (buf[i] == '\r') {
                continue;
            }
            uart_line_ += buf[i];
            if (buf[i] == '\n') {
                std::fputs(uart_line_.c_str(), stdout);
                if (uart_log_) {
                    std::fputs(uart_line_.c_str(), uart_log_);
                }
                uart_line_.clear();
            }
        }
    }
    if (final && !uart_line_.empty()) {
        std::printf("%s\n", uart_line_.c_str());
        uart_line_.clear();
    }
    std::fflush(stdout);
}

void Bridge::type_keys(const std::string &text)
{
    if (uart_in_fd_ >= 0 && !text.empty() && write(uart_in_fd_, text.data(), text.size()) < 0) {
        std::fprintf(stderr, "cosim: warning: cannot type keys: %s\n", std::strerror(errno));
    }
}

// Interactive run: keystrokes go to the firmware; Ctrl-C (raw mode delivers it as a byte) ends the run.
void Bridge::forward_keyboard()
{
    if (!raw_tty_) {
        return;
    }
    pollfd p = {STDIN_FILENO, POLLIN, 0};
    if (poll(&p, 1, 0) <= 0) {
        return;
    }
    char buf[64];
    const ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
    for (ssize_t i = 0; i < n; i++) {
        if (buf[i] == 0x03) {
            g_signal = SIGINT;
            return;
        }
    }
    if (n > 0) {
        type_keys(std::string(buf, static_cast<size_t>(n)));
    }
}

// A new RESET value: forward it at once (a watchdog gave up on a batch), then report the new state.
void Bridge::service_reset(uint32_t value)
{
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    sim_.write(GPU_REG_RESET, value);
    if (opt_.check_model) {
        model_.write(GPU_REG_RESET, value);
    }
    shadow_[GPU_REG_RESET / 4] = value;
    std::printf("cosim: GPU reset by the firmware (RESET = %u)\n", value);
    publish_registers();
}

// The batch about to run, as a primitive list (vertices expanded; invalid primitives left out).
void Bridge::dump_list()
{
    const auto reg = [&](uint32_t offset) { return shadow_[offset / 4]; };
    char path[512];
    std::snprintf(path, sizeof path, "%s/batch%04u.txt", opt_.dump_lists.c_str(), batches_);
    FILE *f = std::fopen(path, "w");
    if (f == nullptr) {
        return;
    }
    if (reg(GPU_REG_CTRL) & GPU_CTRL_CLEAR_MASK) {
        std::fprintf(f, "clear %u\n", reg(GPU_REG_CLEAR_COLOR) & 0xFFu);
    }
    const uint32_t vbase = reg(GPU_REG_VTX_BASE), vcount = reg(GPU_REG_VTX_COUNT);
    const uint32_t tbase = reg(GPU_REG_TRI_BASE), tcount = reg(GPU_REG_TRI_COUNT);
    const auto vertex = [&](uint32_t i, int &x, int &y) {
        const uint32_t w = shadow_[(GPU_WIN_VTX + 8 * (vbase + i)) / 4];
        x = static_cast<int16_t>(w >> GPU_VTX_X_LSB);
        y = static_cast<int16_t>(w >> GPU_VTX_Y_LSB);
    };
    for (uint32_t t = 0; t < tcount && tbase + t < GPU_TRI_CAP && vbase + vcount <= GPU_VTX_CAP; t++) {
        const uint32_t w0 = shadow_[(GPU_WIN_IDX + 8 * (tbase + t)) / 4];
        const uint32_t w1 = shadow_[(GPU_WIN_IDX + 8 * (tbase + t) + 4) / 4];
        const uint32_t i0 = (w0 >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK, i1 = (w0 >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK;
        const uint32_t i2 = (w1 >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK;
        const uint32_t color = (w1 >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK;
        const uint32_t kind = (w1 >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK;
        int x0, y0, x1, y1, x2, y2;
        if (i0 >= vcount || i1 >= vcount) {
            continue;
        }
        vertex(i0, x0, y0);
        vertex(i1, x1, y1);
        if (kind == GPU_PRIM_KIND_LINE) {
            std::fprintf(f, "line %d %d %d %d %u\n", x0, y0, x1, y1, color);
        } else if (kind == GPU_PRIM_KIND_TRI && i2 < vcount) {
            vertex(i2, x2, y2);
            std::fprintf(f, "tri %d %d %d %d %d %d %u\n", x0, y0, x1, y1, x2, y2, color);
        }
    }
    std::fclose(f);
}

// Copy the GPU's read-only registers into the shared window, DONE_SEQ last (kReadOnlyRegs order).
void Bridge::publish_registers()
{
    volatile uint32_t *ap = aperture();
    for (int i = 0; i < kReadOnlyRegCount; i++) {
        const uint32_t offset = kReadOnlyRegs[i];
        const uint32_t value = sim_.read(offset);
        if (offset == GPU_REG_DONE_SEQ) {
            __atomic_thread_fence(__ATOMIC_RELEASE);
        }
        ap[offset / 4] = value;
        shadow_[offset / 4] = value;
    }
}

bool Bridge::service_batch(uint32_t tag)
{
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    volatile uint32_t *ap = aperture();
    const uint32_t doorbell_word = GPU_REG_DOORBELL / 4;
    // Replay the firmware's stores: every word that changed since the last batch, DOORBELL last.
    for (uint32_t w = 0; w < shadow_.size(); w++) {
        const uint32_t value = ap[w];
        if (value != shadow_[w] && w != doorbell_word) {
            sim_.write(w * 4, value);
            if (opt_.check_model) {
                model_.write(w * 4, value);
            }
            shadow_[w] = value;
        }
    }
    if (batches_ + 1 == opt_.drop_doorbell) {
        batches_++;
        shadow_[doorbell_word] = tag;
        std::printf("cosim: doorbell %u (tag %u) dropped on purpose (--drop-doorbell)\n", batches_, tag);
        return true;
    }
    if (!opt_.dump_lists.empty()) {
        dump_list();
    }
    const uint32_t frames_before = sim_.read(GPU_REG_FRAME_COUNT);
    sim_.write(GPU_REG_DOORBELL, tag);
    if (opt_.check_model) {
        model_.write(GPU_REG_DOORBELL, tag);
    }
    shadow_[doorbell_word] = tag;
    batches_++;

    if (!sim_.wait_done(tag, opt_.max_batch_cycles)) {
        fail("GPU timeout: batch %u (tag %u) did not finish within %llu cycles", batches_, tag,
             static_cast<unsigned long long>(opt_.max_batch_cycles));
        return false;
    }
    if (opt_.check_model) {
        const std::string diff = model_.compare_registers(sim_);
        if (!diff.empty()) {
            fail("batch %u: RTL and golden model disagree: %s", batches_, diff.c_str());
            return false;
        }
    }
    if (sim_.read(GPU_REG_FRAME_COUNT) != frames_before) {
        const uint64_t frame_cycles = 800ull * 525 * 4;
        if (!sim_.capture_frame(3 * frame_cycles)) {
            fail("no frame captured from the VGA pins: %s", sim_.vga_error()[0] ? sim_.vga_error() : "timeout");
            return false;
        }
        if (opt_.check_model) {
            const std::string diff = model_.compare_frame(sim_.frame_rgb());
            if (!diff.empty()) {
                fail("frame %u: VGA output differs from the golden model: %s", frames_written_, diff.c_str());
                return false;
            }
        }
        char path[512];
        std::snprintf(path, sizeof path, "%s/%04u.png", opt_.frames_dir.c_str(), frames_written_);
        if (png_write_rgb(path, sim_.frame_rgb(), VGA_W, VGA_H) != 0) {
            fail("cannot write %s", path);
            return false;
        }
        std::printf("cosim: frame %04u -> %s | gpu busy %u cycles | simulated %llu cycles%s\n", frames_written_,
                    path, sim_.read(GPU_REG_PERF_BUSY_CYCLES), static_cast<unsigned long long>(sim_.cycles()),
                    opt_.check_model ? " | equals golden model" : "");
        frames_written_++;
    }
    publish_registers();
    return true;
}

int Bridge::run()
{
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    std::signal(SIGHUP, on_signal);
    std::signal(SIGPIPE, SIG_IGN);

    if (mkdir(opt_.frames_dir.c_str(), 0755) != 0 && errno != EEXIST) {
        return fail("cannot create %s: %s", opt_.frames_dir.c_str(), std::strerror(errno));
    }
    if (!opt_.uart_log.empty() && (uart_log_ = std::fopen(opt_.uart_log.c_str(), "w")) == nullptr) {
        return fail("cannot create %s: %s", opt_.uart_log.c_str(), std::strerror(errno));
    }
    if (!create_shared_ram()) {
        return fail("shared RAM setup failed");
    }
    publish_registers();  // ID, VERSION, CAPS ... are readable before the first doorbell
    if (!start_qemu()) {
        return fail("cannot start QEMU: %s", std::strerror(errno));
    }

    double last_activity = now_s();
    for (;;) {
        if (g_signal) {
            return fail("stopped by signal %d", static_cast<int>(g_signal));
        }
        int status = 0;
        pid_t done = waitpid(qemu_pid_, &status, WNOHANG);
        if (done == qemu_pid_) {
            qemu_pid_ = -1;
            pump_uart(true);
            if (WIFSIGNALED(status)) {
                return fail("QEMU was killed by signal %d", WTERMSIG(status));
            }
            if (WEXITSTATUS(status) != 0) {
                return fail("firmware ended with exit status %d", WEXITSTATUS(status));
            }
            std::printf("cosim: firmware finished: %u batches, %u frames, %llu GPU cycles simulated\n", batches_,
                        frames_written_, static_cast<unsigned long long>(sim_.cycles()));
            shutdown();
            return 0;
        }
        pump_uart(false);
        forward_keyboard();
        const uint32_t reset = __atomic_load_n(&aperture()[GPU_REG_RESET / 4], __ATOMIC_ACQUIRE);
        if (reset != shadow_[GPU_REG_RESET / 4]) {
            service_reset(reset);
            last_activity = now_s();
        }
        const uint32_t tag = __atomic_load_n(&aperture()[GPU_REG_DOORBELL / 4], __ATOMIC_ACQUIRE);
        if (tag != shadow_[GPU_REG_DOORBELL / 4]) {
            pump_uart(false);  // what the firmware printed before ringing comes first
            for (const auto &k : opt_.keys_at) {
                if (k.first == batches_ + 1) {
                    type_keys(k.second);
                }
            }
            if (!service_batch(tag)) {
                return 1;
            }
            last_activity = now_s();
        } else {
            if (now_s() - last_activity > opt_.idle_timeout_s) {
                return fail("the firmware rang no doorbell for %.0f s: giving up", opt_.idle_timeout_s);
            }
            usleep(20);
        }
    }
}

void Bridge::shutdown()
{
    if (qemu_pid_ > 0) {
        kill(qemu_pid_, SIGKILL);
        waitpid(qemu_pid_, nullptr, 0);
        qemu_pid_ = -1;
    }
    if (raw_tty_) {
        tcsetattr(STDIN_FILENO, TCSANOW, &saved_tty_);
        raw_tty_ = false;
    }
    if (uart_in_fd_ >= 0) {
        close(uart_in_fd_);
        uart_in_fd_ = -1;
    }
    if (uart_fd_ >= 0) {
        pump_uart(true);
        close(uart_fd_);
        uart_fd_ = -1;
    }
    if (uart_log_) {
        std::fclose(uart_log_);
        uart_log_ = nullptr;
    }
    if (ram_) {
        munmap(ram_, PLATFORM_RAM_BYTES);
        ram_ = nullptr;
    }
    if (ram_fd_ >= 0) {
        close(ram_fd_);
        ram_fd_ = -1;
    }
}

}  // namespace

int cosim_main(int argc, char **argv)
{
    Options o;
    if (!parse(argc, argv, o)) {
        return usage();
    }
    Bridge bridge(o);
    return bridge.run();
}
