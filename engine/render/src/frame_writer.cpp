// FrameWriter: one worker thread encodes and writes while the caller renders. A bounded queue
// gives back-pressure; finished frames' memory comes back through spareImage().
#include "rube/render/frame_writer.hpp"

#include <stdexcept>
#include <system_error>

namespace rube::render {

FrameWriter::FrameWriter(std::filesystem::path folder, int queueDepth)
    : folder_(std::move(folder)), queueDepth_(static_cast<std::size_t>(queueDepth < 1 ? 1 : queueDepth)) {
    std::error_code error;
    std::filesystem::create_directories(folder_, error);
    if (error) {
        throw std::runtime_error("frame writer: cannot create the folder " + folder_.string() + ": " + error.message());
    }
    if (!std::filesystem::is_directory(folder_)) {
        throw std::runtime_error("frame writer: " + folder_.string() + " is not a folder");
    }
    // Fail now, in the caller's thread, rather than after the first frame has been rendered.
    try {
        writeFileAtomically(folder_ / ".rube-frame-writer-probe", {});
        std::filesystem::remove(folder_ / ".rube-frame-writer-probe", error);
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("frame writer: the folder is not writable: ") + e.what());
    }
    worker_ = std::thread([this] { run(); });
}

FrameWriter::~FrameWriter() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    workReady_.notify_all();
    worker_.join();
}

void FrameWriter::rethrowError() {
    if (error_) std::rethrow_exception(error_);
}

void FrameWriter::write(Image frame, std::string fileName) {
    std::unique_lock lock(mutex_);
    spaceReady_.wait(lock, [&] { return queue_.size() < queueDepth_ || error_; });
    rethrowError();
    queue_.push_back(Job{std::move(frame), std::move(fileName)});
    lock.unlock();
    workReady_.notify_one();
}

void FrameWriter::finish() {
    std::unique_lock lock(mutex_);
    spaceReady_.wait(lock, [&] { return (queue_.empty() && !busy_) || error_; });
    rethrowError();
}

Image FrameWriter::spareImage() {
    std::lock_guard lock(mutex_);
    if (spares_.empty()) return {};
    Image image = std::move(spares_.back());
    spares_.pop_back();
    return image;
}

std::int64_t FrameWriter::framesWritten() const {
    std::lock_guard lock(mutex_);
    return framesWritten_;
}

std::int64_t FrameWriter::bytesWritten() const {
    std::lock_guard lock(mutex_);
    return bytesWritten_;
}

void FrameWriter::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        // On stop, the queue is still drained: the destructor promises the frames get written.
        workReady_.wait(lock, [&] { return !queue_.empty() || stop_; });
        if (queue_.empty() || error_) return;
        Job job = std::move(queue_.front());
        queue_.pop_front();
        busy_ = true;
        lock.unlock();
        spaceReady_.notify_all();

        std::exception_ptr failure;
        std::size_t bytes = 0;
        try {
            std::vector<std::uint8_t> png = encodePng(job.frame);
            bytes = png.size();
            writeFileAtomically(folder_ / job.fileName, png);
        } catch (...) {
            failure = std::current_exception();
        }

        lock.lock();
        busy_ = false;
        if (failure) {
            // The first error wins and stops the writer: later frames would fail the same way.
            error_ = failure;
            queue_.clear();
        } else {
            ++framesWritten_;
            bytesWritten_ += static_cast<std::int64_t>(bytes);
            if (spares_.size() < queueDepth_ + 1) spares_.push_back(std::move(job.frame));
        }
        spaceReady_.notify_all();
    }
}

} // namespace rube::render
