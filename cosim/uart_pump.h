// uart_pump: the firmware's UART as the harness sees it (cosim/harness) — what the firmware prints
// goes to stdout (and a log file), line by line; typed or scripted keys go to the firmware.
//
// Contract: feed() takes the firmware's bytes as they came, from any source (socsim decodes them
// from the TX pin), drops '\r', and writes each complete line to stdout and the log, flushing
// stdout after a line, so the firmware's lines and the harness's own "cosim: ..." / "socsim: ..."
// lines appear in the order they happened. finish() writes an unfinished last line (with a '\n'
// added, on stdout only). pump() drains what QEMU's UART output pipe holds without blocking into
// feed() (finish() too with final set) and flushes stdout on every call. type() writes keys to
// QEMU's UART input pipe (a failure is a warning, not an error). The pipes belong to QemuProcess;
// a closed pipe (-1) is simply skipped. With tee_to(pty), every byte fed also goes to the pty
// (cosim/uart_pty) as it came, '\r' included: a client there sees the raw line. With on_line(fn),
// fn sees each complete line too (without its '\n'), after it was written.
#ifndef UART_PUMP_H
#define UART_PUMP_H

#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>

#include "no_copy.h"

class UartPty;

class UartPump : NoCopy {
public:
    ~UartPump() { close_log(); }

    bool open_log(const std::string &path);  // false if the file cannot be created (errno set)
    void close_log();
    void feed(const char *data, size_t n);
    void finish();
    void pump(int uart_out_fd, bool final);
    void type(int uart_in_fd, const std::string &text);
    // Waits (up to timeout_s) until QEMU has read everything typed into its UART: its serial port
    // then holds the bytes (the firmware enables the 16-byte FIFO), so a script's keys reach the
    // firmware at the frame they were typed for whatever the host's load. False on the timeout.
    bool wait_taken(int uart_in_fd, double timeout_s);
    void tee_to(UartPty *pty) { tee_ = pty; }
    void on_line(std::function<void(const std::string &)> fn) { on_line_ = std::move(fn); }

private:
    FILE *log_ = nullptr;
    std::string line_;
    UartPty *tee_ = nullptr;
    std::function<void(const std::string &)> on_line_;
};

#endif
