// The pipe: a fixed curved guide, an arc of `segments` straight boards whose inner surface lies on a
// circle of radius `bend` about the item's position, `sweep` degrees long (180: a half pipe, 90: a quarter
// pipe). At angle 0 it is a U opening upwards (the arc centred on the circle's bottom); the angle
// turns it. Its boards have bounciness 1 by default, so an elastic ball (C = 1) keeps its speed through
// it: each board it grazes reflects its normal part whole (lecture 3) and the rest of its path is free
// flight; a ball of C < 1 loses (1 - C^2) of its normal speed's energy at each board it meets.
#include "part_common.hpp"

#include <numbers>
#include <vector>

namespace rube::game::parts {
namespace {

constexpr double kWallRadius = 0.04; // m, half a board's thickness

struct PipeParams {
    double radius = 1.0;     // m, to the inner surface
    double sweep = 180.0;    // degrees of arc
    int segments = 12;       // boards along the arc
    double bounciness = 1.0; // C of its boards
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the centre of its arc"},
                             {"angle", "0", "turn, degrees (0: a U opening upwards)"},
                             {"bend", "1", "m, the radius of its arc: from the centre to its inner surface"},
                             {"sweep", "180", "degrees of arc: 180 a half pipe, 90 a quarter pipe"},
                             {"segments", "12", "straight boards along the arc"},
                             {"bounciness", "1", "C of its boards"}};

// The boards' end points: on the circle of radius + wall radius, so their inner faces touch `radius`.
std::vector<Vec2> arcPoints(const ItemDesc& item, double radius) {
    const PipeParams& p = item.params.as<PipeParams>();
    const double sweep = radians(p.sweep);
    const double first = item.angle - 0.5 * std::numbers::pi - 0.5 * sweep; // the arc centred on the bottom
    std::vector<Vec2> points;
    for (int i = 0; i <= p.segments; ++i)
        points.push_back(item.position + Vec2::fromAngle(first + sweep * i / p.segments) * radius);
    return points;
}

class PipeKind final : public PartKind {
public:
    std::string_view name() const override { return "pipe"; }
    int order() const override { return 24; }
    std::string_view summary() const override {
        return "a fixed half pipe of 12 boards, bounciness 1, on a circle of 1 m: a curved guide";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    ItemDesc make(Vec2 position) const override { return made(position, PipeParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        PipeParams& p = item.params.as<PipeParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto r = table.number("bend", kSizeRange)) p.radius = *r;
        if (const auto s = table.number("sweep", NumberRange{0.0, 360.0, true})) p.sweep = *s;
        if (const auto n = table.integer("segments", 1, 360)) p.segments = static_cast<int>(*n);
        if (const auto c = table.number("bounciness", NumberRange::unit())) p.bounciness = *c;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const PipeParams& p = item.params.as<PipeParams>();
        const std::vector<Vec2> points = arcPoints(item, p.radius + kWallRadius);
        ItemBodies bodies;
        for (std::size_t i = 0; i + 1 < points.size(); ++i)
            bodies.segments.push_back({points[i], points[i + 1], kWallRadius, bouncy(p.bounciness), -1});
        return bodies;
    }
    // The boards are the world's; an outer skin drawn a wall's width outside them reads as a pipe's wall.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const std::vector<Vec2> outer = arcPoints(item, item.params.as<PipeParams>().radius + 4.0 * kWallRadius);
        std::vector<render::Point> line;
        for (const Vec2 v : outer) line.push_back(pt(v));
        d.list.polyline(line, 1.5f, render::Palette::greybox()["ground_outline"]);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        std::vector<render::Point> arc;
        for (int i = 0; i <= 12; ++i)
            arc.push_back(pt(centre + Vec2::fromAngle(std::numbers::pi + std::numbers::pi * i / 12) * (0.4 * size)));
        list.polyline(arc, 3.0f, render::Palette::greybox()["ground_outline"]);
    }
};

} // namespace
RUBE_PART(pipe, PipeKind)
} // namespace rube::game::parts
