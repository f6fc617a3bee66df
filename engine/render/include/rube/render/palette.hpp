#pragma once
/// Colours and the palette that names them by role (assets/palette.toml).

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace rube::render {

/// An 8-bit RGBA colour with straight (not premultiplied) alpha.
struct Color {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    std::uint8_t a = 255;

    /// The same colour with another alpha, for fading trails and rings.
    constexpr Color withAlpha(std::uint8_t alpha) const { return {r, g, b, alpha}; }
    /// Fully transparent: a shape drawn with it leaves the frame untouched.
    static constexpr Color transparent() { return {0, 0, 0, 0}; }
    /// Exact equality, channel by channel.
    friend constexpr bool operator==(Color, Color) = default;
};

/// The colour written as "#rrggbb" or "#rrggbbaa"; throws std::invalid_argument otherwise.
Color parseColor(std::string_view hex);

/// Named colours. The renderer itself takes plain colours; the palette keeps the choice of
/// colours in a data file so that the game asks for "ball", never for a number.
class Palette {
public:
    /// Parses lines of `name = "#hex"` with `#` comments (a subset of TOML); throws
    /// std::invalid_argument naming the line on anything else.
    static Palette parse(std::string_view text);
    /// The greybox palette from assets/palette.toml, embedded in the binary at build time.
    static const Palette& greybox();

    /// The colour called `name`; throws std::out_of_range naming it when there is none,
    /// so a typo fails loudly instead of drawing black.
    Color operator[](std::string_view name) const;
    /// Whether the palette has a colour called `name`.
    bool contains(std::string_view name) const;
    /// Every name, sorted.
    std::vector<std::string> names() const;

private:
    std::map<std::string, Color, std::less<>> colours_;
};

} // namespace rube::render
