// Progress: one solved level per line, by its file name, under a one-line comment. Written
// atomically, so a crash mid-write never loses what was solved before.
#include "progress.hpp"

#include "scene_errors.hpp"

#include <cstdlib>
#include <fstream>
#include <system_error>

namespace rube::game {

std::filesystem::path Progress::defaultFile() {
    // XDG Base Directory: a relative XDG_DATA_HOME is invalid and must be ignored.
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg && std::filesystem::path(xdg).is_absolute())
        return std::filesystem::path(xdg) / "rube" / "solved.txt";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".local" / "share" / "rube" / "solved.txt";
    return {};
}

Progress::Progress(std::filesystem::path file) : file_(std::move(file)) {
    if (file_.empty()) return;
    std::ifstream in(file_);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line.front() != '#') solved_.insert(line);
}

bool Progress::markSolved(std::string_view level, std::string& reason) {
    if (!solved_.insert(std::string(level)).second) return true;
    if (file_.empty()) {
        reason = "no data folder (neither XDG_DATA_HOME nor HOME is set)";
        return false;
    }
    std::error_code error;
    std::filesystem::create_directories(file_.parent_path(), error);
    if (error) {
        reason = "cannot create " + file_.parent_path().string() + ": " + error.message();
        return false;
    }
    std::string text = "# rube: the levels solved in 'rube play', one a line\n";
    for (const std::string& name : solved_) text += name + "\n";
    return writeTextFileAtomically(file_, text, reason);
}

std::string levelKey(const std::filesystem::path& levelFile) { return levelFile.stem().string(); }

} // namespace rube::game
