// uart_pty: the firmware's UART as a pseudo-terminal, so that a program that speaks to a serial port
// (tools/mesh_upload.py, a terminal emulator, pyserial) talks to a co-simulated firmware the way it
// talks to a board's /dev/ttyUSB0. `gpusim cosim --uart-pty LINK` and `socsim --uart-pty LINK`.
//
// Contract: open() creates a pty pair, sets the slave side raw (cfmakeraw: 8 bits clean, no echo, no
// CR/LF translation, no signal characters) and makes LINK a symbolic link to the slave's path; a
// stale symbolic link at LINK (a run that was killed) is replaced, anything else there is refused.
// The pty keeps a slave fd open itself, so that a client's close never turns the master's reads
// into EIO (a client may come, go and come back during one run) and the firmware's output before
// the first client waits in the pty rather than being lost. Both fds are non-blocking and
// close-on-exec (QEMU must not inherit them). read() returns what clients wrote since the last
// call, at most max bytes, without blocking. write() hands the firmware's output to the pty
// without ever blocking the simulation: what does not fit in the pty's buffer (nobody reads it) is
// dropped and counted. close() first gives a client up to kDrainMs to read what is still queued
// (closing the master discards it), then removes LINK if it still points at this pty's slave; it
// is safe to call twice (the destructor calls it).
#ifndef UART_PTY_H
#define UART_PTY_H

#include <cstddef>
#include <cstdint>
#include <string>

#include "no_copy.h"

class UartPty : NoCopy {
public:
    ~UartPty() { close(); }

    // False with *error set (the step that failed and why).
    bool open(const std::string &link, std::string *error);
    void close();
    bool is_open() const { return master_ >= 0; }

    std::string read(size_t max);
    void write(const char *data, size_t n);

    const std::string &link() const { return link_; }
    const std::string &slave_path() const { return slave_path_; }
    uint64_t bytes_in() const { return bytes_in_; }          // read from clients
    uint64_t bytes_out() const { return bytes_out_; }        // accepted by the pty
    uint64_t bytes_dropped() const { return bytes_dropped_; }  // the pty's buffer was full

    // Long enough for a client starved by a loaded machine (make test runs two suites per core
    // pair); a run whose pty has no reader ends this much later.
    static constexpr int kDrainMs = 2000;

private:
    int master_ = -1;
    int slave_ = -1;  // held open: see the contract
    std::string link_;
    std::string slave_path_;
    uint64_t bytes_in_ = 0, bytes_out_ = 0, bytes_dropped_ = 0;
};

#endif
