// qemu_process: the CPU side of the co-simulation — QEMU (`virt`, -icount shift=0) running the
// firmware with the shared RAM as its memory backend and its UART on two pipes.
//
// Contract: start() forks and execs QEMU with the shared file as /proc/self/fd/RAM_FD, the UART's
// output on uart_out_fd() (non-blocking, read by this process) and its input on uart_in_fd() (written
// by this process). With gdb_port > 0 QEMU also offers its GDB stub on tcp:127.0.0.1:gdb_port and
// starts halted at reset (-S) until a debugger connects and continues. QEMU is killed with SIGKILL when this process dies (PR_SET_PDEATHSIG; a child
// whose parent is already gone exits at once), so it never outlives the harness. reap() polls
// without blocking: true once QEMU has ended, with its wait status. kill() ends a running QEMU and
// waits for it; close_pipes() closes this side's ends. Both are safe to call twice.
#ifndef QEMU_PROCESS_H
#define QEMU_PROCESS_H

#include <string>

#include <sys/types.h>

#include "no_copy.h"

class QemuProcess : NoCopy {
public:
    ~QemuProcess() { kill(); }

    // False with errno set if a pipe or the fork failed (an exec failure shows as exit status 127).
    // gdb_port 0: no GDB stub, the firmware starts at once.
    bool start(const std::string &qemu, const std::string &firmware, int ram_fd, int gdb_port = 0);
    bool reap(int *status);
    void kill();
    bool running() const { return pid_ > 0; }
    pid_t pid() const { return pid_; }

    int uart_out_fd() const { return uart_out_fd_; }  // firmware -> us (QEMU's stdout)
    int uart_in_fd() const { return uart_in_fd_; }    // us -> firmware (QEMU's stdin)
    void close_uart_in();
    void close_uart_out();

private:
    pid_t pid_ = -1;
    int uart_out_fd_ = -1;
    int uart_in_fd_ = -1;
};

#endif
