#pragma once
/// The trace: a CSV of every dynamic body's state at every step, for plots and exact comparisons.
///
/// Header `step,time,body,x,y,vx,vy,angle,omega,radius`; step 0 is the initial state, then one
/// block of rows per step. `body` is the circle's index in the World, or `b<slot>` for a box or capsule
/// (radius empty), after the circles. Doubles are printed with
/// %.17g, so a trace reads back bit-exact and two runs can be compared byte for byte.

#include "rube/physics/world.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

namespace rube::game {

/// The trace's header line, without the newline.
inline constexpr const char* kTraceHeader = "step,time,body,x,y,vx,vy,angle,omega,radius";
/// A level's trace: every dynamic body, circles as `c<slot>` and boxes and capsules as `b<slot>`
/// (radius empty), with the name of what it is in `item` (LevelRun::nameOf: the item, the cannon a
/// shot came from, the scene's circle or box; empty when unnamed).
inline constexpr const char* kLevelTraceHeader = "step,time,body,item,x,y,vx,vy,angle,omega,radius";

/// Writes a trace into a temporary file beside its target and renames it into place only when the
/// run has finished, so a failed or interrupted run never leaves a half-written trace behind.
class TraceWriter {
public:
    TraceWriter() = default;
    /// Discards the temporary file unless commit() succeeded.
    ~TraceWriter();
    TraceWriter(const TraceWriter&) = delete;
    TraceWriter& operator=(const TraceWriter&) = delete;

    /// Creates the temporary file and writes `header`; false, with `error` set, when it cannot.
    /// First removes the temporaries of this target left by runs whose process is gone (SIGKILL).
    bool open(const std::filesystem::path& target, std::string& error, const char* header = kTraceHeader);
    /// Appends one row per dynamic circle in the world's current state, then one per dynamic box or
    /// capsule (`b<slot>`, radius empty).
    void writeState(const World& world);
    /// Appends a level trace's rows (kLevelTraceHeader): every dynamic circle, then every dynamic
    /// rigid body, with `circleName(id)` and `bodyName(slot)` in the item column.
    void writeLevelState(const World& world, const std::function<std::string(CircleId)>& circleName,
                         const std::function<std::string(int)>& bodyName);
    /// Finishes the file and renames it onto the target; false, with `error` set, when that fails.
    bool commit(std::string& error);
    /// Deletes the temporary file; the target is left as it was.
    void discard();
    /// The rows written so far, not counting the header.
    std::int64_t rows() const { return rows_; }

private:
    void writeCircles(const World& world, const std::function<std::string(CircleId)>* circleName);
    /// The dynamic rigid bodies' rows; with `bodyName`, a level's item column after `b<slot>`.
    void writeBodies(const World& world, const std::function<std::string(int)>* bodyName);

    std::FILE* file_ = nullptr;
    std::filesystem::path target_;
    std::filesystem::path temporary_;
    std::int64_t rows_ = 0;
};

} // namespace rube::game
