// What the subcommands' options share: the one-line usage error and the validators.
#include "command_line.hpp"

#include "run_command.hpp" // kMaxFrameSide

#include "rube/render/render_context.hpp"
#include "rube/render/video_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <iostream>

namespace rube::game::cli {

// Usage errors are one line on stderr, pointing at the help that explains the option.
ExitCode usageError(const std::string& message, const std::string& help) {
    std::cerr << "rube: " << message << " (see '" << help << "')\n";
    return ExitCode::badInput;
}

// CLI11 messages are one line already; this keeps them so if a future version adds a line break.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

// CLI11's own range check prints the largest double in full; this says what a step count is.
std::string stepCount(const std::string& text) {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value < 0)
        return "expected a whole number of steps, 0 or more, got '" + text + "'";
    // A run longer than this is a typo, not a plan: it would not end this year.
    if (value > 1'000'000'000) return "expected at most 1000000000 steps, got '" + text + "'";
    return {};
}

// A whole number from 1 to a billion, for --every and --frames; `what` names the unit.
CLI::Validator countFromOne(std::string what) {
    return CLI::Validator(
        [what](const std::string& text) -> std::string {
            std::int64_t value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc{} || end != text.data() + text.size() || value < 1 || value > 1'000'000'000)
                return "expected a whole number of " + what + " from 1 to 1000000000, got '" + text + "'";
            return {};
        },
        "");
}

// "WxH" with both sides from 1 to kMaxFrameSide; nothing when `text` is not that.
std::optional<render::FrameSize> parseFrameSize(const std::string& text) {
    const auto side = [](const char* begin, const char* end) -> std::optional<int> {
        int value = 0;
        const auto [stop, error] = std::from_chars(begin, end, value);
        if (error != std::errc{} || stop != end || value < 1 || value > kMaxFrameSide) return std::nullopt;
        return value;
    };
    const auto x = text.find('x');
    if (x == std::string::npos) return std::nullopt;
    const auto width = side(text.data(), text.data() + x);
    const auto height = side(text.data() + x + 1, text.data() + text.size());
    if (!width || !height) return std::nullopt;
    return render::FrameSize{*width, *height};
}

std::string frameSizeError(const std::string& text) {
    if (parseFrameSize(text)) return {};
    return "expected WxH in pixels, each from 1 to " + std::to_string(kMaxFrameSide) + ", got '" + text + "'";
}

std::string videoFileError(const std::string& text) {
    if (render::videoFormatOf(text)) return {};
    return "expected a file ending in .mp4, .webm or .gif, got '" + text + "'";
}

std::string glBackendError(const std::string& text) {
    if (render::glBackendFromName(text)) return {};
    return "expected auto, egl or osmesa, got '" + text + "'";
}

} // namespace rube::game::cli
