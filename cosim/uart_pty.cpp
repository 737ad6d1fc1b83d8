// uart_pty: see uart_pty.h.
#include "uart_pty.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

namespace {

bool set_flags(int fd)
{
    const int fl = fcntl(fd, F_GETFL);
    return fl >= 0 && fcntl(fd, F_SETFL, fl | O_NONBLOCK) == 0 && fcntl(fd, F_SETFD, FD_CLOEXEC) == 0;
}

std::string failed(const char *what)
{
    return std::string(what) + ": " + std::strerror(errno);
}

}  // namespace

bool UartPty::open(const std::string &link, std::string *error)
{
    close();
    master_ = posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0) {
        *error = failed("posix_openpt");
        return false;
    }
    char name[128];
    if (!set_flags(master_) || grantpt(master_) != 0 || unlockpt(master_) != 0 ||
        ptsname_r(master_, name, sizeof name) != 0) {
        *error = failed("pty master setup");
        close();
        return false;
    }
    slave_path_ = name;
    // O_NOCTTY: the pty must never become this process's controlling terminal (a client's hang-up
    // would then be a SIGHUP to the simulation).
    slave_ = ::open(name, O_RDWR | O_NOCTTY);
    termios t;
    if (slave_ < 0 || !set_flags(slave_) || tcgetattr(slave_, &t) != 0) {
        *error = failed(name);
        close();
        return false;
    }
    cfmakeraw(&t);
    if (tcsetattr(slave_, TCSANOW, &t) != 0) {
        *error = failed("tcsetattr");
        close();
        return false;
    }
    // A symbolic link left by a run that did not end cleanly is replaced; a file or directory that
    // is not ours is never removed.
    struct stat st;
    if (lstat(link.c_str(), &st) == 0) {
        if (!S_ISLNK(st.st_mode)) {
            *error = link + " exists and is not a symbolic link";
            close();
            return false;
        }
        unlink(link.c_str());
    }
    if (symlink(name, link.c_str()) != 0) {
        *error = failed(("symlink " + link).c_str());
        close();
        return false;
    }
    link_ = link;
    return true;
}

void UartPty::close()
{
    // Closing the master hangs the slave up, which discards what a client has not read yet: the
    // firmware's last lines (a result the client waits for) would be lost. So the client gets up
    // to kDrainMs to read them; what is still queued then has no reader. The kernel moves the
    // master's last write into the slave's queue a little later (its flip buffer's work), so an
    // empty queue counts only when it is seen twice, 10 ms apart (seen here: a lost last newline).
    int empty_seen = 0;
    for (int ms = 0; slave_ >= 0 && ms < kDrainMs && empty_seen < 2; ms += 10) {
        int queued = 0;
        if (ioctl(slave_, TIOCINQ, &queued) != 0) {
            break;
        }
        empty_seen = (queued == 0) ? empty_seen + 1 : 0;
        usleep(10000);
    }
    if (!link_.empty()) {
        // Only our own link: another run may have taken the name over since.
        char target[256];
        const ssize_t n = readlink(link_.c_str(), target, sizeof target - 1);
        if (n > 0 && std::string(target, static_cast<size_t>(n)) == slave_path_) {
            unlink(link_.c_str());
        }
        link_.clear();
    }
    if (slave_ >= 0) {
        ::close(slave_);
        slave_ = -1;
    }
    if (master_ >= 0) {
        ::close(master_);
        master_ = -1;
    }
}

std::string UartPty::read(size_t max)
{
    std::string out;
    char buf[512];
    while (master_ >= 0 && out.size() < max) {
        const size_t want = std::min(sizeof buf, max - out.size());
        const ssize_t n = ::read(master_, buf, want);
        if (n <= 0) {
            break;  // EAGAIN: nothing more for now
        }
        out.append(buf, static_cast<size_t>(n));
    }
    bytes_in_ += out.size();
    return out;
}

void UartPty::write(const char *data, size_t n)
{
    if (master_ < 0) {
        return;
    }
    while (n > 0) {
        const ssize_t w = ::write(master_, data, n);
        if (w <= 0) {
            if (w < 0 && errno == EINTR) {
                continue;
            }
            break;  // EAGAIN: the pty is full, nobody is reading
        }
        bytes_out_ += static_cast<uint64_t>(w);
        data += w;
        n -= static_cast<size_t>(w);
    }
    bytes_dropped_ += n;
}
