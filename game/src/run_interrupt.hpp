#pragma once
/// Ctrl-C (SIGINT) and a polite kill (SIGTERM) stop a run the same way: the step loop ends at the
/// next step, temporaries are removed, the summary says the run was interrupted, and the exit
/// status is ExitCode::failed (1). Scene runs and level runs both use it.

#include <string>

namespace rube::game {

/// Catches SIGINT and SIGTERM for its lifetime and puts the previous handlers back afterwards.
class InterruptGuard {
public:
    /// Installs the handlers and forgets any earlier interruption.
    InterruptGuard();
    /// Restores the handlers that were there before.
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    void (*previousInt_)(int);
    void (*previousTerm_)(int);
};

/// Whether SIGINT or SIGTERM arrived since the guard was installed.
bool interrupted();

/// "SIGINT" or "SIGTERM": the signal that interrupted the run; empty when none did.
std::string interruptingSignal();

} // namespace rube::game
