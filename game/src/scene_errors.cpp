// Scene errors: formatting, sorting, and the typo suggestions of "did you mean ...?".
#include "scene_errors.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>

namespace rube::game {

std::string SceneError::format() const {
    if (place.line <= 0) return file + ": " + message;
    return file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column) + ": " + message;
}

void Diagnostics::error(SourcePlace place, std::string message) {
    // Messages must stay one line: a newline would split one error into two for every tool reading them.
    std::replace(message.begin(), message.end(), '\n', ' ');
    errors_.push_back({file_, place, std::move(message)});
}

std::vector<SceneError> Diagnostics::sorted() const {
    std::vector<SceneError> result = errors_;
    std::stable_sort(result.begin(), result.end(), [](const SceneError& a, const SceneError& b) {
        if (a.place.line != b.place.line) return a.place.line < b.place.line;
        return a.place.column < b.place.column;
    });
    return result;
}

namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbours each cost one, so the common typo "raduis" is one edit from "radius".
std::size_t editDistance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::size_t> d((n + 1) * (m + 1));
    auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
    for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
    for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
                at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
        }
    }
    return at(n, m);
}

} // namespace

std::optional<std::string_view> closestMatch(std::string_view word, std::span<const std::string_view> candidates) {
    // About one edit per three letters: "mas" finds "mass", but "x" does not find "a" (only
    // a difference of case is forgiven in words that short).
    const std::size_t allowed = word.size() < 3 ? 0 : std::max<std::size_t>(1, word.size() / 3);
    std::optional<std::string_view> best;
    std::size_t bestDistance = allowed + 1;
    for (std::string_view candidate : candidates) {
        const std::size_t distance = editDistance(word, candidate);
        if (distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

std::string unknownNameHint(std::string_view word, std::span<const std::string_view> candidates, std::string_view label,
                            std::string_view none) {
    if (const auto match = closestMatch(word, candidates)) return " (did you mean '" + std::string(*match) + "'?)";
    if (candidates.empty()) return " (" + std::string(none) + ")";
    return " (" + std::string(label) + ": " + joinNames(candidates) + ")";
}

std::string joinNames(std::span<const std::string_view> names) {
    std::string result;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) result += ", ";
        result += names[i];
    }
    return result;
}

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string formatPair(double x, double y) {
    std::string result = "[";
    result.append(formatNumber(x)).append(", ").append(formatNumber(y)).append("]");
    return result;
}

} // namespace rube::game
