// uart_pump: see uart_pump.h.
#include "uart_pump.h"

#include <cerrno>
#include <cstring>

#include <sys/ioctl.h>
#include <unistd.h>

#include "uart_pty.h"

bool UartPump::open_log(const std::string &path)
{
    log_ = std::fopen(path.c_str(), "w");
    return log_ != nullptr;
}

void UartPump::close_log()
{
    if (log_) {
        std::fclose(log_);
        log_ = nullptr;
    }
}

void UartPump::feed(const char *data, size_t n)
{
    if (tee_ != nullptr) {
        tee_->write(data, n);
    }
    for (size_t i = 0; i < n; i++) {
        if (data[i] == '\r') {
            continue;
        }
        line_ += data[i];
        if (data[i] == '\n') {
            std::fputs(line_.c_str(), stdout);
            std::fflush(stdout);
            if (log_) {
                std::fputs(line_.c_str(), log_);
            }
            if (on_line_) {
                line_.pop_back();
                on_line_(line_);
            }
            line_.clear();
        }
    }
}

void UartPump::finish()
{
    if (!line_.empty()) {
        std::printf("%s\n", line_.c_str());
        line_.clear();
    }
    std::fflush(stdout);
}

void UartPump::pump(int uart_out_fd, bool final)
{
    char buf[4096];
    for (;;) {
        const ssize_t n = read(uart_out_fd, buf, sizeof buf);
        if (n <= 0) {
            break;
        }
        feed(buf, static_cast<size_t>(n));
    }
    if (final) {
        finish();
    }
    std::fflush(stdout);
}

bool UartPump::wait_taken(int uart_in_fd, double timeout_s)
{
    // FIONREAD on a pipe's write end counts the bytes the reader has not taken yet (Linux).
    for (double waited = 0; uart_in_fd >= 0; waited += 100e-6) {
        int pending = 0;
        if (ioctl(uart_in_fd, FIONREAD, &pending) != 0 || pending == 0) {
            return true;
        }
        if (waited >= timeout_s) {
            return false;
        }
        usleep(100);
    }
    return true;
}

void UartPump::type(int uart_in_fd, const std::string &text)
{
    if (uart_in_fd >= 0 && !text.empty() && write(uart_in_fd, text.data(), text.size()) < 0) {
        std::fprintf(stderr, "cosim: warning: cannot type keys: %s\n", std::strerror(errno));
    }
}
