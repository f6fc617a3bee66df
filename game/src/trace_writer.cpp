// The trace CSV: written to a temporary file, renamed into place at the end.
#include "trace_writer.hpp"

#include <cerrno>
#include <cstring>
#include <signal.h>
#include <unistd.h>

namespace rube::game {

namespace {

std::string describeErrno(int error) { return std::strerror(error); }

// Removes TARGET.tmp-PID files whose process is gone: a run killed with SIGKILL (or a crash)
// cannot remove its own temporary. A live process's, another run writing the same trace, stays.
void removeOrphanedTemporaries(const std::filesystem::path& target) {
    const std::string prefix = target.filename().string() + ".tmp-";
    std::filesystem::path folder = target.parent_path();
    if (folder.empty()) folder = ".";
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with(prefix) || name.size() == prefix.size()) continue;
        const std::string digits = name.substr(prefix.size());
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
        const pid_t pid = static_cast<pid_t>(std::stol(digits));
        if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) std::filesystem::remove(entry.path(), ec);
    }
}

} // namespace

TraceWriter::~TraceWriter() { discard(); }

bool TraceWriter::open(const std::filesystem::path& target, std::string& error, const char* header) {
    std::error_code ec;
    if (std::filesystem::is_directory(target, ec)) {
        error = target.string() + ": cannot write trace: it is a directory";
        return false;
    }
    removeOrphanedTemporaries(target);
    target_ = target;
    // Same folder as the target, so the final rename stays on one file system and is atomic;
    // the process id keeps two runs writing the same trace from sharing a temporary file.
    temporary_ = target;
    temporary_ += ".tmp-" + std::to_string(::getpid());
    file_ = std::fopen(temporary_.c_str(), "wx");
    if (!file_) {
        error = target.string() + ": cannot write trace: " + describeErrno(errno);
        temporary_.clear(); // not ours: discard() must not delete a file another run created
        return false;
    }
    // A large buffer: a pile of 1000 balls writes a row per ball per step.
    std::setvbuf(file_, nullptr, _IOFBF, 1 << 20);
    std::fprintf(file_, "%s\n", header);
    return true;
}

namespace {

// A name as one CSV field: quoted, with quotes doubled, when it holds a comma, quote or line break.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

} // namespace

void TraceWriter::writeCircles(const World& world, const std::function<std::string(CircleId)>* circleName) {
    const long long step = static_cast<long long>(world.stats().steps);
    const auto circles = world.circles();
    for (std::size_t i = 0; i < circles.size(); ++i) {
        const Circle& c = circles[i];
        if (c.motion != Motion::dynamic) continue;
        // A scene's row names the circle by its slot; a level's by c<slot> and its item's name.
        if (circleName)
            std::fprintf(file_, "%lld,%.17g,c%zu,%s,", step, world.time(), i,
                         csvField((*circleName)(world.circleId(static_cast<int>(i)))).c_str());
        else std::fprintf(file_, "%lld,%.17g,%zu,", step, world.time(), i);
        std::fprintf(file_, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", c.position.x, c.position.y, c.velocity.x,
                     c.velocity.y, c.angle, c.angularVelocity, c.radius);
        ++rows_;
    }
}

void TraceWriter::writeState(const World& world) {
    if (!file_) return;
    writeCircles(world, nullptr);
    // Then the boxes and capsules, b<slot> in the scene's numbering (every [[box]], then every
    // [[capsule]]), radius empty: a scene without them writes the same bytes as before they had rows.
    writeBodies(world, nullptr);
}

void TraceWriter::writeLevelState(const World& world, const std::function<std::string(CircleId)>& circleName,
                                  const std::function<std::string(int)>& bodyName) {
    if (!file_) return;
    writeCircles(world, &circleName);
    writeBodies(world, &bodyName);
}

void TraceWriter::writeBodies(const World& world, const std::function<std::string(int)>* bodyName) {
    const long long step = static_cast<long long>(world.stats().steps);
    const auto bodies = world.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        if (b.motion != Motion::dynamic) continue;
        std::fprintf(file_, "%lld,%.17g,b%zu,", step, world.time(), i);
        if (bodyName) std::fprintf(file_, "%s,", csvField((*bodyName)(static_cast<int>(i))).c_str());
        std::fprintf(file_, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,\n", b.position.x, b.position.y, b.velocity.x,
                     b.velocity.y, b.angle, b.angularVelocity);
        ++rows_;
    }
}

bool TraceWriter::commit(std::string& error) {
    if (!file_) return false;
    const bool writeFailed = std::ferror(file_) != 0;
    const bool closeFailed = std::fclose(file_) != 0;
    file_ = nullptr;
    if (writeFailed || closeFailed) {
        error = target_.string() + ": cannot write trace: " + describeErrno(errno);
        discard();
        return false;
    }
    std::error_code ec;
    std::filesystem::rename(temporary_, target_, ec);
    if (ec) {
        error = target_.string() + ": cannot write trace: " + ec.message();
        discard();
        return false;
    }
    temporary_.clear();
    return true;
}

void TraceWriter::discard() {
    if (file_) {
        std::fclose(file_);
        file_ = nullptr;
    }
    if (!temporary_.empty()) {
        std::error_code ec;
        std::filesystem::remove(temporary_, ec);
        temporary_.clear();
    }
}

} // namespace rube::game
