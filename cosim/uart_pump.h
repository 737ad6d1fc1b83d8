// uart_pump: the firmware's UART as this process sees it — what the firmware prints goes to stdout
// (and a log file), line by line; typed or scripted keys go to the firmware.
//
// Contract: pump() drains what the UART's output pipe holds without blocking, drops '\r', and writes
// each complete line to stdout and the log; with final set it also writes an unfinished last line
// (with a '\n' added, on stdout only). stdout is flushed on every call, so the firmware's lines and
// the harness's own "cosim: ..." lines appear in the order they happened. type() writes keys to the
// UART's input pipe (a failure is a warning, not an error). The pipes belong to QemuProcess; a
// closed pipe (-1) is simply skipped. With tee_to(pty), every byte read from the UART also goes to
// the pty (cosim/uart_pty) as it came, '\r' included: a client there sees the raw line. With
// on_line(fn), fn sees each complete line too (without its '\n'), after it was written.
#ifndef UART_PUMP_H
#define UART_PUMP_H

#include <cstdio>
#include <functional>
#include <string>

class UartPty;

class UartPump {
public:
    UartPump() = default;
    UartPump(const UartPump &) = delete;
    UartPump &operator=(const UartPump &) = delete;
    ~UartPump() { close_log(); }

    bool open_log(const std::string &path);  // false if the file cannot be created (errno set)
    void close_log();
    void pump(int uart_out_fd, bool final);
    void type(int uart_in_fd, const std::string &text);
    void tee_to(UartPty *pty) { tee_ = pty; }
    void on_line(std::function<void(const std::string &)> fn) { on_line_ = std::move(fn); }

private:
    FILE *log_ = nullptr;
    std::string line_;
    UartPty *tee_ = nullptr;
    std::function<void(const std::string &)> on_line_;
};

#endif
