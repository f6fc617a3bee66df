// The output folder's lock: flock on DIR/.rube.lock, the holder's pid written in it for the message.
#include "out_folder_lock.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace rube::game {

OutFolderLock::OutFolderLock(const std::filesystem::path& folder) {
    const std::filesystem::path file = folder / kOutFolderLockName;
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        why_ = "cannot lock " + folder.string() + ": " + std::strerror(errno);
        return;
    }
    // LOCK_NB: a second run refuses at once rather than waiting for the first to finish.
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        char text[32] = {};
        const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
        ::close(fd);
        const std::string pid = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string("unknown");
        why_ = error == EWOULDBLOCK ? folder.string() + " is in use by another rube run (pid " + pid + ")"
                                    : "cannot lock " + folder.string() + ": " + std::strerror(error);
        return;
    }
    // The holder's pid, only for the refusal's message: the lock itself is the flock.
    const std::string pid = std::to_string(::getpid());
    // Best effort: a lock file that cannot hold the pid still locks; a refusal then says "pid unknown".
    const bool pidWritten = ::ftruncate(fd, 0) == 0 &&
                            ::pwrite(fd, pid.data(), pid.size(), 0) == static_cast<ssize_t>(pid.size());
    static_cast<void>(pidWritten);
    fd_ = fd;
}

OutFolderLock::~OutFolderLock() {
    if (fd_ >= 0) ::close(fd_); // closing the last descriptor releases the flock
}

} // namespace rube::game
