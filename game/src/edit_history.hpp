#pragma once
/// EditHistory: undo and redo for the play window and the editor. It keeps whole snapshots of
/// what an edit may change (a few placements, a level's items), not commands: a snapshot cannot
/// drift from the state it restores, and at these sizes a hundred of them cost next to nothing.

#include <cstddef>
#include <deque>
#include <utility>

namespace rube::game {

template <class State>
class EditHistory {
public:
    /// How many edits can be undone; older ones are forgotten first.
    static constexpr std::size_t kDepth = 100;

    /// Call before an edit with the state as it was: the edit can then be undone. A new edit
    /// forgets what was undone (there is no redo after it).
    void record(State before) {
        undo_.push_back(std::move(before));
        if (undo_.size() > kDepth) undo_.pop_front();
        redo_.clear();
    }
    /// Takes back the last edit: `now` becomes the state before it. False when there is none.
    bool undo(State& now) { return move(undo_, redo_, now); }
    /// Does again the last edit undone. False when there is none.
    bool redo(State& now) { return move(redo_, undo_, now); }

    std::size_t undoable() const { return undo_.size(); }
    std::size_t redoable() const { return redo_.size(); }
    void clear() {
        undo_.clear();
        redo_.clear();
    }

private:
    static bool move(std::deque<State>& from, std::deque<State>& to, State& now) {
        if (from.empty()) return false;
        to.push_back(std::move(now));
        now = std::move(from.back());
        from.pop_back();
        return true;
    }

    std::deque<State> undo_;
    std::deque<State> redo_;
};

} // namespace rube::game
