#pragma once
/// Progress: which levels the player has solved, kept between sessions in a small text file
/// under the user's data folder ($XDG_DATA_HOME/rube/solved.txt, else ~/.local/share/rube/).

#include <filesystem>
#include <set>
#include <string>
#include <string_view>

namespace rube::game {

class Progress {
public:
    /// The file the play window keeps progress in: $XDG_DATA_HOME/rube/solved.txt when
    /// XDG_DATA_HOME is set and absolute (as the XDG spec asks), else ~/.local/share/rube/solved.txt;
    /// empty when neither can be found (progress is then not kept).
    static std::filesystem::path defaultFile();

    /// Progress read from `file`; a missing file is no level solved yet.
    explicit Progress(std::filesystem::path file);

    /// True when `level` (a level's file name without .toml, "ramp") has been solved.
    bool solved(std::string_view level) const { return solved_.count(std::string(level)) != 0; }
    /// Records `level` as solved and writes the file (its folder created if missing). False, with
    /// the reason, when it could not be written; the level still counts as solved in this session.
    bool markSolved(std::string_view level, std::string& reason);
    /// The file progress is kept in.
    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    std::set<std::string> solved_;
};

/// The name a level is known by in the progress file: its file name without `.toml`.
std::string levelKey(const std::filesystem::path& levelFile);

} // namespace rube::game
