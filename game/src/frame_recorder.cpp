// FrameRecorder: render, read back into memory a finished frame gave back, queue for encoding.
// The render thread never encodes: zlib at ~10 ms a frame runs beside the next frame's physics
// and drawing, on the writer's worker thread.
#include "frame_recorder.hpp"

#include <algorithm>
#include <cstdio>
#include <string_view>

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

FrameRecorder::FrameRecorder(const std::filesystem::path& folder, render::FrameSize size)
    : start_(std::chrono::steady_clock::now()) {
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
    context_ = render::createOffscreenContext(size);
    renderer_ = std::make_unique<render::Renderer>(*context_);
    staleFramesRemoved_ = removeFrames(folder);
    // An earlier level run's summary would otherwise sit beside these frames until this run's
    // replaced it, and for good if this run fails before writing its own.
    std::filesystem::remove(folder / "summary.json", error);
}

FrameRecorder::~FrameRecorder() = default;

void FrameRecorder::record(const render::DrawList& list, const render::Camera& camera, std::int64_t index) {
    renderer_->draw(list, camera);
    render::Image frame = writer_->spareImage();
    renderer_->readPixels(frame);
    writer_->write(std::move(frame), frameFileName(index));
    ++queued_;
}

RecordingStats FrameRecorder::finish() {
    writer_->finish();
    return {writer_->framesWritten(), writer_->bytesWritten(), elapsedSeconds()};
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

std::unique_ptr<FrameRecorder> openFrameRecorder(const std::filesystem::path& folder, render::FrameSize size,
                                                 std::ostream& err, std::string_view who, ExitCode& exitStatus) {
    try {
        return std::make_unique<FrameRecorder>(folder, size);
    } catch (const OutputFolderError& e) {
        err << who << ": " << e.what() << '\n';
        exitStatus = ExitCode::badInput;
    } catch (const std::exception& e) {
        err << who << ": cannot render: " << e.what() << '\n';
        exitStatus = ExitCode::failed;
    }
    return nullptr;
}

} // namespace rube::game
