// shared_ram: see shared_ram.h.
#include "shared_ram.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

extern "C" {
#include "platform.h"
}

bool SharedRam::create()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    const double now = ts.tv_sec + ts.tv_nsec * 1e-9;
    char name[96];
    unsigned nonce = static_cast<unsigned>(now * 1e6) ^ static_cast<unsigned>(getpid() << 12);
    std::snprintf(name, sizeof name, "/dev/shm/gpu-cosim-%d-%08x", static_cast<int>(getpid()), nonce);
    fd_ = open(name, O_RDWR | O_CREAT | O_EXCL, 0600);
    if (fd_ < 0) {
        std::fprintf(stderr, "cosim: error: cannot create %s: %s\n", name, std::strerror(errno));
        return false;
    }
    // Unlink at once: QEMU reaches the file through our inherited descriptor, and nothing is left
    // behind however either process ends.
    unlink(name);
    if (ftruncate(fd_, PLATFORM_RAM_BYTES) != 0) {
        std::fprintf(stderr, "cosim: error: cannot size shared RAM: %s\n", std::strerror(errno));
        return false;
    }
    void *p = mmap(nullptr, PLATFORM_RAM_BYTES, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
    if (p == MAP_FAILED) {
        std::fprintf(stderr, "cosim: error: cannot map shared RAM: %s\n", std::strerror(errno));
        return false;
    }
    base_ = static_cast<uint8_t *>(p);
    return true;
}

void SharedRam::close()
{
    if (base_) {
        munmap(base_, PLATFORM_RAM_BYTES);
        base_ = nullptr;
    }
    if (fd_ >= 0) {
        ::close(fd_);
        fd_ = -1;
    }
}

volatile uint32_t *SharedRam::gpu_window() const
{
    return reinterpret_cast<volatile uint32_t *>(base_ + (PLATFORM_GPU_BASE - PLATFORM_RAM_BASE));
}
