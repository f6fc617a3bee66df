// SIGINT and SIGTERM during a run: the handler only records the signal (all it may safely do);
// the step loops poll interrupted() between steps.
#include "run_interrupt.hpp"

#include <csignal>

namespace rube::game {

namespace {

volatile std::sig_atomic_t gSignal = 0;
extern "C" void onInterrupt(int signal) { gSignal = signal; }

} // namespace

InterruptGuard::InterruptGuard()
    : previousInt_(std::signal(SIGINT, onInterrupt)), previousTerm_(std::signal(SIGTERM, onInterrupt)) {
    gSignal = 0;
}

InterruptGuard::~InterruptGuard() {
    std::signal(SIGINT, previousInt_);
    std::signal(SIGTERM, previousTerm_);
}

bool interrupted() { return gSignal != 0; }

std::string interruptingSignal() {
    if (gSignal == SIGINT) return "SIGINT";
    if (gSignal == SIGTERM) return "SIGTERM";
    return "";
}

} // namespace rube::game
