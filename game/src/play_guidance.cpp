// The play session's guidance: what the bar says when the goal is reached or the time is up, the
// level's hints (H) and its intended solution (W), shown once the level is solved.
#include "play_session.hpp"

#include "play_internal.hpp"

namespace rube::game {

void PlaySession::goalMessages(bool reachedBefore) {
    if (!reachedBefore && run_->goalStep()) {
        solved_ = true;
        say("GOAL REACHED at step " + std::to_string(*run_->goalStep()) +
                " - N next level, W the intended solution, R edits again",
            "goal");
    } else if (!timeUpSaid_ && run_->timeUp()) {
        // The fail state: the goal can no longer count. The machine runs on, so the player sees why.
        timeUpSaid_ = true;
        say("TIME UP: no goal within " + play::number(*level_.level.goal->timeLimit) + " s - R to retry", "magnet");
    }
}

void PlaySession::showHint() {
    const std::vector<Hint>& hints = level_.level.hints;
    if (hints.empty()) {
        say("this level has no hints");
        return;
    }
    const std::size_t i = nextHint_++ % hints.size();
    say("hint " + std::to_string(i + 1) + "/" + std::to_string(hints.size()) + ": " + hints[i].text);
}

void PlaySession::watchSolution() {
    if (!solved_) {
        say("solve the level first: then W shows the intended solution", "magnet");
        return;
    }
    if (!solution_) {
        say("this level has no solution script beside it", "magnet");
        return;
    }
    if (run_) reset();
    cancelDrag();
    recordEdit(); // the player's own edits come back with Ctrl+Z
    load(*solution_);
    start();
    say("the intended solution - R, then Ctrl+Z, brings your own edits back");
}

} // namespace rube::game
