// The report of a search: grouping, shortcuts, robustness; JSON out and back in; merging slices.
#include "solve_report.hpp"

#include "json_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>

namespace rube::game {

namespace {

std::string verbOf(ActionKind kind) {
    switch (kind) {
    case ActionKind::rotate:
    case ActionKind::aim: return "aim";
    case ActionKind::fire:
    case ActionKind::fireWhen: return "fire";
    case ActionKind::detonate: return "detonate";
    case ActionKind::toggle: return "toggle";
    case ActionKind::cut: return "cut";
    }
    return "";
}

std::string fraction(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6f", value);
    return text;
}

// Share of neighbours solving, compared exactly: a/b > c/d as a d > c b (no neighbours: 0).
bool moreRobust(const FoundSolution& a, const FoundSolution& b) {
    const long long left = static_cast<long long>(a.neighboursSolving) * std::max(1, b.neighbours);
    const long long right = static_cast<long long>(b.neighboursSolving) * std::max(1, a.neighbours);
    return left > right;
}

std::string actionJson(const Action& a) {
    std::string text = "{\"step\": " + std::to_string(a.step) + ", \"do\": \"" + std::string(actionVerb(a.kind)) +
                       "\", \"item\": " + jsonString(a.item);
    if (a.angle) text += ", \"angle\": " + scriptNumber(a.angleDegrees);
    if (!a.target.empty())
        text += ", \"target\": " + jsonString(a.target) + ", \"arc\": \"" + (a.highArc ? "high" : "low") + "\"";
    return text + "}";
}

std::string placementJson(const Placement& p) {
    return "{\"kind\": " + jsonString(itemKindName(p.kind)) + ", \"position\": [" + scriptNumber(p.position.x) + ", " +
           scriptNumber(p.position.y) + "], \"angle\": " + scriptNumber(p.angleDegrees) + "}";
}

std::string placementWords(const Placement& p) {
    std::string text = std::string(itemKindName(p.kind)) + " at " + formatPair(p.position.x, p.position.y);
    if (p.kind->turns()) text += " angle " + scriptNumber(p.angleDegrees);
    return text;
}

std::string actionWords(const Action& a) {
    std::string text = std::string(actionVerb(a.kind)) + " " + a.item;
    if (a.angle) text += " to " + scriptNumber(a.angleDegrees) + " degrees";
    if (!a.target.empty()) text += " at " + a.target + (a.highArc ? " (high arc)" : " (low arc)");
    return text + " at step " + std::to_string(a.step);
}

bool unsignedNumber(const JsonValue* value, std::uint64_t& out) {
    if (!value || value->type != JsonValue::Type::number) return false;
    const char* end = value->text.data() + value->text.size();
    const auto [ptr, ec] = std::from_chars(value->text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

} // namespace

std::string PartsUsed::label() const {
    std::string text;
    for (const auto& [kind, count] : parts)
        text += (text.empty() ? "" : " + ") + kind + (count > 1 ? " x" + std::to_string(count) : "");
    std::string clicks;
    for (const std::string& act : acts) clicks += (clicks.empty() ? "" : ", ") + act;
    if (text.empty() && clicks.empty()) return "nothing";
    if (text.empty()) return clicks;
    return clicks.empty() ? text : text + "; " + clicks;
}

int PartsUsed::partCount() const {
    int n = 0;
    for (const auto& entry : parts) n += entry.second;
    return n;
}

PartsUsed partsUsed(const ScriptDesc& script) {
    PartsUsed used;
    for (const Placement& p : script.placements) ++used.parts[std::string(itemKindName(p.kind))];
    for (const Action& a : script.actions) used.acts.insert(verbOf(a.kind) + " " + a.item);
    return used;
}

std::string shortcutReason(const PartsUsed& used, const PartsUsed& intended) {
    if (used.partCount() < intended.partCount())
        return "fewer parts than the intended solution (" + std::to_string(used.partCount()) + " < " +
               std::to_string(intended.partCount()) + ")";
    for (const auto& [kind, count] : used.parts) {
        const auto it = intended.parts.find(kind);
        if (it == intended.parts.end() || it->second < count)
            return "more " + kind + " than the intended solution places";
    }
    for (const std::string& act : used.acts)
        if (!intended.acts.contains(act)) return "'" + act + "', which the intended solution does not do";
    return "";
}

std::size_t SolveReport::shortcuts() const {
    return static_cast<std::size_t>(
        std::count_if(groups.begin(), groups.end(), [](const SolutionGroup& g) { return !g.shortcut.empty(); }));
}

std::string subsetLabel(const SearchSpace& space, int subset) {
    PartsUsed used;
    const std::vector<int>& counts = space.subsetCounts(subset);
    for (std::size_t k = 0; k < counts.size(); ++k)
        if (counts[k] > 0) used.parts[std::string(itemKindName(space.kinds()[k].kind))] = counts[k];
    return used.label();
}

SolveReport makeReport(const SearchResult& result, const SearchSpace& space, const std::optional<PartsUsed>& intended) {
    SolveReport report;
    report.result = result;
    report.intended = intended;
    report.solveFraction = result.solveFraction(space);
    report.exhaustive = planSearch(space, result.budget).exhaustive();
    std::vector<int> partCounts;
    for (const FoundSolution& s : result.solutions) {
        const PartsUsed used = partsUsed(space.script(candidateOf(space, result, s.number)));
        report.uses.push_back(used.label());
        partCounts.push_back(used.partCount());
        auto group = std::find_if(report.groups.begin(), report.groups.end(),
                                  [&](const SolutionGroup& g) { return g.uses == report.uses.back(); });
        if (group == report.groups.end()) {
            report.groups.push_back({report.uses.back(), 0, s.number, intended ? shortcutReason(used, *intended) : ""});
            group = report.groups.end() - 1;
        }
        ++group->solutions;
    }
    std::sort(report.groups.begin(), report.groups.end(),
              [](const SolutionGroup& a, const SolutionGroup& b) { return a.uses < b.uses; });
    for (std::size_t i = 0; i < result.solutions.size(); ++i) {
        if (!report.mostRobust) {
            report.mostRobust = i;
            continue;
        }
        const std::size_t best = *report.mostRobust;
        const FoundSolution& a = result.solutions[i];
        const FoundSolution& b = result.solutions[best];
        if (moreRobust(a, b) || (!moreRobust(b, a) && partCounts[i] < partCounts[best])) report.mostRobust = i;
    }
    return report;
}

ScriptDesc solutionScript(const SearchSpace& space, const SearchResult& result, const FoundSolution& solution) {
    ScriptDesc script = space.script(candidateOf(space, result, solution.number));
    Expectation goal;
    goal.kind = EventKind::goal;
    goal.beforeStep = solution.goalStep + 1;
    script.expectations.push_back(goal);
    return script;
}

std::string reportJson(const SolveReport& report, const SearchSpace& space) {
    const SearchResult& r = report.result;
    std::ostringstream out;
    out << "{\n  \"level\": " << jsonString(r.level) << ",\n  \"search\": \""
        << (report.exhaustive ? "exhaustive" : "sampled") << "\",\n  \"space\": " << r.space
        << ",\n  \"budget\": " << r.budget << ",\n  \"seed\": " << r.seed << ",\n  \"shard\": [" << r.shardIndex << ", "
        << r.shardCount << "]"
        << ",\n  \"candidates\": " << r.tried() << ",\n  \"valid\": " << r.valid()
        << ",\n  \"solved\": " << r.solutions.size() << ",\n  \"solve_fraction\": " << fraction(report.solveFraction)
        << ",\n  \"found\": " << (r.solutions.empty() ? "false" : "true")
        << ",\n  \"intended\": " << (report.intended ? jsonString(report.intended->label()) : "null")
        << ",\n  \"subsets\": [";
    for (std::size_t i = 0; i < r.subsets.size(); ++i) {
        const SubsetTally& t = r.subsets[i];
        const int subset = static_cast<int>(i);
        out << (i ? "," : "") << "\n    {\"places\": " << jsonString(subsetLabel(space, subset))
            << ", \"size\": " << space.subsetSize(subset) << ", \"tried\": " << t.tried << ", \"valid\": " << t.valid
            << ", \"solved\": " << t.solved << "}";
    }
    out << "\n  ],\n  \"groups\": [";
    for (std::size_t g = 0; g < report.groups.size(); ++g) {
        const SolutionGroup& group = report.groups[g];
        out << (g ? "," : "") << "\n    {\"uses\": " << jsonString(group.uses) << ", \"solutions\": " << group.solutions
            << ", \"first\": " << group.first << ", \"shortcut\": " << (group.shortcut.empty() ? "false" : "true")
            << ", \"why\": " << jsonString(group.shortcut) << "}";
    }
    out << (report.groups.empty() ? "]" : "\n  ]") << ",\n  \"shortcuts\": " << report.shortcuts()
        << ",\n  \"most_robust\": "
        << (report.mostRobust ? std::to_string(r.solutions[*report.mostRobust].number) : "null")
        << ",\n  \"solutions\": [";
    for (std::size_t i = 0; i < r.solutions.size(); ++i) {
        const FoundSolution& s = r.solutions[i];
        const ScriptDesc script = space.script(candidateOf(space, r, s.number));
        out << (i ? "," : "") << "\n    {\"number\": " << s.number << ", \"uses\": " << jsonString(report.uses[i])
            << ", \"goal_step\": " << s.goalStep << ", \"neighbours\": " << s.neighbours
            << ", \"neighbours_solving\": " << s.neighboursSolving << ", \"place\": [";
        for (std::size_t p = 0; p < script.placements.size(); ++p)
            out << (p ? ", " : "") << placementJson(script.placements[p]);
        out << "], \"actions\": [";
        for (std::size_t a = 0; a < script.actions.size(); ++a) out << (a ? ", " : "") << actionJson(script.actions[a]);
        out << "]}";
    }
    out << (r.solutions.empty() ? "]" : "\n  ]") << "\n}\n";
    return out.str();
}

std::string reportText(const SolveReport& report, const SearchSpace& space) {
    const SearchResult& r = report.result;
    std::ostringstream out;
    out << "level:            " << r.level << '\n';
    out << "search:           "
        << (report.exhaustive ? "exhaustive, " : "sampled (seed " + std::to_string(r.seed) + "), ") << r.tried()
        << " candidates of " << r.space;
    if (r.shardCount > 1) out << " (slice " << r.shardIndex << " of " << r.shardCount << ")";
    out << '\n';
    out << "valid:            " << r.valid() << " (the rest refused by the placement rules or an aim out of reach)\n";
    out << "solutions:        " << r.solutions.size() << (r.solutions.empty() ? " (none found)" : "") << '\n';
    out << "solve fraction:   " << fraction(report.solveFraction) << '\n';
    for (std::size_t i = 0; i < r.subsets.size(); ++i) {
        const SubsetTally& t = r.subsets[i];
        const int subset = static_cast<int>(i);
        out << "subset:           " << subsetLabel(space, subset) << ": " << t.solved << " of " << t.valid
            << " valid solve, " << t.tried << " tried of " << space.subsetSize(subset) << '\n';
    }
    out << "intended:         " << (report.intended ? report.intended->label() : "(no solution script)") << '\n';
    for (const SolutionGroup& g : report.groups)
        out << (g.shortcut.empty() ? "group:            " : "shortcut:         ") << g.uses << ": " << g.solutions
            << " solution" << (g.solutions == 1 ? "" : "s") << ", first #" << g.first
            << (g.shortcut.empty() ? "" : " (" + g.shortcut + ")") << '\n';
    if (report.mostRobust) {
        const FoundSolution& s = r.solutions[*report.mostRobust];
        const ScriptDesc script = space.script(candidateOf(space, r, s.number));
        std::string what;
        for (const Placement& p : script.placements) what += (what.empty() ? "" : ", ") + placementWords(p);
        for (const Action& a : script.actions) what += (what.empty() ? "" : ", ") + actionWords(a);
        out << "most robust:      #" << s.number << ": " << (what.empty() ? "nothing placed" : what) << "; "
            << s.neighboursSolving << " of " << s.neighbours << " neighbours solve; goal at step " << s.goalStep
            << '\n';
    }
    return out.str();
}

std::optional<SearchResult> readResultJson(std::string_view text, std::string& error) {
    const std::optional<JsonValue> json = parseJson(text, error);
    if (!json) return std::nullopt;
    SearchResult r;
    const JsonValue* level = json->find("level");
    const JsonValue* search = json->find("search");
    const JsonValue* shard = json->find("shard");
    const JsonValue* solutions = json->find("solutions");
    const JsonValue* subsets = json->find("subsets");
    std::uint64_t shardIndex = 0, shardCount = 0;
    if (!level || level->type != JsonValue::Type::string || !search || !shard ||
        shard->type != JsonValue::Type::array || shard->array.size() != 2 ||
        !unsignedNumber(&shard->array[0], shardIndex) || !unsignedNumber(&shard->array[1], shardCount) ||
        !unsignedNumber(json->find("space"), r.space) || !unsignedNumber(json->find("budget"), r.budget) ||
        !unsignedNumber(json->find("seed"), r.seed) || !subsets || subsets->type != JsonValue::Type::array ||
        !solutions || solutions->type != JsonValue::Type::array) {
        error = "not a 'rube solve --json' result (level, search, space, budget, seed, shard, subsets and solutions "
                "are needed)";
        return std::nullopt;
    }
    r.level = level->text;
    for (const JsonValue& t : subsets->array) {
        SubsetTally tally;
        if (!unsignedNumber(t.find("tried"), tally.tried) || !unsignedNumber(t.find("valid"), tally.valid) ||
            !unsignedNumber(t.find("solved"), tally.solved)) {
            error = "a subset without tried, valid and solved";
            return std::nullopt;
        }
        r.subsets.push_back(tally);
    }
    r.shardIndex = static_cast<int>(shardIndex);
    r.shardCount = static_cast<int>(shardCount);
    for (const JsonValue& s : solutions->array) {
        FoundSolution f;
        std::uint64_t goal = 0, n = 0, solving = 0;
        if (!unsignedNumber(s.find("number"), f.number) || !unsignedNumber(s.find("goal_step"), goal) ||
            !unsignedNumber(s.find("neighbours"), n) || !unsignedNumber(s.find("neighbours_solving"), solving)) {
            error = "a solution without number, goal_step, neighbours and neighbours_solving";
            return std::nullopt;
        }
        f.goalStep = static_cast<std::int64_t>(goal);
        f.neighbours = static_cast<int>(n);
        f.neighboursSolving = static_cast<int>(solving);
        r.solutions.push_back(f);
    }
    return r;
}

std::optional<SearchResult> mergeResults(std::vector<SearchResult> slices, std::string& error) {
    if (slices.empty()) {
        error = "nothing to merge";
        return std::nullopt;
    }
    const SearchResult& first = slices.front();
    const int count = first.shardCount;
    std::vector<bool> seen(static_cast<std::size_t>(std::max(count, 0)), false);
    SearchResult merged = first;
    merged.shardIndex = 0;
    merged.shardCount = 1;
    merged.runs = 0;
    merged.solutions.clear();
    for (SubsetTally& t : merged.subsets) t = {};
    for (const SearchResult& s : slices) {
        if (s.level != first.level || s.space != first.space || s.budget != first.budget || s.seed != first.seed ||
            s.shardCount != count || s.subsets.size() != first.subsets.size()) {
            error = "the results are not slices of one search (level, space, budget, seed and slice count must agree)";
            return std::nullopt;
        }
        if (s.shardIndex < 0 || s.shardIndex >= count || seen[static_cast<std::size_t>(s.shardIndex)]) {
            error = "slice " + std::to_string(s.shardIndex) + " of " + std::to_string(count) + " is given twice";
            return std::nullopt;
        }
        seen[static_cast<std::size_t>(s.shardIndex)] = true;
        for (std::size_t i = 0; i < s.subsets.size(); ++i) {
            merged.subsets[i].tried += s.subsets[i].tried;
            merged.subsets[i].valid += s.subsets[i].valid;
            merged.subsets[i].solved += s.subsets[i].solved;
        }
        merged.runs += s.runs;
        merged.solutions.insert(merged.solutions.end(), s.solutions.begin(), s.solutions.end());
    }
    for (int i = 0; i < count; ++i)
        if (!seen[static_cast<std::size_t>(i)]) {
            error = "slice " + std::to_string(i) + " of " + std::to_string(count) + " is missing";
            return std::nullopt;
        }
    std::sort(merged.solutions.begin(), merged.solutions.end(),
              [](const FoundSolution& a, const FoundSolution& b) { return a.number < b.number; });
    return merged;
}

} // namespace rube::game
