// VideoWriter: ffmpeg as a child process reading raw rgb24 frames on its standard input.
// The input is one end of a Unix socket pair rather than a pipe so that writing after ffmpeg
// died returns EPIPE (send with MSG_NOSIGNAL) instead of killing rube with SIGPIPE, without
// touching the process's signal dispositions.
#include "rube/render/video_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

#include <csignal>
#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rube::render {

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string errnoText(int error) { return std::strerror(error); }

// The encoder's arguments after the input's. Quality settings: visually lossless for the flat
// greybox colours (crf 18 for H.264, 32 for VP9 at constant quality), fast presets because a
// playthrough is encoded while it is simulated.
std::vector<std::string> encoderArguments(VideoFormat format) {
    switch (format) {
    case VideoFormat::mp4:
        return {"-c:v",     "libx264", "-preset",   "veryfast",   "-crf", "18",
                "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f",   "mp4"};
    case VideoFormat::webm:
        return {"-c:v", "libvpx-vp9", "-deadline", "realtime", "-cpu-used", "8",  "-crf",
                "32",   "-b:v",       "0",         "-pix_fmt", "yuv420p",   "-f", "webm"};
    case VideoFormat::gif:
        // One palette for the whole clip, made from every frame's colours (palettegen), then
        // applied without dithering, so flat fills stay flat and outlines keep clean edges.
        // palettegen sees the last frame before the first is written: ffmpeg holds the frames
        // until the input ends, so GIFs are for short clips.
        return {"-filter_complex",
                "[0:v]split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=none",
                "-loop",
                "0",
                "-f",
                "gif"};
    }
    return {};
}

// The last line ffmpeg wrote (at -loglevel error, its reason), or "" when it wrote none.
std::string lastLine(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string line, last;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    }
    return last;
}

// A SIGKILLed run cannot clean up: its ffmpeg finishes the temporary file and it stays. The next
// run writing the same video removes the temporaries of runs whose process is gone.
void removeDeadRunsTemporaries(const std::filesystem::path& folder, const std::string& name) {
    const std::string prefix = "." + name + ".";
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::string file = entry.path().filename().string();
        if (!file.starts_with(prefix)) continue;
        const std::string rest = file.substr(prefix.size());
        const std::size_t dot = rest.find('.');
        if (dot == std::string::npos || (rest.substr(dot) != ".part" && rest.substr(dot) != ".log")) continue;
        const std::string digits = rest.substr(0, dot);
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
            continue;
        const pid_t pid = static_cast<pid_t>(std::stol(digits));
        if (::kill(pid, 0) != 0 && errno == ESRCH) std::filesystem::remove(entry.path(), error);
    }
}

} // namespace

std::optional<VideoFormat> videoFormatOf(const std::filesystem::path& file) {
    const std::string extension = lower(file.extension().string());
    if (extension == ".mp4") return VideoFormat::mp4;
    if (extension == ".webm") return VideoFormat::webm;
    if (extension == ".gif") return VideoFormat::gif;
    return std::nullopt;
}

std::string videoSizeProblem(VideoFormat format, FrameSize size) {
    // H.264 in 4:2:0 halves both chroma sides, and libx264 refuses odd ones rather than pad.
    if (format == VideoFormat::mp4 && (size.width % 2 != 0 || size.height % 2 != 0))
        return "H.264 (.mp4) needs an even width and height, got " + std::to_string(size.width) + "x" +
               std::to_string(size.height);
    return "";
}

std::filesystem::path findFfmpeg() {
    const char* path = std::getenv("PATH");
    std::string_view rest = path != nullptr ? path : "";
    while (true) {
        const std::size_t colon = rest.find(':');
        const std::string_view dir = rest.substr(0, colon);
        const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : std::string(dir)) / "ffmpeg";
        if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
        if (colon == std::string_view::npos) return {};
        rest.remove_prefix(colon + 1);
    }
}

std::string ffmpegRate(double framesPerSecond) {
    // The continued fraction of the rate, up to the last convergent whose denominator is at most
    // 1001 (NTSC's 30000/1001): 1 / (dt x K) for a dt of 1/N seconds comes out as N/K exactly,
    // and a convergent p/q is within 1/q^2 of the rate.
    long long p0 = 0, q0 = 1, p1 = 1, q1 = 0; // convergents p(k-2)/q(k-2), p(k-1)/q(k-1)
    double x = framesPerSecond;
    for (int k = 0; k < 64; ++k) {
        const double a = std::floor(x);
        const long long p2 = static_cast<long long>(a) * p1 + p0, q2 = static_cast<long long>(a) * q1 + q0;
        if (q2 > 1001) break;
        p0 = p1, q0 = q1, p1 = p2, q1 = q2;
        const double fraction = x - a;
        // Close enough to exact: dt = 1/60 is not exactly representable, so 1/dt misses 60 by an ulp.
        if (fraction < 1e-9 * x ||
            std::abs(static_cast<double>(p1) / static_cast<double>(q1) - framesPerSecond) < 1e-9 * framesPerSecond)
            break;
        x = 1.0 / fraction;
    }
    return q1 == 1 ? std::to_string(p1) : std::to_string(p1) + "/" + std::to_string(q1);
}

VideoWriter::VideoWriter(std::filesystem::path file, FrameSize size, double framesPerSecond)
    : file_(std::move(file)), size_(size) {
    const std::optional<VideoFormat> format = videoFormatOf(file_);
    if (!format) throw std::runtime_error("cannot write " + file_.string() + ": a video ends in .mp4, .webm or .gif");
    if (const std::string why = videoSizeProblem(*format, size); !why.empty())
        throw std::runtime_error("cannot write " + file_.string() + ": " + why);
    if (!(framesPerSecond > 0.0)) throw std::runtime_error("cannot write " + file_.string() + ": no frame rate");
    const std::filesystem::path ffmpeg = findFfmpeg();
    if (ffmpeg.empty()) throw std::runtime_error(std::string(kFfmpegMissing));

    const std::string pid = std::to_string(::getpid());
    const std::filesystem::path folder = file_.parent_path().empty() ? std::filesystem::path(".") : file_.parent_path();
    // Built by append: GCC 12 warns falsely (-Wrestrict) on "." + a temporary string.
    std::string hidden(".");
    hidden.append(file_.filename().string()).append(".").append(pid);
    temporary_ = folder / (hidden + ".part");
    log_ = folder / (hidden + ".log");
    removeDeadRunsTemporaries(folder, file_.filename().string());
    const int log = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (log < 0) throw std::runtime_error("cannot write " + file_.string() + ": " + errnoText(errno));

    int sockets[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
        const int error = errno;
        ::close(log);
        std::filesystem::remove(log_);
        throw std::runtime_error("cannot start ffmpeg: socketpair: " + errnoText(error));
    }
    // A frame of 1280x720 is 2.7 MB: a larger buffer lets ffmpeg read while rube draws.
    const int buffer = 4 << 20;
    ::setsockopt(sockets[0], SOL_SOCKET, SO_SNDBUF, &buffer, sizeof buffer);

    std::vector<std::string> arguments = {ffmpeg.string(),
                                          "-hide_banner",
                                          "-loglevel",
                                          "error",
                                          "-y",
                                          "-f",
                                          "rawvideo",
                                          "-pix_fmt",
                                          "rgb24",
                                          "-video_size",
                                          std::to_string(size.width) + "x" + std::to_string(size.height),
                                          "-framerate",
                                          ffmpegRate(framesPerSecond),
                                          "-i",
                                          "pipe:0"};
    for (std::string& a : encoderArguments(*format)) arguments.push_back(std::move(a));
    arguments.push_back(temporary_.string());
    std::vector<char*> argv;
    for (std::string& a : arguments) argv.push_back(a.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, sockets[1], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, log, STDERR_FILENO);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    // Its own process group: Ctrl-C on the terminal goes to rube, which abandons the video,
    // not to ffmpeg, which would close a half video. Signals rube catches are reset by exec.
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    const int spawned = ::posix_spawn(&child_, argv[0], &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(sockets[1]);
    ::close(log);
    if (spawned != 0) {
        child_ = -1;
        ::close(sockets[0]);
        std::filesystem::remove(log_);
        throw std::runtime_error("cannot start " + ffmpeg.string() + ": " + errnoText(spawned));
    }
    input_ = sockets[0];
}

VideoWriter::~VideoWriter() {
    if (!done_) abandon();
}

void VideoWriter::write(const Image& frame) {
    if (input_ < 0) throw std::runtime_error("video " + file_.string() + ": written after it was finished");
    if (frame.width != size_.width || frame.height != size_.height)
        throw std::runtime_error("video " + file_.string() + ": a frame of the wrong size");
    const std::uint8_t* data = frame.pixel(0, 0);
    std::size_t left = static_cast<std::size_t>(size_.width) * static_cast<std::size_t>(size_.height) * 3;
    while (left > 0) {
        const ssize_t sent = ::send(input_, data, left, MSG_NOSIGNAL);
        if (sent < 0 && errno == EINTR) continue;
        if (sent < 0) {
            // ffmpeg stopped reading: it failed, and its own message says why.
            ::close(input_);
            input_ = -1;
            int status = 0;
            while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {}
            child_ = -1;
            done_ = true;
            std::error_code ignored;
            std::filesystem::remove(temporary_, ignored);
            const std::string why = ffmpegFailure(status);
            std::filesystem::remove(log_, ignored);
            throw std::runtime_error(why);
        }
        data += sent;
        left -= static_cast<std::size_t>(sent);
    }
    ++frames_;
}

void VideoWriter::finish() {
    if (done_) return;
    done_ = true;
    ::close(input_); // end of input: ffmpeg flushes and writes the container's index
    input_ = -1;
    int status = 0;
    while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {}
    child_ = -1;
    std::error_code error;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::filesystem::remove(temporary_, error);
        const std::string why = ffmpegFailure(status);
        std::filesystem::remove(log_, error);
        throw std::runtime_error(why);
    }
    std::filesystem::remove(log_, error);
    std::filesystem::rename(temporary_, file_, error);
    if (error) {
        std::filesystem::remove(temporary_);
        throw std::runtime_error("cannot write " + file_.string() + ": " + error.message());
    }
    bytes_ = static_cast<std::int64_t>(std::filesystem::file_size(file_, error));
}

void VideoWriter::abandon() {
    done_ = true;
    if (input_ >= 0) ::close(input_);
    input_ = -1;
    if (child_ > 0) {
        ::kill(child_, SIGKILL);
        int status = 0;
        while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {}
        child_ = -1;
    }
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    std::filesystem::remove(log_, ignored);
}

std::string VideoWriter::ffmpegFailure(int status) {
    std::string text = "ffmpeg failed to write " + file_.string();
    if (WIFEXITED(status)) text += " (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
    else if (WIFSIGNALED(status)) text += " (killed by signal " + std::to_string(WTERMSIG(status)) + ")";
    const std::string last = lastLine(log_);
    return last.empty() ? text : text + ": " + last;
}

} // namespace rube::render
