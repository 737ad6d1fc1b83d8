// uart_terminal: an interactive run — with a terminal on stdin, its keystrokes are meant for the
// firmware's UART, and Ctrl-C ends the run.
//
// Contract: enter_raw() switches a terminal stdin to raw mode (no line editing, no echo, no signal
// keys) and does nothing when stdin is not a terminal; restore() puts the saved mode back (safe to
// call twice, and done by the destructor). read_keys() never blocks: it returns the bytes typed since
// the last call, or sets *ctrl_c when they include Ctrl-C (raw mode delivers it as byte 0x03, not as
// SIGINT), in which case no key is returned.
#ifndef UART_TERMINAL_H
#define UART_TERMINAL_H

#include <string>

#include <termios.h>

#include "no_copy.h"

class UartTerminal : NoCopy {
public:
    ~UartTerminal() { restore(); }

    void enter_raw();
    void restore();
    std::string read_keys(bool *ctrl_c);

private:
    bool raw_ = false;
    termios saved_{};
};

#endif
