// The wheel: a disc on a fixed axle, free to turn, with paddles welded to it if asked for. Nothing
// drives it of itself: a belt or gears from a motor turn it, or balls falling on its paddles.
#include "wheel_common.hpp"

namespace rube::game::parts {
namespace {

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the axle"},
                             kWheelAngleKey,
                             {"radius", "0.4", "the disc's, m"},
                             kWheelMassKey,
                             kWheelPaddlesKey,
                             kWheelPaddleKey};

class WheelKind final : public PartKind {
public:
    std::string_view name() const override { return "wheel"; }
    int order() const override { return 61; }
    std::string_view summary() const override {
        return "a disc (with paddles if asked) on a fixed axle, turned by a belt, gears or what hits it";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; } // the paddles' direction
    bool plays(PartRole role) const override { return role == PartRole::wheel; }
    ItemDesc make(Vec2 position) const override { return made(position, WheelParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        readWheel(table, item, item.params.as<WheelParams>());
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        return wheelBodies(item, item.params.as<WheelParams>(), {}, 0.3);
    }
    void draw(const PartDrawing& d) const override { drawWheel(d, style("box", "box_outline"), "ground"); }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        drawWheelIcon(centre, size, available, "ground", list);
    }
};

} // namespace
RUBE_PART(wheel, WheelKind)
} // namespace rube::game::parts
