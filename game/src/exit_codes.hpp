#pragma once
/// The `rube` command's exit statuses, named once: every command returns one of these, and main()
/// turns it into the process's status with exitStatus().

namespace rube::game {

/// What a command's run came to. The numbers are the documented exit statuses (README, --help).
enum class ExitCode : int {
    ok = 0,     ///< done: the run finished, the goal was reached and every expectation met, every file checked is good
    failed = 1, ///< the input was good but the run failed: goal missed, an expectation failed, a state went
                ///< non-finite, interrupted, an output could not be written, no GL context or window
    badInput = 2, ///< bad input or usage: a scene, script or option refused with one line, nothing written
};

/// The process exit status for `code` (what main() returns).
constexpr int exitStatus(ExitCode code) { return static_cast<int>(code); }

} // namespace rube::game
