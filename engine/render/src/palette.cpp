// Palette: named colours parsed from a small TOML subset, and the embedded greybox palette.
#include "rube/render/palette.hpp"

#include "palette_toml.hpp" // generated from assets/palette.toml

#include <stdexcept>
#include <string>

namespace rube::render {
namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string_view trim(std::string_view s) {
    auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

bool isNameChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

} // namespace

Color parseColor(std::string_view hex) {
    if ((hex.size() != 7 && hex.size() != 9) || hex[0] != '#') {
        throw std::invalid_argument("colour \"" + std::string(hex) + "\" is not #rrggbb or #rrggbbaa");
    }
    std::uint8_t channel[4] = {0, 0, 0, 255};
    for (std::size_t i = 0; 1 + 2 * i < hex.size(); ++i) {
        int high = hexDigit(hex[1 + 2 * i]);
        int low = hexDigit(hex[2 + 2 * i]);
        if (high < 0 || low < 0) {
            throw std::invalid_argument("colour \"" + std::string(hex) + "\" has a character that is not hexadecimal");
        }
        channel[i] = static_cast<std::uint8_t>(high * 16 + low);
    }
    return {channel[0], channel[1], channel[2], channel[3]};
}

Palette Palette::parse(std::string_view text) {
    Palette palette;
    int lineNumber = 0;
    while (!text.empty()) {
        auto end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        ++lineNumber;
        auto fail = [&](const std::string& why) {
            throw std::invalid_argument("palette line " + std::to_string(lineNumber) + ": " + why + ": " +
                                        std::string(line));
        };
        // A '#' outside quotes starts a comment; inside quotes it starts the colour.
        auto quote = line.find('"');
        auto comment = line.find('#');
        if (comment != std::string_view::npos && (quote == std::string_view::npos || comment < quote)) {
            line = line.substr(0, comment);
        }
        line = trim(line);
        if (line.empty()) continue;
        auto equals = line.find('=');
        if (equals == std::string_view::npos) fail("expected name = \"#hex\"");
        std::string_view name = trim(line.substr(0, equals));
        if (name.empty()) fail("missing name");
        for (char c : name) {
            if (!isNameChar(c)) fail("bad character in name");
        }
        std::string_view value = trim(line.substr(equals + 1));
        auto closing = value.find('"', 1);
        if (value.size() < 2 || value[0] != '"' || closing == std::string_view::npos)
            fail("value must be a quoted colour");
        if (!trim(value.substr(closing + 1)).empty() && trim(value.substr(closing + 1))[0] != '#')
            fail("unexpected text after the colour");
        try {
            Color colour = parseColor(value.substr(1, closing - 1));
            if (!palette.colours_.emplace(std::string(name), colour).second) fail("name defined twice");
        } catch (const std::invalid_argument& e) {
            if (std::string_view(e.what()).starts_with("palette line")) throw;
            fail(e.what());
        }
    }
    return palette;
}

const Palette& Palette::greybox() {
    static const Palette palette = parse(assets::paletteToml);
    return palette;
}

Color Palette::operator[](std::string_view name) const {
    auto it = colours_.find(name);
    if (it == colours_.end()) {
        throw std::out_of_range("the palette has no colour \"" + std::string(name) + "\"");
    }
    return it->second;
}

bool Palette::contains(std::string_view name) const { return colours_.find(name) != colours_.end(); }

std::vector<std::string> Palette::names() const {
    std::vector<std::string> result;
    result.reserve(colours_.size());
    for (const auto& entry : colours_) result.push_back(entry.first);
    return result;
}

} // namespace rube::render
