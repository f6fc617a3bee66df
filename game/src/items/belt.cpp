// The belt: runs over two wheels (motors or plain wheels, named) and turns the second the same way
// as the first at r1 / r2 of its speed: a gear between their axles of ratio -r2 / r1 (joint.hpp),
// theta1 - (r2 / r1) theta2 = constant, so the rims move together. It has no body of its own.
#include "part_common.hpp"

#include "rube/physics/collision.hpp"

#include <cmath>
#include <optional>
#include <vector>
#include <tuple>

namespace rube::game::parts {
namespace {

constexpr double kMarkSpacing = 0.3; // m between the marks that show the belt running
constexpr double kRunReach = 0.05;   // m either side of a run that picks the belt in the editor

// A straight run of the belt: from the first wheel's rim to the second's.
struct BeltRun {
    Vec2 from, to;
};

// The two outer tangents of wheels (one, r1) and (two, r2), the runs a crossed-free belt lies on;
// none when one wheel is inside the other. With u the unit vector between the centres and
// c = (r1 - r2) / d, each tangent's normal is n = c u +- sqrt(1 - c^2) u_perp, touching at centre + r n.
std::vector<BeltRun> beltRuns(Vec2 one, double r1, Vec2 two, double r2) {
    const Vec2 between = two - one;
    const double distance = between.length();
    if (distance <= std::abs(r1 - r2)) return {};
    const Vec2 u = between * (1.0 / distance);
    const double c = (r1 - r2) / distance, s = std::sqrt(1.0 - c * c);
    std::vector<BeltRun> runs;
    for (const double side : {1.0, -1.0}) {
        const Vec2 n = u * c + u.perpendicular() * (side * s);
        runs.push_back({one + n * r1, two + n * r2});
    }
    return runs;
}

struct BeltParams {
    std::string from, to; // the wheels' names: the first drives, the second is driven
    SourcePlace fromAt, toAt;
    bool given = false; // both were written (a missing one is already an error of its own)
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: where the editor shows it (it runs between its wheels)"},
    {"from", "required", "the name of the wheel or motor it runs from"},
    {"to", "required", "the name of the wheel or motor it turns"}};

class BeltKind final : public PartKind {
public:
    std::string_view name() const override { return "belt"; }
    int order() const override { return 62; }
    std::string_view summary() const override {
        return "a belt over two named wheels: the second turns the same way at r1 / r2 of the first";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    ItemDesc make(Vec2 position) const override { return made(position, BeltParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        BeltParams& p = item.params.as<BeltParams>();
        p.from = table.string("from", Need::required).value_or("");
        p.fromAt = table.valuePlace("from");
        p.to = table.string("to", Need::required).value_or("");
        p.toAt = table.valuePlace("to");
        p.given = table.find("from") != nullptr && table.find("to") != nullptr;
    }
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        const BeltParams& p = item.params.as<BeltParams>();
        if (!p.given) return;
        for (const auto& [key, name, at] : {std::tuple{"from", &p.from, &p.fromAt}, std::tuple{"to", &p.to, &p.toAt}}) {
            if (std::string message = itemReferenceError(reading.scene.level, key, *name, PartRole::wheel);
                !message.empty())
                reading.diag.error(*at, std::move(message));
        }
        if (!p.from.empty() && p.from == p.to)
            reading.diag.error(p.toAt, "a belt must run between two wheels, not one");
    }
    // It has no body of its own: where only the item is known (a played level's items), its wheels
    // are picked instead; in a level being edited, it is picked on its runs between the wheels.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)item, (void)at, (void)cursor, (void)tolerance;
        return false;
    }
    bool pickedInLevel(const ItemDesc& item, const LevelDesc& level, Vec2 cursor, double tolerance) const override {
        const BeltParams& p = item.params.as<BeltParams>();
        const int a = level.find(p.from), b = level.find(p.to);
        if (a < 0 || b < 0) return false;
        const auto rim = [&](int index) -> std::optional<CircleDef> {
            const ItemDesc& wheel = level.items[static_cast<std::size_t>(index)];
            const ItemBodies shapes = wheel.kind->bodies(wheel);
            if (shapes.circles.empty()) return std::nullopt;
            return shapes.circles.front();
        };
        const std::optional<CircleDef> one = rim(a), two = rim(b);
        if (!one || !two) return false;
        for (const BeltRun& run : beltRuns(one->position, one->radius, two->position, two->radius))
            if (cursor.distance(closestPointOnSegment(cursor, run.from, run.to)) <= tolerance + kRunReach) return true;
        return false;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const BeltParams& p = item.params.as<BeltParams>();
        ItemBodies bodies;
        ItemJoint belt;
        belt.def.kind = JointKind::gear;
        belt.ratio = ItemJoint::Ratio::belt; // -r2 / r1 from the wheels' rims when it joins the World
        belt.gearItemA = p.from;
        belt.gearItemB = p.to;
        bodies.joints.push_back(belt);
        return bodies;
    }
    // The runs are drawn with the joints (joint_drawing.cpp); here, marks on them that move with the
    // rims, so a still frame shows a belt and a sequence shows it running.
    void draw(const PartDrawing& d) const override {
        const BeltParams& p = itemOf(d).params.as<BeltParams>();
        const int a = d.run.find(p.from), b = d.run.find(p.to);
        if (a < 0 || b < 0) return;
        const World& world = d.run.world();
        const CircleId ca = d.run.states()[static_cast<std::size_t>(a)].circle;
        const CircleId cb = d.run.states()[static_cast<std::size_t>(b)].circle;
        if (ca.isNull() || cb.isNull()) return;
        const Circle& one = world.circle(ca);
        const Circle& two = world.circle(cb);
        const double travelled = one.angle * one.radius; // how far the belt has run, m
        const render::Color mark = render::Palette::greybox()["rope"];
        double side = 1.0; // the first run goes one way, the second the other
        for (const BeltRun& run : beltRuns(one.position, one.radius, two.position, two.radius)) {
            const double length = run.from.distance(run.to);
            if (length > 0.0) {
                const Vec2 along = (run.to - run.from) * (1.0 / length);
                const double shift = std::fmod(side * travelled, kMarkSpacing);
                for (double t = shift < 0.0 ? shift + kMarkSpacing : shift; t < length; t += kMarkSpacing)
                    d.list.circle(pt(run.from + along * t), 0.035f, {mark, mark, 0.0f});
            }
            side = -side;
        }
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        const render::Style wheel = style("box", "box_outline");
        list.circle({c.x - 0.5f * r, c.y}, 0.35f * r, wheel);
        list.circle({c.x + 0.55f * r, c.y}, 0.22f * r, wheel);
        const render::Color rope = render::Palette::greybox()["rope"];
        list.line({c.x - 0.5f * r, c.y + 0.35f * r}, {c.x + 0.55f * r, c.y + 0.22f * r}, 2.0f, rope);
        list.line({c.x - 0.5f * r, c.y - 0.35f * r}, {c.x + 0.55f * r, c.y - 0.22f * r}, 2.0f, rope);
    }
};

} // namespace
RUBE_PART(belt, BeltKind)
} // namespace rube::game::parts
