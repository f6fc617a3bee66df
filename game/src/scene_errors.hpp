#pragma once
/// Scene errors: what went wrong and where, collected so `rube check` can list every one.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rube::game {

/// A place in a scene file, 1-based as in every editor's status bar; line 0 means the whole file.
struct SourcePlace {
    int line = 0;   ///< 1-based; 0 when the error is about the whole file
    int column = 0; ///< 1-based, in characters
};

/// One problem in a scene file.
struct SceneError {
    std::string file;    ///< as the user named it, so the line leads back to it
    SourcePlace place;   ///< where it was written
    std::string message; ///< one line, no trailing period: "radius must be greater than 0, got 0"
    /// The one-line form editors and CI logs jump to: `file:line:col: message` (`file: message` without a place).
    std::string format() const;
};

/// Collects the errors of one file and hands them back sorted top to bottom, since
/// TOML tables are visited in key order rather than in the order they were written.
class Diagnostics {
public:
    /// `file` is the name every error is reported under.
    explicit Diagnostics(std::string file) : file_(std::move(file)) {}
    /// Records an error at `place`.
    void error(SourcePlace place, std::string message);
    /// True while nothing has gone wrong.
    bool empty() const { return errors_.empty(); }
    /// The errors so far, sorted by line and column (stable, so one place keeps its order).
    std::vector<SceneError> sorted() const;
    /// The file name the errors are reported under.
    const std::string& file() const { return file_; }

private:
    std::string file_;
    std::vector<SceneError> errors_;
};

/// The candidate closest to `word` when it is close enough to be a typo of it (a few edits,
/// transpositions counting as one), so a message can ask "did you mean 'radius'?".
std::optional<std::string_view> closestMatch(std::string_view word, std::span<const std::string_view> candidates);

/// The end of an "unknown name" message, so every file words it alike: " (did you mean 'x'?)" for a
/// likely typo, else " (<label>: a, b)" listing the candidates, or " (<none>)" when there are none.
std::string unknownNameHint(std::string_view word, std::span<const std::string_view> candidates, std::string_view label,
                            std::string_view none);

/// "a, b, c": candidates listed for a message.
std::string joinNames(std::span<const std::string_view> names);

/// A number as short as it can be printed and still read back exactly ("0.1", "1e+300", "nan").
std::string formatNumber(double value);

/// A pair as a scene file writes it: "[0.5, -1]".
std::string formatPair(double x, double y);

/// The largest scene, level or script file read: 4 MiB.
inline constexpr std::uintmax_t kMaxTextFileBytes = 4u << 20;

/// The whole text of a file, or nothing with `error` set to "cannot open file" (also for a
/// folder), "not a regular file" (a FIFO, a device: refused before any read, so none can block
/// or run on for ever), "file too large: ..." (over kMaxTextFileBytes, however the bytes come) or
/// "cannot read file", so every loader words an unreadable file the same way (text_file_io.cpp).
std::optional<std::string> readTextFile(const std::filesystem::path& file, SceneError& error);

/// Writes `text` to `file` under a temporary name and renames it, so a reader (or an interrupted
/// run) never sees half a file; false when it could not be written, with `reason` set (the
/// system's words, e.g. "No space left on device") and no temporary left behind.
bool writeTextFileAtomically(const std::filesystem::path& file, const std::string& text, std::string& reason);

} // namespace rube::game
