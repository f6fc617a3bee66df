// FrameRecorder: render, read back into memory a finished frame gave back, queue for encoding.
// The render thread never encodes: zlib at ~10 ms a frame runs beside the next frame's physics
// and drawing, on the writer's worker thread.
#include "frame_recorder.hpp"

#include "run_interrupt.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string_view>

#include <unistd.h>

namespace rube::game {

namespace {

// At most this many frames wait for the encoder: enough to ride out a slow write, and at
// 1280x720 only 11 MB of pixels.
constexpr int kQueueDepth = 4;

} // namespace

bool isFrameFileName(std::string_view name) {
    // frame_ + at least five digits + .png: exactly what frameFileName makes, nothing else.
    constexpr std::string_view prefix = "frame_", suffix = ".png";
    if (!name.starts_with(prefix) || !name.ends_with(suffix)) return false;
    const std::string_view digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    return digits.size() >= 5 && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

namespace {

// A frame's temporary file, left behind only when a run was killed while writing it:
// "." + a frame's name + ".<pid>-<n>.part" (see writeFileAtomically).
bool isUnfinishedFrameName(std::string_view name) {
    if (!name.starts_with('.') || !name.ends_with(".part")) return false;
    const std::size_t png = name.find(".png.");
    return png != std::string_view::npos && isFrameFileName(name.substr(1, png + 4 - 1));
}

} // namespace

std::int64_t removeFrames(const std::filesystem::path& folder) {
    std::int64_t removed = 0;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::string name = entry.path().filename().string();
        if (!entry.is_regular_file(error)) continue;
        // A killed run's unfinished frames go too (not counted: they were never frames).
        if (isUnfinishedFrameName(name)) std::filesystem::remove(entry.path(), error);
        else if (isFrameFileName(name) && std::filesystem::remove(entry.path(), error)) ++removed;
    }
    return removed;
}

std::string frameFileName(std::int64_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05lld.png", static_cast<long long>(index));
    return name;
}

namespace {

// ffmpeg is not installed: the environment, not the input, so exit status 1 like a missing GL.
struct FfmpegMissing : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The video's folder must exist and be writable before anything starts: bad input otherwise.
void checkVideoPath(const std::filesystem::path& video) {
    const std::filesystem::path folder = video.parent_path().empty() ? std::filesystem::path(".") : video.parent_path();
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        throw OutputFolderError("cannot write " + video.string() + ": " + folder.string() + " is not a folder");
    if (std::filesystem::is_directory(video, error))
        throw OutputFolderError("cannot write " + video.string() + ": it is a folder");
    if (::access(folder.c_str(), W_OK) != 0)
        throw OutputFolderError("cannot write " + video.string() + ": " + std::strerror(errno));
}

} // namespace

FrameRecorder::FrameRecorder(const RecordingTarget& target) : start_(std::chrono::steady_clock::now()) {
    const std::filesystem::path& folder = target.folder;
    if (!folder.empty()) {
        // The writer would create the folder too; doing it here gives the plain reason ("Not a directory").
        std::error_code error;
        std::filesystem::create_directories(folder, error);
        if (error) throw OutputFolderError("cannot write frames to " + folder.string() + ": " + error.message());
        // Before anything in the folder is touched: two runs into one folder would mix their frames.
        lock_ = std::make_unique<OutFolderLock>(folder);
        if (!lock_->locked()) throw OutputFolderError(lock_->why());
        try {
            writer_ = std::make_unique<render::FrameWriter>(folder, kQueueDepth);
        } catch (const std::exception& e) {
            throw OutputFolderError("cannot write frames to " + folder.string() + ": " + e.what());
        }
    }
    if (!target.video.empty()) {
        checkVideoPath(target.video);
        // A level's script may set an odd size after the command line was checked.
        const auto format = render::videoFormatOf(target.video);
        if (!format)
            throw OutputFolderError("cannot write " + target.video.string() + ": a video ends in .mp4, .webm or .gif");
        if (const std::string why = render::videoSizeProblem(*format, target.size); !why.empty())
            throw OutputFolderError("cannot write " + target.video.string() + ": " + why);
        if (render::findFfmpeg().empty()) throw FfmpegMissing(std::string(render::kFfmpegMissing));
    }
    context_ = render::createOffscreenContext(target.size, target.gl);
    renderer_ = std::make_unique<render::Renderer>(*context_);
    if (!target.video.empty())
        video_ = std::make_unique<render::VideoWriter>(target.video, target.size, target.framesPerSecond);
    if (!folder.empty()) {
        staleFramesRemoved_ = removeFrames(folder);
        // An earlier level run's summary would otherwise sit beside these frames until this run's
        // replaced it, and for good if this run fails before writing its own.
        std::error_code error;
        std::filesystem::remove(folder / "summary.json", error);
    }
}

FrameRecorder::~FrameRecorder() = default;

void FrameRecorder::record(const render::DrawList& list, const render::Camera& camera, std::int64_t index) {
    renderer_->draw(list, camera);
    // The video gets the very pixels the PNG gets: one readback, sent to ffmpeg, then queued.
    render::Image frame = writer_ ? writer_->spareImage() : std::move(videoFrame_);
    renderer_->readPixels(frame);
    if (video_) video_->write(frame);
    if (writer_) writer_->write(std::move(frame), frameFileName(index));
    else videoFrame_ = std::move(frame);
    ++queued_;
}

RecordingStats FrameRecorder::finish() {
    RecordingStats stats;
    stats.gl = std::string(context_->backendName());
    if (video_) {
        if (interrupted()) {
            video_->abandon();
        } else {
            video_->finish();
            stats.videoFrames = video_->frames();
            stats.videoBytes = video_->bytes();
        }
    }
    if (writer_) {
        writer_->finish();
        stats.frames = writer_->framesWritten();
        stats.bytes = writer_->bytesWritten();
    }
    stats.wallSeconds = elapsedSeconds();
    return stats;
}

double FrameRecorder::elapsedSeconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

ProgressLine::ProgressLine(std::ostream& out, bool enabled, std::int64_t totalFrames)
    : out_(out), enabled_(enabled), total_(totalFrames) {}

ProgressLine::~ProgressLine() {
    // "\r" and erase-to-end-of-line: the terminal is left as if the line had never been there.
    if (shown_) out_ << "\r\033[K" << std::flush;
}

void ProgressLine::update(std::int64_t frames, double seconds) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (shown_ && frames < total_ && now - lastShown_ < std::chrono::milliseconds(100)) return;
    lastShown_ = now;
    shown_ = true;
    char line[128];
    const double percent = total_ > 0 ? 100.0 * static_cast<double>(frames) / static_cast<double>(total_) : 100.0;
    std::snprintf(line, sizeof line, "\rrube run: frame %lld of %lld (%.0f %%), %.1f fps\033[K",
                  static_cast<long long>(frames), static_cast<long long>(total_), percent,
                  seconds > 0.0 ? static_cast<double>(frames) / seconds : 0.0);
    out_ << line << std::flush;
}

std::unique_ptr<FrameRecorder> openFrameRecorder(const RecordingTarget& target, std::ostream& err, std::string_view who,
                                                 ExitCode& exitStatus) {
    try {
        return std::make_unique<FrameRecorder>(target);
    } catch (const OutputFolderError& e) {
        err << who << ": " << e.what() << '\n';
        exitStatus = ExitCode::badInput;
    } catch (const FfmpegMissing& e) {
        err << who << ": --video: " << e.what() << '\n';
        exitStatus = ExitCode::failed;
    } catch (const std::exception& e) {
        err << who << ": cannot render: " << e.what() << '\n';
        exitStatus = ExitCode::failed;
    }
    return nullptr;
}

std::string recordingSummary(const RecordingTarget& target, const RecordingStats& stats) {
    std::string text = "gl:               " + stats.gl +
                       (target.gl == render::GlBackend::automatic ? " (chosen by --gl auto)" : "") + "\n";
    if (!target.video.empty() && stats.videoFrames > 0) {
        char line[160];
        std::snprintf(line, sizeof line, "%lld frames of %dx%d at %s fps, %lld bytes",
                      static_cast<long long>(stats.videoFrames), target.size.width, target.size.height,
                      render::ffmpegRate(target.framesPerSecond).c_str(), static_cast<long long>(stats.videoBytes));
        text += "video:            " + target.video.string() + " (" + line + ")\n";
    }
    return text;
}

} // namespace rube::game
