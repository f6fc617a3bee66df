// Scene files: [[joint]], the machines' joints (engine/physics/include/rube/physics/joint.hpp):
// kind = "revolute" | "prismatic" | "weld" | "spring" | "pulley" | "gear" | "belt". Ends `a` and `b`
// name a [[circle]], [[box]] or [[capsule]] (an absent `a` is the world); a gear or belt names the
// joints it couples, defined before it. Read after the bodies. Each kind takes only its own keys: a
// key of another kind is reported with the kind it belongs to.
#include "scene_errors.hpp"
#include "scene_reading.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace rube::game {

namespace {

constexpr std::string_view kKindNames[] = {"revolute", "prismatic", "weld", "spring", "pulley", "gear", "belt"};
enum Kind : std::size_t { revolute, prismatic, weld, spring, pulley, gear, belt };

constexpr std::string_view kRevoluteKeys[] = {
    "kind", "a", "b", "anchor", "motor_speed", "max_torque", "lower_degrees", "upper_degrees", "collide_connected"};
constexpr std::string_view kPrismaticKeys[] = {"kind",        "a",         "b",     "anchor", "axis",
                                               "motor_speed", "max_force", "lower", "upper",  "collide_connected"};
constexpr std::string_view kWeldKeys[] = {"kind", "a", "b", "anchor", "hertz", "damping_ratio", "collide_connected"};
constexpr std::string_view kSpringKeys[] = {"kind",        "a",         "b",       "anchor_a", "anchor_b",
                                            "rest_length", "stiffness", "damping", "side",     "collide_connected"};
constexpr std::string_view kPulleyKeys[] = {"kind",     "a",        "b",     "anchor_a", "anchor_b",
                                            "ground_a", "ground_b", "ratio", "length",   "collide_connected"};
constexpr std::string_view kGearKeys[] = {"kind", "joint_a", "joint_b", "ratio"};
constexpr std::string_view kBeltKeys[] = {"kind", "joint_a", "joint_b", "radius_a", "radius_b"};
constexpr std::array<std::span<const std::string_view>, 7> kKeysOf = {
    kRevoluteKeys, kPrismaticKeys, kWeldKeys, kSpringKeys, kPulleyKeys, kGearKeys, kBeltKeys};
constexpr std::string_view kNameKey[] = {"name"};
constexpr std::string_view kSideNames[] = {"both", "push", "pull"};
constexpr SpringSide kSides[] = {SpringSide::both, SpringSide::pushOnly, SpringSide::pullOnly};
constexpr JointKind kKinds[] = {JointKind::revolute, JointKind::prismatic, JointKind::weld, JointKind::spring,
                                JointKind::pulley,   JointKind::gear,      JointKind::gear};

/// "(it belongs in a joint of kind 'x')" for every key of another kind.
std::vector<KeyHome> homesFor(std::size_t kind, std::vector<std::string>& words) {
    std::vector<KeyHome> homes;
    words.clear();
    words.reserve(64);
    for (std::size_t k = 0; k < kKeysOf.size(); ++k) {
        if (k == kind) continue;
        for (const std::string_view key : kKeysOf[k]) {
            const auto own = kKeysOf[kind];
            if (std::find(own.begin(), own.end(), key) != own.end()) continue;
            if (std::any_of(homes.begin(), homes.end(), [&](const KeyHome& h) { return h.key == key; })) continue;
            words.push_back("a [[joint]] of kind '" + std::string(kKindNames[k]) + "'");
            homes.push_back({key, words.back()});
        }
    }
    return homes;
}

/// The body named by `key`: a circle's or a rigid body's name. Nothing (and no error) when absent
/// and not required.
std::optional<SceneJointEnd> readEnd(TableReader& joint, std::string_view key, const SceneReading& reading, Need need) {
    const toml::node* node = joint.get(key, need);
    if (!node) return need == Need::required ? std::nullopt : std::optional<SceneJointEnd>{SceneJointEnd{}};
    const SourcePlace place = placeOf(node->source());
    const auto* text = node->as_string();
    if (!text) {
        joint.error(place, std::string(key) + " must name a circle, box or capsule (a string), got " +
                               std::string(typeName(*node)));
        return std::nullopt;
    }
    const std::string& name = text->get();
    const SceneDesc& scene = reading.scene;
    std::vector<std::string_view> names;
    for (std::size_t i = 0; i < scene.circleNames.size(); ++i) {
        if (!name.empty() && scene.circleNames[i] == name) return SceneJointEnd{static_cast<int>(i), -1};
        if (!scene.circleNames[i].empty()) names.push_back(scene.circleNames[i]);
    }
    for (std::size_t i = 0; i < scene.bodyNames.size(); ++i) {
        if (!name.empty() && scene.bodyNames[i] == name) return SceneJointEnd{-1, static_cast<int>(i)};
        if (!scene.bodyNames[i].empty()) names.push_back(scene.bodyNames[i]);
    }
    joint.error(place,
                "unknown body '" + name + "'" +
                    unknownNameHint(name, names, "named bodies", "no [[circle]], [[box]] or [[capsule]] has a name"));
    return std::nullopt;
}

Vec2 centreOf(const SceneJointEnd& end, const SceneDesc& scene) {
    if (end.circle >= 0) return scene.circles[static_cast<std::size_t>(end.circle)].position;
    if (end.body >= 0) return scene.bodies[static_cast<std::size_t>(end.body)].position;
    return {};
}

/// A gear's or belt's coupled joint, by the name of a [[joint]] before it.
std::optional<int> readCoupled(TableReader& joint, std::string_view key, const SceneReading& reading) {
    const auto name = joint.string(key, Need::required);
    if (!name) return std::nullopt;
    const auto& names = reading.scene.jointNames;
    std::vector<std::string_view> known;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (!name->empty() && names[i] == *name) return static_cast<int>(i);
        if (!names[i].empty()) known.push_back(names[i]);
    }
    joint.error(joint.valuePlace(key),
                "unknown joint '" + *name + "'" +
                    unknownNameHint(*name, known, "named joints before it", "no [[joint]] before it has a name"));
    return std::nullopt;
}

/// Both or neither of a limit's keys; lower <= upper.
std::optional<JointLimits> readLimits(TableReader& joint, std::string_view lowerKey, std::string_view upperKey,
                                      double scale) {
    const auto lower = joint.number(lowerKey), upper = joint.number(upperKey);
    if (!lower && !upper) return JointLimits{};
    if (!lower || !upper) {
        joint.error(joint.valuePlace(lower ? lowerKey : upperKey),
                    "give both " + std::string(lowerKey) + " and " + std::string(upperKey) + ", or neither");
        return std::nullopt;
    }
    if (*lower > *upper) {
        joint.error(joint.valuePlace(lowerKey), std::string(lowerKey) + " must not exceed " + std::string(upperKey));
        return std::nullopt;
    }
    return JointLimits{true, *lower * scale, *upper * scale};
}

/// A motor: its speed needs its maximum force or torque (a speed alone would be silently ignored).
std::optional<JointMotor> readMotor(TableReader& joint, std::string_view forceKey) {
    const auto speed = joint.number("motor_speed");
    const auto force = joint.number(forceKey, NumberRange::nonNegative());
    if (speed && !force) {
        joint.error(joint.valuePlace("motor_speed"), "a motor needs " + std::string(forceKey) + " as well");
        return std::nullopt;
    }
    return JointMotor{speed.value_or(0.0), force.value_or(0.0)};
}

void readJoint(const toml::table& table, SceneReading& reading) {
    SceneDesc& scene = reading.scene;
    const toml::node* kindNode = table.get("kind");
    std::size_t kind = kKindNames[0].size(); // not a kind yet
    if (kindNode && kindNode->is_string()) {
        const std::string& given = kindNode->as_string()->get();
        for (std::size_t k = 0; k < std::size(kKindNames); ++k)
            if (kKindNames[k] == given) kind = k;
    }
    if (kind >= std::size(kKindNames)) {
        // The kind first: every other key depends on it.
        std::vector<std::string_view> every;
        for (const auto keys : kKeysOf) every.insert(every.end(), keys.begin(), keys.end());
        TableReader joint(table, "in [[joint]]", every, reading.diag, {}, kNameKey);
        joint.choice("kind", kKindNames, Need::required);
        return;
    }
    std::vector<std::string> words;
    const std::vector<KeyHome> homes = homesFor(kind, words);
    TableReader joint(table, "in [[joint]] of kind '" + std::string(kKindNames[kind]) + "'", kKeysOf[kind],
                      reading.diag, homes, kNameKey);
    SceneJoint out;
    out.def.kind = kKinds[kind];
    bool ok = true;
    if (kind == gear || kind == belt) {
        const auto first = readCoupled(joint, "joint_a", reading), second = readCoupled(joint, "joint_b", reading);
        ok = first && second;
        if (ok && *first == *second) {
            joint.error(joint.valuePlace("joint_b"), "a gear couples two different joints");
            ok = false;
        }
        if (ok) {
            const JointKind ka = scene.joints[static_cast<std::size_t>(*first)].def.kind,
                            kb = scene.joints[static_cast<std::size_t>(*second)].def.kind;
            if (ka != JointKind::revolute) {
                joint.error(joint.valuePlace("joint_a"), "joint_a must be a revolute joint");
                ok = false;
            } else if (kb != JointKind::revolute && (kind == belt || kb != JointKind::prismatic)) {
                joint.error(joint.valuePlace("joint_b"), kind == belt
                                                             ? "a belt joins two revolute joints"
                                                             : "joint_b must be a revolute or prismatic joint");
                ok = false;
            }
        }
        if (kind == gear) {
            const auto ratio = joint.number("ratio", NumberRange::any(), Need::required);
            if (ratio && *ratio == 0.0) joint.error(joint.valuePlace("ratio"), "a gear's ratio must not be 0");
            if (!ratio || *ratio == 0.0) ok = false;
            else out.def.ratio = *ratio;
        } else if (ok) {
            // The belt's wheels: the radii given, else the radius of each revolute's circle.
            const auto radius = [&](std::string_view key, int coupled) -> std::optional<double> {
                if (const auto r = joint.number(key, NumberRange::size())) return r;
                if (joint.find(key)) return std::nullopt;
                const SceneJointEnd& wheel = scene.joints[static_cast<std::size_t>(coupled)].b;
                if (wheel.circle >= 0) return scene.circles[static_cast<std::size_t>(wheel.circle)].radius;
                joint.error(joint.tablePlace(), "give " + std::string(key) + ": the wheel of " +
                                                    std::string(key == "radius_a" ? "joint_a" : "joint_b") +
                                                    " is not a circle");
                return std::nullopt;
            };
            const auto ra = radius("radius_a", *first), rb = radius("radius_b", *second);
            ok = ra && rb;
            if (ok) out.def.ratio = -*rb / *ra; // same sense: r_a angle_a = r_b angle_b
        }
        out.jointA = first.value_or(-1);
        out.jointB = second.value_or(-1);
    } else {
        const bool twoBodies = kind == pulley;
        const auto a = readEnd(joint, "a", reading, twoBodies ? Need::required : Need::optional);
        const auto b = readEnd(joint, "b", reading, Need::required);
        ok = a && b;
        if (ok && a->circle == b->circle && a->body == b->body) {
            joint.error(joint.valuePlace("b"), "a joint must join two different bodies");
            ok = false;
        }
        if (ok) {
            out.a = *a;
            out.b = *b;
        }
        const Vec2 centreA = ok ? centreOf(out.a, scene) : Vec2{}, centreB = ok ? centreOf(out.b, scene) : Vec2{};
        if (kind == revolute || kind == prismatic || kind == weld) {
            const Vec2 anchor = joint.vec2("anchor", NumberRange::coordinate()).value_or(centreB);
            out.anchorA = out.anchorB = anchor;
        } else {
            const auto anchorA = joint.vec2("anchor_a", NumberRange::coordinate());
            if (ok && !anchorA && out.a.isWorld()) {
                joint.error(joint.tablePlace(), "a spring to the world needs anchor_a, the fixed point");
                ok = false;
            }
            out.anchorA = anchorA.value_or(centreA);
            out.anchorB = joint.vec2("anchor_b", NumberRange::coordinate()).value_or(centreB);
        }
        JointDef& d = out.def;
        // Whether the two bodies still collide with each other (by default they do not).
        d.collideConnected = joint.boolean("collide_connected").value_or(false);
        switch (kind) {
        case revolute: {
            const auto motor = readMotor(joint, "max_torque");
            const auto limits = readLimits(joint, "lower_degrees", "upper_degrees", std::numbers::pi / 180.0);
            ok = ok && motor && limits;
            if (motor) d.motor = *motor;
            if (limits) d.limits = *limits;
            break;
        }
        case prismatic: {
            const auto axis = joint.vec2("axis");
            if (axis && axis->length() == 0.0) {
                joint.error(joint.valuePlace("axis"), "a prismatic joint's axis must not be [0, 0]");
                ok = false;
            }
            // The axis is given in the world; the joint keeps it in a's frame.
            if (axis && axis->length() > 0.0) {
                const double angleA = out.a.body >= 0 ? scene.bodies[static_cast<std::size_t>(out.a.body)].angle : 0.0;
                const double c = std::cos(angleA), s = std::sin(angleA);
                d.localAxisA = Vec2{c * axis->x + s * axis->y, -s * axis->x + c * axis->y}.normalized();
            }
            const auto motor = readMotor(joint, "max_force");
            const auto limits = readLimits(joint, "lower", "upper", 1.0);
            ok = ok && motor && limits;
            if (motor) d.motor = *motor;
            if (limits) d.limits = *limits;
            break;
        }
        case weld:
            d.hertz = joint.number("hertz", NumberRange::nonNegative()).value_or(0.0);
            d.dampingRatio = joint.number("damping_ratio", NumberRange::nonNegative()).value_or(1.0);
            break;
        case spring: {
            const auto k = joint.number("stiffness", NumberRange::nonNegative(), Need::required);
            ok = ok && k;
            d.stiffness = k.value_or(0.0);
            d.damping = joint.number("damping", NumberRange::nonNegative()).value_or(0.0);
            d.restLength = joint.number("rest_length", NumberRange::nonNegative())
                               .value_or(out.anchorA.distance(out.anchorB));
            if (const auto side = joint.choice("side", kSideNames)) d.springSide = kSides[*side];
            break;
        }
        case pulley: {
            const auto groundA = joint.vec2("ground_a", NumberRange::coordinate(), Need::required);
            const auto groundB = joint.vec2("ground_b", NumberRange::coordinate(), Need::required);
            d.ratio = joint.number("ratio", NumberRange::positive()).value_or(1.0);
            ok = ok && groundA && groundB;
            if (!ok) break;
            d.groundA = *groundA;
            d.groundB = *groundB;
            const double taut = out.anchorA.distance(d.groundA) + d.ratio * out.anchorB.distance(d.groundB);
            const auto length = joint.number("length", NumberRange::positive());
            d.length = length.value_or(taut);
            if (!(d.length > 0.0)) {
                joint.error(joint.tablePlace(), "the pulley's rope starts with no length: give it a length");
                ok = false;
            } else if (taut > d.length * (1.0 + 1e-6)) {
                joint.error(joint.valuePlace("length"), "the pulley's rope needs " + formatNumber(taut) +
                                                            " m to reach its ends, more than its length " +
                                                            formatNumber(d.length));
                ok = false;
            }
            break;
        }
        default: break;
        }
    }
    const std::string name = readBodyName(joint, reading);
    // A joint that failed still takes its place (its error is reported: no World is built), so later
    // gears name the joints the file shows.
    if (!ok && reading.diag.empty()) joint.error(joint.tablePlace(), "this joint is not complete");
    scene.joints.push_back(out);
    scene.jointNames.push_back(name);
}

} // namespace

void readJoints(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("joint")) readJoint(*table, reading);
}

} // namespace rube::game
