// no_copy: the base of the harness's classes that own something their destructor gives back — a
// process (QemuProcess), a mapping (SharedRam), a terminal mode (UartTerminal), a pty (UartPty), a
// log file (UartPump), a window (SdlWindow), a run's state (Harness). A copy would give it back
// twice, so none of them can be copied.
//
// Contract: a class derived from NoCopy (`class X : NoCopy`, private) has no copy constructor and
// no copy assignment; its own constructors and destructor are as it declares them (with none
// declared, the implicit default constructor).
#ifndef NO_COPY_H
#define NO_COPY_H

class NoCopy {
public:
    NoCopy(const NoCopy &) = delete;
    NoCopy &operator=(const NoCopy &) = delete;

protected:
    NoCopy() = default;
    ~NoCopy() = default;
};

#endif
