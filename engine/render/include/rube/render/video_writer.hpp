#pragma once
/// VideoWriter: frames piped as raw RGB to Debian's ffmpeg, which encodes an .mp4, .webm or .gif.

#include "rube/render/camera.hpp"
#include "rube/render/image.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <sys/types.h>

namespace rube::render {

/// The containers `rube run --video` writes, chosen by the file's extension.
enum class VideoFormat {
    mp4,  ///< H.264 (libx264), yuv420p: plays everywhere; needs an even width and height
    webm, ///< VP9 (libvpx-vp9), yuv420p
    gif,  ///< a palette generated from the frames themselves (palettegen, paletteuse without dithering)
};

/// The format for `file`'s extension (.mp4, .webm, .gif, any case); nothing for any other.
std::optional<VideoFormat> videoFormatOf(const std::filesystem::path& file);

/// Why `size` cannot be encoded as `format` (one phrase), or "" when it can.
std::string videoSizeProblem(VideoFormat format, FrameSize size);

/// ffmpeg's path found on PATH, or empty when it is not installed.
std::filesystem::path findFfmpeg();

/// The one-line reason given when ffmpeg is missing: names the Debian package.
inline constexpr std::string_view kFfmpegMissing =
    "ffmpeg is not installed (not found on PATH): apt-get install ffmpeg";

/// "60", "60/7" or "30000/1001": a frame rate as ffmpeg's -framerate reads it, the closest fraction
/// with a denominator of at most 1001 (exact for 1 / (dt x K) when dt is 1/N seconds).
std::string ffmpegRate(double framesPerSecond);

/// Encodes one video. ffmpeg runs as a child process (spawned with an argument vector, no shell,
/// in its own process group so a terminal's Ctrl-C reaches only rube, which then abandons the
/// video) and writes a temporary file beside the final one, renamed over it only when ffmpeg
/// has finished without error: an interrupted or failed run leaves nothing under the final name.
class VideoWriter {
public:
    /// Starts ffmpeg for frames of `size` at `framesPerSecond`. Throws std::runtime_error when
    /// ffmpeg is missing (kFfmpegMissing), the extension or size does not fit, or it cannot start.
    VideoWriter(std::filesystem::path file, FrameSize size, double framesPerSecond);
    /// Abandons the video unless finish() succeeded.
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    /// Sends one frame (of the constructor's size, RGB, top row first). Throws when ffmpeg has
    /// stopped reading (it failed: its last message and status are in the exception).
    void write(const Image& frame);
    /// Ends the input, waits for ffmpeg and renames the video into place. Throws with ffmpeg's
    /// last message and its exit status when it failed (the temporary file is removed then).
    void finish();
    /// Stops ffmpeg and removes the temporary file; the final name is never touched.
    void abandon();

    /// Frames sent so far.
    std::int64_t frames() const { return frames_; }
    /// The finished video's size in bytes (0 before finish()).
    std::int64_t bytes() const { return bytes_; }
    /// The video's final path.
    const std::filesystem::path& file() const { return file_; }
    /// The temporary file ffmpeg writes: "." + the name + ".<pid>.part" in the same folder.
    const std::filesystem::path& temporaryFile() const { return temporary_; }

private:
    std::string ffmpegFailure(int status);

    std::filesystem::path file_;
    std::filesystem::path temporary_;
    std::filesystem::path log_; // ffmpeg's stderr, read back for the one-line reason of a failure
    FrameSize size_;
    pid_t child_ = -1;
    int input_ = -1; // the pipe to ffmpeg's stdin
    std::int64_t frames_ = 0;
    std::int64_t bytes_ = 0;
    bool done_ = false;
};

} // namespace rube::render
