// shared_ram: the guest RAM both sides of the co-simulation see — a PLATFORM_RAM_BYTES file in
// /dev/shm that QEMU uses as its memory backend and this process maps MAP_SHARED.
//
// Contract: create() makes a new file with a unique name (pid and a time nonce, O_EXCL), unlinks it
// at once — QEMU reaches it through the inherited descriptor as /proc/self/fd/FD, and nothing is left
// behind however either process ends — sizes it and maps it. On failure it prints one
// "cosim: error: ..." line and returns false. The descriptor is inherited by QEMU (not O_CLOEXEC).
// close() unmaps and closes; safe to call twice. Shared RAM cannot trap accesses: the GPU's
// registers in it are polled (gpu_window()), with acquire/release fences around them.
#ifndef SHARED_RAM_H
#define SHARED_RAM_H

#include <cstdint>

#include "no_copy.h"

class SharedRam : NoCopy {
public:
    ~SharedRam() { close(); }

    bool create();
    void close();

    int fd() const { return fd_; }
    bool mapped() const { return base_ != nullptr; }
    // The GPU's bus window (PLATFORM_GPU_BASE) as 32-bit words: registers, then the data windows.
    volatile uint32_t *gpu_window() const;

private:
    int fd_ = -1;
    uint8_t *base_ = nullptr;
};

#endif
