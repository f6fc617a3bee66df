// The front: auto against every other configuration of its scene (see front.hpp).

#include "front.hpp"

#include <cmath>
#include <ostream>
#include <sstream>

namespace bench {

double chartError(const Row& r) { return r.metrics.tunnels >= 0 ? r.metrics.tunnels : r.metrics.error; }

namespace {

bool failed(const Row& r) { return r.timeout || r.nonFinite || r.escapes > 0 || std::isnan(chartError(r)); }

// Lower by more than the margin; round-off errors (below the floor) are all equal.
bool moreAccurate(double a, double b) {
    if (b <= kErrorFloor) return false;
    return a < b * (1.0 - kErrorMargin);
}

std::string stepName(double dt) {
    std::ostringstream s;
    s << "1/" << std::lround(1.0 / dt) << " s";
    return s.str();
}

} // namespace

bool beats(const Row& a, const Row& b) {
    // A run that failed never beats one that held; one that held beats a failed one by being cheaper.
    if (failed(a) || failed(b)) return !failed(a) && failed(b) && a.msPerSimSecond < b.msPerSimSecond;
    return a.msPerSimSecond < b.msPerSimSecond * (1.0 - kCostMargin) && moreAccurate(chartError(a), chartError(b));
}

std::vector<AutoVerdict> judgeAuto(const std::vector<Row>& rows, const std::vector<std::string>& scenes) {
    std::vector<AutoVerdict> verdicts;
    for (const std::string& scene : scenes) {
        for (const Row& a : rows) {
            if (a.scene != scene || a.engine != "rube-auto") continue;
            AutoVerdict v{scene, a.timeStep, a.msPerSimSecond, chartError(a), {}};
            for (const Row& other : rows) {
                if (other.scene != scene || other.engine == a.engine) continue;
                // rube's other methods compete at the same time step (auto picks a method, not dt);
                // a peer competes at the step its users run it at.
                if (!other.peer && other.timeStep != a.timeStep) continue;
                if (!beats(other, a)) continue;
                v.beatenBy += (v.beatenBy.empty() ? "" : ", ") + other.engine;
            }
            verdicts.push_back(v);
        }
    }
    return verdicts;
}

void writeAutoTable(std::ostream& out, const std::vector<AutoVerdict>& verdicts) {
    out << "| scene | dt | auto ms per simulated s | auto error | beaten by (cheaper by > "
        << static_cast<int>(kCostMargin * 100) << " % and more accurate) |\n|---|---|---|---|---|\n";
    for (const AutoVerdict& v : verdicts)
        out << "| " << v.scene << " | " << stepName(v.timeStep) << " | " << v.msPerSimSecond << " | " << v.error
            << " | " << (v.beatenBy.empty() ? "none: on the front" : v.beatenBy) << " |\n";
}

} // namespace bench
