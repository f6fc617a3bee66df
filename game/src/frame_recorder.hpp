#pragma once
/// FrameRecorder: renders draw lists offscreen and writes them as numbered PNG frames, the PNG
/// encoding running on the writer's thread while the caller simulates and draws the next frame.

#include "exit_codes.hpp"
#include "out_folder_lock.hpp"

#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"
#include "rube/render/frame_writer.hpp"
#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"
#include "rube/render/video_writer.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rube::game {

/// The output folder cannot be created or written: bad input, reported before anything is drawn.
struct OutputFolderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// "frame_00042.png": five digits, the numbering ffmpeg reads with `-i frame_%05d.png`.
std::string frameFileName(std::int64_t index);

/// Whether `name` is one of ours: frame_ and five or more digits, .png.
bool isFrameFileName(std::string_view name);

/// Removes the frames (files named as frameFileName makes them) in `folder` and returns how many,
/// so that a folder holds one run's frames only: ffmpeg's frame_%05d.png would otherwise carry
/// on into the tail of a longer earlier run. Other files are left alone.
std::int64_t removeFrames(const std::filesystem::path& folder);

/// Where a run's frames go: PNGs in a folder, a video, or both (the same frames).
struct RecordingTarget {
    std::filesystem::path folder;                        ///< --out: frame_00000.png, ...; empty for no PNGs
    std::filesystem::path video;                         ///< --video: .mp4, .webm or .gif; empty for none
    render::FrameSize size{1280, 720};                   ///< pixels
    render::GlBackend gl = render::GlBackend::automatic; ///< --gl
    double framesPerSecond = 60.0;                       ///< the video's rate: 1 / (time step x steps between frames)
};

/// What a recording produced, for the run summary.
struct RecordingStats {
    std::int64_t frames = 0;      ///< PNG files written
    std::int64_t bytes = 0;       ///< their total size
    std::int64_t videoFrames = 0; ///< frames in the video (0 without one, or when it was abandoned)
    std::int64_t videoBytes = 0;  ///< the video's size
    std::string gl;               ///< the offscreen back end that drew: "egl" or "osmesa"
    double wallSeconds = 0.0;     ///< from the recorder's creation to the last file on disk
    /// Frames per second, end to end; 0 before anything was written.
    double framesPerSecond() const { return wallSeconds > 0.0 ? static_cast<double>(frames) / wallSeconds : 0.0; }
    /// Mean PNG size, bytes.
    double bytesPerFrame() const { return frames > 0 ? static_cast<double>(bytes) / static_cast<double>(frames) : 0.0; }
};

/// Records frames into one folder and/or a video. The folder is checked first (OutputFolderError),
/// then ffmpeg's presence, then the GL context is made (std::runtime_error), and ffmpeg started
/// last, so a bad --out costs no GL start-up and writes nothing.
class FrameRecorder {
public:
    /// Frames of `target.size` into `target.folder`, created if missing and locked for this run's
    /// life (OutputFolderError when another run holds it; the frames and summary.json of an
    /// earlier run in it are removed once the folder and the GL context are known to work), and
    /// into `target.video` through ffmpeg.
    explicit FrameRecorder(const RecordingTarget& target);
    /// Writes the frames still queued (errors then are lost: call finish() to see them); a video
    /// not finished is abandoned (nothing under its name).
    ~FrameRecorder();
    FrameRecorder(const FrameRecorder&) = delete;
    FrameRecorder& operator=(const FrameRecorder&) = delete;

    /// Renders `list` through `camera` and queues it as frame number `index`; blocks only while
    /// the writer's queue is full. Throws the writer's first error (a full disk, say).
    void record(const render::DrawList& list, const render::Camera& camera, std::int64_t index);
    /// Waits until every frame is on disk and the video is encoded and renamed into place; throws
    /// the writer's first error or ffmpeg's failure. After SIGINT or SIGTERM (run_interrupt.hpp)
    /// the video is abandoned instead: a cut-short run leaves no video under the final name.
    RecordingStats finish();

    /// Frames queued so far.
    std::int64_t framesQueued() const { return queued_; }
    /// Seconds since the recorder was made.
    double elapsedSeconds() const;
    /// Frames of an earlier run that the constructor removed.
    std::int64_t staleFramesRemoved() const { return staleFramesRemoved_; }

private:
    std::chrono::steady_clock::time_point start_;
    std::unique_ptr<OutFolderLock> lock_; ///< taken first and released last: the folder is this run's
    // Declared in this order so the writer is made (checking the folder) before GL starts, and
    // the renderer is destroyed before its context and the writer drains last.
    std::unique_ptr<render::FrameWriter> writer_;
    std::unique_ptr<render::RenderContext> context_;
    std::unique_ptr<render::Renderer> renderer_;
    std::unique_ptr<render::VideoWriter> video_;
    render::Image videoFrame_; // the frame read back when there are no PNGs to queue it for
    std::int64_t queued_ = 0;
    std::int64_t staleFramesRemoved_ = 0;
};

/// A one-line progress display on a terminal: rewritten in place at most ten times a second,
/// and wiped when done, so the summary that follows starts on a clean line.
class ProgressLine {
public:
    /// Writes to `out` when `enabled`, otherwise never writes anything.
    ProgressLine(std::ostream& out, bool enabled, std::int64_t totalFrames);
    /// Wipes the line, if one was shown.
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    /// Shows that `frames` frames are done after `seconds` of wall clock.
    void update(std::int64_t frames, double seconds);

private:
    std::ostream& out_;
    bool enabled_;
    bool shown_ = false;
    std::int64_t total_;
    std::chrono::steady_clock::time_point lastShown_{};
};

/// Opens a FrameRecorder for the command line: on failure says why in one line on `err` (after
/// `who`, e.g. "rube run") and sets `exitStatus` to badInput for a folder or video path that
/// cannot be written, or failed when no GL context can be made or ffmpeg is missing; returns null then.
std::unique_ptr<FrameRecorder> openFrameRecorder(const RecordingTarget& target, std::ostream& err, std::string_view who,
                                                 ExitCode& exitStatus);

/// The summary's lines about the recording ("gl:", "video:") for `stats` of `target`, each ending in a newline.
std::string recordingSummary(const RecordingTarget& target, const RecordingStats& stats);

} // namespace rube::game
