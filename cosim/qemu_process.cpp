// qemu_process: see qemu_process.h.
#include "qemu_process.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern "C" {
#include "platform.h"
}

namespace {
constexpr int kQemuNice = 10;  // below the harness (0): see start()
}

bool QemuProcess::start(const std::string &qemu, const std::string &firmware, int ram_fd, int gdb_port)
{
    int pipe_fds[2];
    int in_fds[2];
    if (pipe2(pipe_fds, O_CLOEXEC) != 0 || pipe2(in_fds, O_CLOEXEC) != 0) {
        return false;
    }
    const pid_t parent = getpid();
    char ram_size[32], backend[160], gdb[48];
    std::snprintf(ram_size, sizeof ram_size, "%uM", PLATFORM_RAM_BYTES >> 20);
    std::snprintf(backend, sizeof backend,
                  "memory-backend-file,id=mem,size=%uM,mem-path=/proc/self/fd/%d,share=on",
                  PLATFORM_RAM_BYTES >> 20, ram_fd);
    std::vector<const char *> args = {
        qemu.c_str(), "-machine", "virt,memory-backend=mem", "-m", ram_size, "-object", backend,
        "-bios", "none", "-kernel", firmware.c_str(), "-display", "none", "-serial", "stdio",
        "-monitor", "none", "-icount", "shift=0", "-no-reboot"};
    if (gdb_port > 0) {
        std::snprintf(gdb, sizeof gdb, "tcp:127.0.0.1:%d", gdb_port);
        args.insert(args.end(), {"-gdb", gdb, "-S"});  // halted at reset until the debugger continues
    }
    args.push_back(nullptr);

    pid_ = fork();
    if (pid_ < 0) {
        return false;
    }
    if (pid_ == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL);  // the GPU side died: so does the CPU side
        if (getppid() != parent) {
            _exit(127);
        }
        dup2(pipe_fds[1], STDOUT_FILENO);
        dup2(in_fds[0], STDIN_FILENO);  // the UART's receive side: scripted or forwarded keys
        // While the harness simulates a batch, the firmware only polls DONE_SEQ: QEMU spins. At a
        // lower priority the spin takes only CPU time nobody else wants (the harness's, another
        // run's), and the firmware's own work is milliseconds a frame.
        if (setpriority(PRIO_PROCESS, 0, kQemuNice) != 0) {
            std::fprintf(stderr, "cosim: warning: cannot lower QEMU's priority: %s\n", std::strerror(errno));
        }
        execvp(args[0], const_cast<char *const *>(args.data()));
        std::fprintf(stderr, "cosim: error: cannot run %s: %s\n", args[0], std::strerror(errno));
        _exit(127);
    }
    close(pipe_fds[1]);
    close(in_fds[0]);
    uart_out_fd_ = pipe_fds[0];
    uart_in_fd_ = in_fds[1];
    fcntl(uart_out_fd_, F_SETFL, O_NONBLOCK);
    return true;
}

bool QemuProcess::reap(int *status)
{
    if (pid_ <= 0) {
        return false;
    }
    if (waitpid(pid_, status, WNOHANG) == pid_) {
        pid_ = -1;
        return true;
    }
    return false;
}

void QemuProcess::kill()
{
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
        pid_ = -1;
    }
}

void QemuProcess::close_uart_in()
{
    if (uart_in_fd_ >= 0) {
        close(uart_in_fd_);
        uart_in_fd_ = -1;
    }
}

void QemuProcess::close_uart_out()
{
    if (uart_out_fd_ >= 0) {
        close(uart_out_fd_);
        uart_out_fd_ = -1;
    }
}
