#pragma once
/// FrameWriter: encodes and writes PNG frames on a worker thread while the caller renders the next.

#include "rube/render/image.hpp"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace rube::render {

/// Writes frames into one folder asynchronously. The queue is bounded: write() blocks while
/// `queueDepth` frames wait, so a fast renderer cannot eat all memory. Each file appears whole
/// or not at all (see writePng). The first error (an unwritable folder, a full disk) stops the
/// writer and is rethrown by the next write() or by finish().
class FrameWriter {
public:
    /// Creates the folder if needed and checks that a file can be written there; throws
    /// std::runtime_error naming the folder and the reason when it cannot.
    explicit FrameWriter(std::filesystem::path folder, int queueDepth = 4);
    /// Writes what is queued, then stops; errors at this point are lost: call finish() to see them.
    ~FrameWriter();
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    /// Queues `frame` to be written as folder/fileName; blocks while the queue is full.
    void write(Image frame, std::string fileName);
    /// Waits until every queued frame is on disk; throws the first error, if any.
    void finish();
    /// An image whose memory a written frame no longer needs (or an empty one), so that a
    /// render loop can read pixels into it without allocating a frame's worth each time.
    Image spareImage();

    /// The folder frames go to.
    const std::filesystem::path& folder() const { return folder_; }
    /// Frames written so far.
    std::int64_t framesWritten() const;
    /// PNG bytes written so far.
    std::int64_t bytesWritten() const;

private:
    struct Job {
        Image frame;
        std::string fileName;
    };
    void run();
    void rethrowError(); // called with mutex_ held

    std::filesystem::path folder_;
    std::size_t queueDepth_;
    mutable std::mutex mutex_;
    std::condition_variable workReady_;  // the worker waits for a job or for stop
    std::condition_variable spaceReady_; // write() and finish() wait for the worker
    std::deque<Job> queue_;
    std::vector<Image> spares_;
    bool busy_ = false; // the worker holds a job outside the queue
    bool stop_ = false;
    std::exception_ptr error_;
    std::int64_t framesWritten_ = 0;
    std::int64_t bytesWritten_ = 0;
    std::thread worker_; // last: started after everything it uses exists
};

} // namespace rube::render
