#pragma once
/// OutFolderLock: one rube run at a time writes into an output folder. The lock is flock(2) on
/// DIR/.rube.lock, held for the run's life; the kernel drops it when the process ends however it
/// ends (even SIGKILL), so a killed run never blocks the next one.

#include <filesystem>
#include <string>

namespace rube::game {

/// The name of the lock file in an output folder; it stays there between runs (removing it would
/// let two runs lock two different files of the same name).
inline constexpr const char* kOutFolderLockName = ".rube.lock";

/// An exclusive lock on an output folder, or the reason it could not be taken.
class OutFolderLock {
public:
    /// Takes the lock on `folder` (which must exist) without waiting: when another run holds it,
    /// locked() is false and why() says "DIR is in use by another rube run (pid N)".
    explicit OutFolderLock(const std::filesystem::path& folder);
    /// Releases the lock (the file stays).
    ~OutFolderLock();
    OutFolderLock(const OutFolderLock&) = delete;
    OutFolderLock& operator=(const OutFolderLock&) = delete;

    /// Whether this run holds the folder.
    bool locked() const { return fd_ >= 0; }
    /// Why the lock was not taken; empty when it was.
    const std::string& why() const { return why_; }

private:
    int fd_ = -1;
    std::string why_;
};

} // namespace rube::game
