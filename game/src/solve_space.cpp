// The search space of `rube solve`: the grids, the subsets, and candidates by index or by draw.
#include "solve_space.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game {

namespace {

constexpr std::uint64_t kSaturated = std::uint64_t{1} << 62;

std::uint64_t times(std::uint64_t a, std::uint64_t b) {
    if (a == 0 || b == 0) return 0;
    return a > kSaturated / b ? kSaturated : a * b;
}

// SplitMix64 (Steele, Lea and Flood 2014): a tiny generator whose every output is a bijective mix
// of its counter, so seeding it with (seed, sample) gives independent, reproducible streams.
struct SplitMix {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
};

// Grid coordinates are written to scripts: whole millimetres read better and replay exactly.
double millimetres(double metres) { return std::round(metres * 1000.0) / 1000.0; }

// The points of a zone a part's centre may take: the zone shrunk by the part's smaller half-size
// (a ball's radius, a board's thickness), cut every `step`, the grid centred in what is left.
void addZoneGrid(KindAxis& axis, const Aabb& box, double margin, int zone) {
    const double lo[2] = {box.min.x + margin, box.min.y + margin};
    const double span[2] = {box.max.x - box.min.x - 2 * margin, box.max.y - box.min.y - 2 * margin};
    int count[2] = {0, 0};
    double offset[2] = {0, 0};
    for (int a = 0; a < 2; ++a) {
        if (span[a] < 0) return; // the part is bigger than the zone this way
        count[a] = static_cast<int>(std::floor(span[a] / axis.step + 1e-9)) + 1;
        offset[a] = 0.5 * (span[a] - (count[a] - 1) * axis.step);
    }
    axis.columns.push_back(count[0]);
    axis.rows.push_back(count[1]);
    for (int row = 0; row < count[1]; ++row)
        for (int column = 0; column < count[0]; ++column) {
            axis.points.push_back({zone, column, row});
            axis.positions.push_back({millimetres(lo[0] + offset[0] + column * axis.step),
                                      millimetres(lo[1] + offset[1] + row * axis.step)});
        }
}

KindAxis kindAxis(ItemKind kind, int count, const LevelDesc& level, const SpaceOptions& options) {
    KindAxis axis;
    axis.kind = kind;
    axis.count = count;
    const Aabb extent = itemExtent(defaultItem(kind, {0.0, 0.0}));
    const Vec2 size = extent.max - extent.min;
    // A quarter of the part's size: it moves by less than itself, so no gap it could fill is skipped.
    axis.step = options.step.value_or(0.25 * std::max(size.x, size.y));
    const double margin = 0.5 * std::min(size.x, size.y);
    for (std::size_t z = 0; z < level.zones.size(); ++z) {
        const std::size_t before = axis.columns.size();
        addZoneGrid(axis, level.zones[z].box, margin, static_cast<int>(z));
        if (axis.columns.size() == before) { // no room: keep the zone's slot so indices match
            axis.columns.push_back(0);
            axis.rows.push_back(0);
        }
    }
    if (kind->turns()) {
        const double period = kind->turnPeriod();
        const int n = std::max(1, static_cast<int>(std::floor(period / options.angleStep + 1e-9)));
        axis.angles.clear();
        for (int k = 0; k < n; ++k) axis.angles.push_back(-0.5 * period + k * options.angleStep);
        axis.turnsAround = std::abs(n * options.angleStep - period) < 1e-9;
    }
    return axis;
}

// Axis kinds of a subset's digits, in digit order.
enum class Axis : std::uint8_t { position, angle, aim, step };
struct AxisRef {
    Axis axis;
    int index; // the kind (position, angle) or actor (aim, step)
};

std::vector<AxisRef> axesOf(const std::vector<int>& counts, const std::vector<KindAxis>& kinds,
                            const std::vector<ActorAxis>& actors) {
    std::vector<AxisRef> axes;
    for (std::size_t k = 0; k < kinds.size(); ++k)
        for (int n = 0; n < counts[k]; ++n) {
            axes.push_back({Axis::position, static_cast<int>(k)});
            if (kinds[k].angles.size() > 1) axes.push_back({Axis::angle, static_cast<int>(k)});
        }
    for (std::size_t a = 0; a < actors.size(); ++a) {
        if (!actors[a].aims.empty()) axes.push_back({Axis::aim, static_cast<int>(a)});
        axes.push_back({Axis::step, static_cast<int>(a)});
    }
    return axes;
}

std::uint32_t radix(const AxisRef& ref, const std::vector<KindAxis>& kinds, const std::vector<ActorAxis>& actors) {
    switch (ref.axis) {
    case Axis::position: return static_cast<std::uint32_t>(kinds[static_cast<std::size_t>(ref.index)].points.size());
    case Axis::angle: return static_cast<std::uint32_t>(kinds[static_cast<std::size_t>(ref.index)].angles.size());
    case Axis::aim: return static_cast<std::uint32_t>(actors[static_cast<std::size_t>(ref.index)].aims.size());
    case Axis::step: return static_cast<std::uint32_t>(actors[static_cast<std::size_t>(ref.index)].clickSteps.size());
    }
    return 1;
}

} // namespace

SearchSpace::SearchSpace(const SceneDesc& level, const SpaceOptions& options)
    : levelName_(level.name) {
    const double dt = level.world.timeStep;
    steps_ = level.defaultSteps();
    if (level.level.goal && level.level.goal->timeLimit)
        steps_ = static_cast<std::int64_t>(std::ceil(*level.level.goal->timeLimit / dt - 1e-9));
    for (const auto& [name, count] : level.level.inventory)
        if (const ItemKind kind = findPartKind(name); kind && kind->placeable() && count > 0)
            kinds_.push_back(kindAxis(kind, count, level.level, options));
    std::sort(kinds_.begin(), kinds_.end(),
              [](const KindAxis& a, const KindAxis& b) { return a.kind->order() < b.kind->order(); });

    const std::int64_t every = std::max<std::int64_t>(1, std::llround(options.actionEvery / dt));
    for (const ItemDesc& item : level.level.items) {
        const std::optional<ActionKind> click = item.kind->clickAction();
        if (!click || item.name.empty()) continue;
        // A part the level's clicks leave out is never clicked; a cannon's aim, editing, stays.
        const bool clickable = level.level.clickable(item.name);
        if (!clickable && !item.kind->plays(PartRole::fire)) continue;
        ActorAxis actor;
        actor.item = item.name;
        actor.verb = *click;
        actor.clickSteps.push_back(-1);
        for (std::int64_t f = 0; clickable && f < steps_; f += every) actor.clickSteps.push_back(f);
        if (item.kind->plays(PartRole::fire)) {
            actor.aims.push_back({});
            const int n = static_cast<int>(std::floor(360.0 / options.aimStep + 1e-9));
            for (int k = 0; k < n; ++k) actor.aims.push_back({-180.0 + k * options.aimStep, "", false});
            for (const ItemDesc& other : level.level.items)
                if (other.kind->plays(PartRole::aimTarget) && !other.name.empty()) {
                    actor.aims.push_back({std::nullopt, other.name, false});
                    actor.aims.push_back({std::nullopt, other.name, true});
                }
        }
        actors_.push_back(std::move(actor));
    }

    // Every subset: counts 0 .. count of each kind, the first kind slowest.
    std::vector<int> counts(kinds_.size(), 0);
    for (;;) {
        subsets_.push_back(counts);
        std::size_t k = kinds_.size();
        while (k > 0 && counts[k - 1] == kinds_[k - 1].count) counts[--k] = 0;
        if (k == 0) break;
        ++counts[k - 1];
    }
    for (std::size_t s = 0; s < subsets_.size(); ++s) {
        std::uint64_t size = 1;
        double weight = 1.0;
        for (std::uint32_t r : radices(static_cast<int>(s))) {
            size = times(size, r);
            weight *= r;
        }
        subsetSizes_.push_back(size);
        subsetWeights_.push_back(weight);
        total_ = std::min(kSaturated, total_ + size);
    }
}

std::vector<std::uint32_t> SearchSpace::radices(int subset) const {
    std::vector<std::uint32_t> out;
    for (const AxisRef& ref : axesOf(subsets_[static_cast<std::size_t>(subset)], kinds_, actors_))
        out.push_back(radix(ref, kinds_, actors_));
    return out;
}

Candidate SearchSpace::at(std::uint64_t index) const {
    std::size_t s = 0;
    while (s + 1 < subsetSizes_.size() && index >= subsetSizes_[s]) index -= subsetSizes_[s++];
    return at(static_cast<int>(s), index);
}

Candidate SearchSpace::at(int subset, std::uint64_t index) const {
    Candidate c;
    c.subset = subset;
    const std::vector<std::uint32_t> r = radices(c.subset);
    c.digits.assign(r.size(), 0);
    for (std::size_t d = r.size(); d-- > 0;) {
        c.digits[d] = r[d] == 0 ? 0 : static_cast<std::uint32_t>(index % r[d]);
        if (r[d] != 0) index /= r[d];
    }
    return c;
}

Candidate SearchSpace::sample(int subset, std::uint64_t seed, std::uint64_t number) const {
    SplitMix rng{seed * 0xD1B54A32D192ED03ull ^ number};
    rng.next();
    Candidate c;
    c.subset = subset;
    for (std::uint32_t r : radices(c.subset))
        c.digits.push_back(r == 0 ? 0 : static_cast<std::uint32_t>(rng.next() % r));
    return c;
}

std::vector<Candidate> SearchSpace::neighbours(const Candidate& candidate) const {
    std::vector<Candidate> out;
    const std::vector<AxisRef> axes = axesOf(subsets_[static_cast<std::size_t>(candidate.subset)], kinds_, actors_);
    const auto with = [&](std::size_t d, std::uint32_t value) {
        Candidate n = candidate;
        n.digits[d] = value;
        out.push_back(std::move(n));
    };
    for (std::size_t d = 0; d < axes.size(); ++d) {
        const std::uint32_t v = candidate.digits[d];
        const std::uint32_t r = radix(axes[d], kinds_, actors_);
        switch (axes[d].axis) {
        case Axis::position: {
            const KindAxis& k = kinds_[static_cast<std::size_t>(axes[d].index)];
            const GridPoint p = k.points[v];
            const int columns = k.columns[static_cast<std::size_t>(p.zone)];
            const int rows = k.rows[static_cast<std::size_t>(p.zone)];
            const auto moved = [&](int dc, int dr) {
                const int c = p.column + dc, row = p.row + dr;
                if (c < 0 || c >= columns || row < 0 || row >= rows) return;
                with(d, static_cast<std::uint32_t>(static_cast<int>(v) + dc + dr * columns));
            };
            moved(-1, 0);
            moved(1, 0);
            moved(0, -1);
            moved(0, 1);
            break;
        }
        case Axis::angle: {
            const bool around = kinds_[static_cast<std::size_t>(axes[d].index)].turnsAround;
            if (v > 0) with(d, v - 1);
            else if (around && r > 2) with(d, r - 1);
            if (v + 1 < r) with(d, v + 1);
            else if (around && r > 2) with(d, 0);
            break;
        }
        case Axis::aim: {
            const ActorAxis& a = actors_[static_cast<std::size_t>(axes[d].index)];
            if (!a.aims[v].angle) break; // kept or aimed at an item: no step to take
            std::uint32_t angles = 0;    // aims 1 .. angles are the angles, all the way round
            while (angles + 1 < r && a.aims[angles + 1].angle) ++angles;
            with(d, v > 1 ? v - 1 : angles);
            with(d, v < angles ? v + 1 : 1);
            break;
        }
        case Axis::step:
            if (v == 0) break; // never: no step to take
            if (v > 1) with(d, v - 1);
            if (v + 1 < r) with(d, v + 1);
            break;
        }
    }
    return out;
}

ScriptDesc SearchSpace::script(const Candidate& candidate) const {
    ScriptDesc script;
    script.level = levelName_;
    const std::vector<AxisRef> axes = axesOf(subsets_[static_cast<std::size_t>(candidate.subset)], kinds_, actors_);
    std::vector<std::uint32_t> aimOf(actors_.size(), 0);
    std::vector<std::int64_t> stepOf(actors_.size(), -1);
    for (std::size_t d = 0; d < axes.size(); ++d) {
        const std::uint32_t v = candidate.digits[d];
        const std::size_t i = static_cast<std::size_t>(axes[d].index);
        switch (axes[d].axis) {
        case Axis::position: {
            Placement p;
            p.kind = kinds_[i].kind;
            p.position = kinds_[i].positions[v];
            script.placements.push_back(p);
            break;
        }
        case Axis::angle:
            script.placements.back().angleDegrees = kinds_[i].angles[v];
            script.placements.back().angle = scriptRadians(kinds_[i].angles[v]);
            break;
        case Axis::aim: aimOf[i] = v; break;
        case Axis::step: stepOf[i] = actors_[i].clickSteps[v]; break;
        }
    }
    for (std::size_t i = 0; i < actors_.size(); ++i) {
        const ActorAxis& a = actors_[i];
        if (!a.aims.empty() && aimOf[i] > 0) {
            const AimChoice& aim = a.aims[aimOf[i]];
            Action action;
            action.kind = ActionKind::aim;
            action.item = a.item;
            if (aim.angle) {
                action.angle = scriptRadians(*aim.angle);
                action.angleDegrees = *aim.angle;
            } else {
                // Aimed at an item when it fires, so a moving one is led from where it is then.
                action.step = std::max<std::int64_t>(0, stepOf[i]);
                action.target = aim.target;
                action.highArc = aim.highArc;
            }
            script.actions.push_back(action);
        }
        if (stepOf[i] >= 0) {
            Action action;
            action.kind = a.verb;
            action.item = a.item;
            action.step = stepOf[i];
            script.actions.push_back(action);
        }
    }
    std::stable_sort(script.actions.begin(), script.actions.end(),
                     [](const Action& a, const Action& b) { return a.step < b.step; });
    return script;
}

std::string SearchSpace::key(const Candidate& candidate) {
    std::string text = "s";
    text += std::to_string(candidate.subset);
    text += ':';
    for (std::size_t d = 0; d < candidate.digits.size(); ++d) {
        if (d > 0) text += ',';
        text += std::to_string(candidate.digits[d]);
    }
    return text;
}

} // namespace rube::game
