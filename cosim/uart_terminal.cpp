// uart_terminal: see uart_terminal.h.
#include "uart_terminal.h"

#include <poll.h>
#include <unistd.h>

void UartTerminal::enter_raw()
{
    if (isatty(STDIN_FILENO) && tcgetattr(STDIN_FILENO, &saved_) == 0) {
        termios raw = saved_;
        raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO | ISIG);
        raw.c_cc[VMIN] = 0;
        raw.c_cc[VTIME] = 0;
        raw_ = tcsetattr(STDIN_FILENO, TCSANOW, &raw) == 0;
    }
}

void UartTerminal::restore()
{
    if (raw_) {
        tcsetattr(STDIN_FILENO, TCSANOW, &saved_);
        raw_ = false;
    }
}

std::string UartTerminal::read_keys(bool *ctrl_c)
{
    *ctrl_c = false;
    if (!raw_) {
        return "";
    }
    pollfd p = {STDIN_FILENO, POLLIN, 0};
    if (poll(&p, 1, 0) <= 0) {
        return "";
    }
    char buf[64];
    const ssize_t n = read(STDIN_FILENO, buf, sizeof buf);
    for (ssize_t i = 0; i < n; i++) {
        if (buf[i] == 0x03) {
            *ctrl_c = true;
            return "";
        }
    }
    return n > 0 ? std::string(buf, static_cast<size_t>(n)) : std::string();
}
