// Reading and writing the small text files of a run (scenes, levels, scripts, summaries) with
// bounded work: a read never takes more than kMaxTextFileBytes + 1 bytes nor waits on a FIFO,
// and a write that fails says why and leaves no temporary behind.
#include "scene_errors.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rube::game {

namespace {

// Closes a descriptor on every way out of readTextFile.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

std::string tooLarge(const std::string& size) {
    return "file too large: " + size + " bytes, at most " + std::to_string(kMaxTextFileBytes) + " (4 MiB)";
}

} // namespace

std::optional<std::string> readTextFile(const std::filesystem::path& file, SceneError& error) {
    error = SceneError{file.string(), {}, ""};
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer, possibly for ever.
    const FileDescriptor fd(::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    struct stat status {};
    if (fd.get() < 0 || ::fstat(fd.get(), &status) != 0 || S_ISDIR(status.st_mode)) {
        error.message = "cannot open file";
        return std::nullopt;
    }
    // A FIFO, a socket or a device (/dev/zero, /dev/urandom) has no end that can be trusted:
    // refused before the first byte is read.
    if (!S_ISREG(status.st_mode)) {
        error.message = "not a regular file (a FIFO, socket or device cannot be a scene, level or script)";
        return std::nullopt;
    }
    // Scenes, levels and scripts are written by hand: a file this big is a mistake (or not a
    // scene at all), and reading it whole would only waste memory before failing anyway.
    if (static_cast<std::uintmax_t>(status.st_size) > kMaxTextFileBytes) {
        error.message = tooLarge(std::to_string(status.st_size));
        return std::nullopt;
    }
    // The size is only a hint (a file still growing, or /proc's files that report 0): the bytes
    // read are counted too, and reading stops one byte past the limit.
    std::string text;
    text.resize(kMaxTextFileBytes + 1);
    std::size_t got = 0;
    while (got < text.size()) {
        const ssize_t n = ::read(fd.get(), text.data() + got, text.size() - got);
        if (n == 0) break;
        if (n < 0) {
            if (errno == EINTR) continue;
            error.message = std::string("cannot read file: ") + std::strerror(errno);
            return std::nullopt;
        }
        got += static_cast<std::size_t>(n);
    }
    if (got > kMaxTextFileBytes) {
        error.message = tooLarge("more than " + std::to_string(kMaxTextFileBytes));
        return std::nullopt;
    }
    text.resize(got);
    return text;
}

bool writeTextFileAtomically(const std::filesystem::path& file, const std::string& text, std::string& reason) {
    const std::filesystem::path temporary = file.string() + ".tmp";
    std::FILE* out = std::fopen(temporary.c_str(), "wb");
    if (!out) {
        reason = std::strerror(errno);
        return false;
    }
    // A full disk shows at fwrite, at fflush or only at fclose: the first failure's errno is kept.
    int failure = 0;
    if (std::fwrite(text.data(), 1, text.size(), out) != text.size() || std::fflush(out) != 0) failure = errno;
    if (std::fclose(out) != 0 && failure == 0) failure = errno;
    std::error_code ec;
    if (failure == 0) {
        std::filesystem::rename(temporary, file, ec);
        if (!ec) return true;
        reason = ec.message();
    } else {
        reason = std::strerror(failure);
    }
    std::filesystem::remove(temporary, ec); // nothing half-written stays behind
    return false;
}

} // namespace rube::game
