// The launcher: a spring behind a plunger that slides in a fixed guide (a prismatic joint). The
// plunger starts pulled back by `pull`, held by a latch (the guide's motor at speed 0); a switch,
// click or script releases it, and the spring drives it forward to its stop at the rest length,
// flinging what lies on its face: energy 1/2 k x^2 into the plunger and ball together, so a ball
// of mass m leaves at v = x sqrt(k / (m + m_plunger)) (less what gravity takes along the stroke).
#include "part_common.hpp"

#include "script_file.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kPlungerMass = 0.2;  // kg
constexpr double kPlungerHalf = 0.06; // m: half the plunger's thickness along its axis
constexpr double kSpringBase = 0.6;   // m behind the plunger's rest, where the spring is fixed
constexpr double kLatch = 1e5;        // N: the latch's hold (the guide's motor at speed 0)

struct LauncherParams {
    double stiffness = 300.0; // k, N/m
    double pull = 0.3;        // x, m
    double width = 0.5;       // m
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the plunger's centre at its stop"},
                             {"angle", "0", "the way it throws, degrees"},
                             {"stiffness", "300", "the spring's k, N/m"},
                             {"pull", "0.3", "how far the plunger starts pulled back, m"},
                             {"width", "0.5", "the plunger's face, m"}};

Vec2 axisOf(const ItemDesc& item) { return Vec2::fromAngle(item.angle); }

class LauncherKind final : public PartKind {
public:
    std::string_view name() const override { return "launcher"; }
    int order() const override { return 64; }
    std::string_view summary() const override {
        return "a latched spring plunger: released by a switch or click, it throws at x sqrt(k / m)";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, LauncherParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        LauncherParams& p = item.params.as<LauncherParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto k = table.number("stiffness", NumberRange{0.0, 1e5, true})) p.stiffness = *k;
        if (const auto x = table.number("pull", NumberRange{0.0, 2.0, true})) p.pull = *x;
        if (const auto w = table.number("width", kSizeRange)) p.width = *w;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const LauncherParams& p = item.params.as<LauncherParams>();
        const Vec2 u = axisOf(item);
        ItemBodies bodies;
        RigidBodyDef plunger;
        plunger.position = item.position - u * p.pull;
        plunger.angle = item.angle;
        plunger.halfExtents = {kPlungerHalf, 0.5 * p.width};
        plunger.mass = kPlungerMass;
        plunger.material = bouncy(0.0); // it pushes; it does not bounce the ball off
        plunger.gravityScale = 0.0;     // the guide carries its weight
        bodies.rigidBodies.push_back(plunger);
        // The guide: slide s = (p - position) . u, from -pull to its stop at 0; latched by its motor.
        ItemJoint guide;
        guide.def.kind = JointKind::prismatic;
        guide.def.localAnchorA = item.position;
        guide.def.localAxisA = u;
        guide.def.referenceAngle = item.angle;
        guide.def.limits = {true, -p.pull, 0.0};
        guide.def.motor = {0.0, kLatch};
        guide.b = {ItemJointEnd::To::body, 0, {}};
        bodies.joints.push_back(guide);
        // The spring, from a fixed base behind the stop, at its rest length when the plunger is there.
        ItemJoint spring;
        spring.def.kind = JointKind::spring;
        spring.def.localAnchorA = item.position - u * kSpringBase;
        spring.def.restLength = kSpringBase;
        spring.def.stiffness = p.stiffness;
        spring.def.springSide = SpringSide::pushOnly;
        spring.b = {ItemJointEnd::To::body, 0, {}};
        bodies.joints.push_back(spring);
        return bodies;
    }
    // A click on the plunger (as it starts, pulled back) picks it.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at;
        const LauncherParams& p = item.params.as<LauncherParams>();
        const Vec2 u = axisOf(item), offset = cursor - (item.position - u * p.pull);
        return std::abs(offset.dot(u)) <= kPlungerHalf + tolerance &&
               std::abs(offset.dot(u.perpendicular())) <= 0.5 * p.width + tolerance;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)g, (void)seconds;
        const LauncherParams& p = item.params.as<LauncherParams>();
        return p.pull * std::sqrt(p.stiffness / std::max(lightest, 1e-6)); // all of 1/2 k x^2 into the lightest
    }
    // Releases the latch (once: a released spring stays released).
    void trigger(LevelRun& run, int item) const override { releaseLatch(run, item); }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The plunger, guide and spring are drawn with the bodies and joints; here the base the spring
    // stands on, lit while latched.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const bool latched = firstMotorOn(d);
        const Vec2 base = item.position - axisOf(item) * kSpringBase;
        d.list.box(pt(base), {0.05f, static_cast<float>(0.3 * item.params.as<LauncherParams>().width)},
                   static_cast<float>(item.angle), style(latched ? "highlight" : "ground", "ground_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.box({c.x - 0.8f * r, c.y}, {0.08f * r, 0.5f * r}, 0.0f, style("ground", "ground_outline"));
        const render::Point coil[] = {{c.x - 0.7f * r, c.y},
                                      {c.x - 0.55f * r, c.y + 0.25f * r},
                                      {c.x - 0.35f * r, c.y - 0.25f * r},
                                      {c.x - 0.15f * r, c.y + 0.25f * r},
                                      {c.x + 0.05f * r, c.y - 0.25f * r},
                                      {c.x + 0.2f * r, c.y}};
        list.polyline(coil, 2.0f, render::Palette::greybox()["rope"]);
        list.box({c.x + 0.3f * r, c.y}, {0.1f * r, 0.5f * r}, 0.0f, style("box", "box_outline"));
        list.circle({c.x + 0.7f * r, c.y}, 0.25f * r, style("ball", "ball_outline"));
    }
};

} // namespace
RUBE_PART(launcher, LauncherKind)
} // namespace rube::game::parts
