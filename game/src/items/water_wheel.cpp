// The water wheel: a paddle wheel on a fixed axle, free to turn, that balls falling on its paddles
// turn as water turns a mill's. Each ball's impulse J on a paddle at r from the axle gives the wheel
// the angular impulse r x J (the axle's push goes through the axle and turns nothing), so the wheel
// turns the way the balls push: down on the side they fall. Dull paddles (bounciness 0.1) keep most
// of each ball's momentum. A belt or a gear may name it.
#include "wheel_common.hpp"

namespace rube::game::parts {
namespace {

constexpr double kBounciness = 0.1;

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the axle"},
                             kWheelAngleKey,
                             {"radius", "0.3", "the disc's, m"},
                             {"mass", "1", "the disc's mass, kg"},
                             {"paddles", "6", "paddles round the rim (0 to 8), welded to the disc"},
                             kWheelPaddleKey};

class WaterWheelKind final : public PartKind {
public:
    std::string_view name() const override { return "water-wheel"; }
    int order() const override { return 82; }
    std::string_view summary() const override {
        return "a paddle wheel on a fixed axle, bounciness 0.1, turned by balls falling on its paddles";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; } // the paddles' direction
    bool plays(PartRole role) const override { return role == PartRole::wheel; }
    ItemDesc make(Vec2 position) const override { return made(position, WheelParams{0.3, 1.0, 6, kPaddleLength}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        readWheel(table, item, item.params.as<WheelParams>());
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        return wheelBodies(item, item.params.as<WheelParams>(), {}, kBounciness);
    }
    void draw(const PartDrawing& d) const override { drawWheel(d, style("box", "box_outline"), "water"); }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        drawWheelIcon(centre, size, available, "water", list);
    }
};

} // namespace
RUBE_PART(water_wheel, WaterWheelKind)
} // namespace rube::game::parts
