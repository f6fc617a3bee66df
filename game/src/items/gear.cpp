// The gear: a toothed wheel on a fixed axle. Its pitch radius is teeth x pitch / 2 pi, so teeth
// and rims are in proportion; meshed with the wheel it names (a gear, a motor or a plain wheel, which
// is then drawn toothed too) it turns the opposite way at n_other / n_own of its speed:
// theta_own = -(n_other / n_own) theta_other, a gear joint between the two axles (joint.hpp).
#include "wheel_common.hpp"

#include <cmath>

namespace rube::game::parts {
namespace {

// As joint_drawing.cpp draws gears' teeth: a tooth per 0.2 m of rim, standing 0.08 m out of it; so a
// gear of n teeth, of pitch radius n x 0.2 / 2 pi, is drawn with its n teeth.
constexpr double kToothPitch = 0.2;
constexpr double kToothDepth = 0.08;
// Meshed axles stand r1 + r2 + a tooth's depth apart (the teeth in each other's gaps), within this, m.
constexpr double kMeshTolerance = 0.05;

struct GearParams {
    int teeth = 12;
    double mass = 1.0; // kg
    int paddles = 0;
    double paddleLength = kPaddleLength;
    std::string meshes; // the wheel it meshes with, or none
    SourcePlace meshesAt;
    bool meshed = false; // `meshes` was written
};

// A length for a message, to the centimetre.
std::string centimetres(double metres) { return formatNumber(std::round(metres * 100.0) / 100.0); }

double pitchRadius(int teeth) { return teeth * kToothPitch / (2.0 * std::numbers::pi); }

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: the axle"},
    kWheelAngleKey,
    {"teeth", "12", "6 to 72; the pitch radius is teeth x 0.2 m / 2 pi"},
    {"mass", "1", "kg"},
    kWheelPaddlesKey,
    kWheelPaddleKey,
    {"meshes", "none", "the name of the gear, motor or wheel it meshes with (axles r1 + r2 + 0.08 m apart)"}};

class GearKind final : public PartKind {
public:
    std::string_view name() const override { return "gear"; }
    int order() const override { return 63; }
    std::string_view summary() const override {
        return "a toothed wheel on a fixed axle; meshed with another it turns the other way at the teeth's ratio";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool plays(PartRole role) const override { return role == PartRole::wheel; }
    ItemDesc make(Vec2 position) const override { return made(position, GearParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        GearParams& p = item.params.as<GearParams>();
        if (const auto n = table.integer("teeth", 6, 72)) p.teeth = static_cast<int>(*n);
        if (const auto m = table.number("mass", NumberRange{0.0, 1e4, true})) p.mass = *m;
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto n = table.integer("paddles", 0, 8)) p.paddles = static_cast<int>(*n);
        if (const auto l = table.number("paddle", kSizeRange)) p.paddleLength = *l;
        if (const auto name = table.string("meshes")) p.meshes = *name;
        p.meshesAt = table.valuePlace("meshes");
        p.meshed = table.find("meshes") != nullptr;
    }
    // The wheel it meshes with must be one, and stand where its teeth meet this gear's.
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        const GearParams& p = item.params.as<GearParams>();
        if (!p.meshed) return;
        const LevelDesc& level = reading.scene.level;
        if (std::string message = itemReferenceError(level, "meshes", p.meshes, PartRole::wheel); !message.empty())
            return reading.diag.error(p.meshesAt, std::move(message));
        const ItemDesc& other = level.items[static_cast<std::size_t>(level.find(p.meshes))];
        if (&other == &item) return reading.diag.error(p.meshesAt, "a gear cannot mesh with itself");
        const ItemBodies bodies = itemBodies(other);
        if (bodies.circles.empty()) return;
        const double apart = pitchRadius(p.teeth) + bodies.circles.front().radius + kToothDepth;
        const double distance = item.position.distance(other.position);
        if (std::abs(distance - apart) > kMeshTolerance)
            reading.diag.error(p.meshesAt, "gear meshes with '" + p.meshes + "' " + centimetres(distance) +
                                               " m away: meshed axles stand r1 + r2 + " + formatNumber(kToothDepth) +
                                               " = " + centimetres(apart) + " m apart");
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const GearParams& p = item.params.as<GearParams>();
        ItemBodies bodies = wheelBodies(item, WheelParams{pitchRadius(p.teeth), p.mass, p.paddles, p.paddleLength}, {},
                                        0.3);
        if (!p.meshes.empty()) {
            ItemJoint mesh;
            mesh.def.kind = JointKind::gear;
            mesh.ratio = ItemJoint::Ratio::mesh; // n_other / n_own, from the rims
            mesh.gearA = 0;                      // its own axle
            mesh.gearItemB = p.meshes;
            bodies.joints.push_back(mesh);
        }
        return bodies;
    }
    // The teeth are drawn with the joints (joint_drawing.cpp), turning with the wheel; here its face.
    void draw(const PartDrawing& d) const override { drawWheel(d, style("box", "box_outline"), "ground"); }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style look = style("box", "box_outline");
        if (!available) look.fill = look.fill.withAlpha(0x60);
        const double r = 0.3 * size;
        const int teeth = 10;
        for (int k = 0; k < teeth; ++k) {
            const double a = 2.0 * std::numbers::pi * k / teeth;
            const Vec2 along = Vec2::fromAngle(a), across = along.perpendicular();
            const render::Point tooth[4] = {pt(centre + along * (0.9 * r) - across * (0.12 * r)),
                                            pt(centre + along * (1.25 * r) - across * (0.07 * r)),
                                            pt(centre + along * (1.25 * r) + across * (0.07 * r)),
                                            pt(centre + along * (0.9 * r) + across * (0.12 * r))};
            list.polygon(tooth, look);
        }
        list.circle(pt(centre), static_cast<float>(r), look);
        list.box(pt(centre), {0.25f * static_cast<float>(r), 0.25f * static_cast<float>(r)}, 0.0f,
                 style("ground", "box_outline"));
    }
};

} // namespace
RUBE_PART(gear, GearKind)
} // namespace rube::game::parts
