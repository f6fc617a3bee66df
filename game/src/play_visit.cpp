// The visit: which screen the window shows, and the changes between them. Sessions end here, so
// the progress file is written and the summary reported in one place whichever way a level ends.
#include "play_visit.hpp"

#include "scene_file.hpp"

namespace rube::game {

namespace {

// NAME.solution.toml beside NAME.toml: the intended solution W shows once the level is solved.
std::optional<ScriptDesc> solutionOf(const std::filesystem::path& level, const SceneDesc& scene) {
    std::filesystem::path file = level;
    file.replace_extension(".solution.toml");
    if (!std::filesystem::is_regular_file(file)) return std::nullopt;
    ScriptLoad load = loadScriptFile(file, scene);
    return std::move(load.script);
}

// Where `level` stands in the index, if it is listed there.
std::optional<std::size_t> indexOf(const std::vector<IndexedLevel>& index, const std::filesystem::path& level) {
    std::error_code error;
    for (std::size_t i = 0; i < index.size(); ++i)
        if (std::filesystem::equivalent(index[i].file, level, error)) return i;
    return std::nullopt;
}

} // namespace

PlayVisit::PlayVisit(std::vector<IndexedLevel> index, std::optional<VisitLevel> first, VisitOptions options,
                     SessionEnded ended, std::function<void(const std::string&)> failedLevel)
    : index_(std::move(index)), options_(std::move(options)), ended_(std::move(ended)),
      failedLevel_(std::move(failedLevel)), progress_(options_.progressFile) {
    if (first) {
        const std::optional<std::size_t> at = indexOf(index_, first->file);
        open(std::move(*first), at);
    } else {
        fromList_ = true;
        showList(0);
    }
}

render::FrameSize PlayVisit::windowSize() const {
    return {options_.levelFrame.width, options_.levelFrame.height + InventoryBar::kHeight};
}

render::InputListener* PlayVisit::screen() {
    if (session_) return session_.get();
    return list_.get();
}

void PlayVisit::cursorMoved(float x, float y) {
    if (auto* s = screen()) s->cursorMoved(x, y);
}
void PlayVisit::mouseButton(render::MouseButton button, bool pressed) {
    if (auto* s = screen()) s->mouseButton(button, pressed);
}
void PlayVisit::scrolled(float notches) {
    if (auto* s = screen()) s->scrolled(notches);
}
void PlayVisit::key(render::Key key, render::KeyAction action) {
    if (auto* s = screen()) s->key(key, action);
}

void PlayVisit::showList(std::size_t selected) {
    session_.reset();
    list_ = std::make_unique<LevelSelect>(index_, progress_, windowSize(), selected);
}

void PlayVisit::open(VisitLevel level, std::optional<std::size_t> at) {
    list_.reset();
    at_ = at;
    level_ = std::move(level.scene);
    levelFile_ = std::move(level.file);
    session_ = std::make_unique<PlaySession>(level_, levelFile_.string(), options_.levelFrame);
    if (level.script) session_->load(*level.script);
    if (auto solution = solutionOf(levelFile_, level_)) session_->setSolution(std::move(*solution));
    if (progress_.solved(levelKey(levelFile_))) session_->markSolved();
    if (options_.quitAfter) session_->stopAtStep(*options_.quitAfter);
    if (options_.runAtOnce) session_->start();
}

void PlayVisit::openIndexed(std::size_t at) {
    const SceneLoad load = loadSceneFile(index_[at].file);
    if (!load.ok()) {
        failedLevel_(load.errors.front().format());
        finished_ = true;
        return;
    }
    open(VisitLevel{*load.scene, index_[at].file, std::nullopt}, at);
}

void PlayVisit::endSession() {
    const LevelRun* run = session_->run();
    if (run && run->goalStep()) {
        std::string reason;
        if (!progress_.markSolved(levelKey(levelFile_), reason) && failedLevel_)
            failedLevel_("rube play: progress not kept in " + progress_.file().string() + ": " + reason);
    }
    // A run that ends without its goal fails, as in 'rube run'.
    lastRunFailed_ = run && level_.level.goal && !run->goalStep();
    recording_ = session_->recordedScript();
    ended_(*session_, level_);
}

void PlayVisit::close() {
    if (session_) endSession();
    session_.reset();
    finished_ = true;
}

void PlayVisit::tick(double seconds) {
    if (finished_) return;
    if (list_) {
        if (list_->quitRequested()) finished_ = true;
        else if (const auto chosen = list_->chosen()) openIndexed(*chosen);
        return;
    }
    PlaySession& s = *session_;
    // --quit-after counts steps, so a slow machine ends where a fast one does.
    if (options_.quitAfter && s.run() && s.run()->steps() >= *options_.quitAfter) {
        quitAfterReached_ = true;
        close();
        return;
    }
    if (s.nextRequested()) {
        endSession();
        if (at_ && *at_ + 1 < index_.size()) return openIndexed(*at_ + 1);
        if (index_.empty()) return close(); // no list to go back to
        fromList_ = true;                   // after the last level, back to the list
        return showList(at_.value_or(0));
    }
    if (s.quitRequested()) {
        endSession();
        if (!fromList_ || index_.empty()) {
            session_.reset();
            finished_ = true;
            return;
        }
        return showList(at_.value_or(0));
    }
    if (options_.stepsPerFrame > 0) {
        if (s.mode() == PlaySession::Mode::running && !s.paused())
            for (int i = 0; i < options_.stepsPerFrame; ++i) s.step();
    } else {
        s.advance(seconds);
    }
}

void PlayVisit::draw(render::DrawList& list) const {
    if (session_) session_->draw(list);
    else if (list_) list_->draw(list);
}

render::Camera PlayVisit::camera() const {
    if (session_) return session_->windowCamera();
    if (list_) return list_->pixelCamera();
    return {};
}

} // namespace rube::game
