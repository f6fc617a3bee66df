// CSV writing. Fields never contain commas or quotes (names are identifiers), so no quoting is needed.

#include "csv.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace bench {

const char* const kCsvHeader =
    "scene,engine,kind,dt_s,bodies,steps,repeats,ms_per_step,us_per_body_step,ms_per_sim_second,"
    "error,error_kind,error2,error2_kind,max_overlap_m,tunnels,escapes,caps_hit,nan,timeout,momentum_error_rel,"
    "ms_per_step_last_second,workers,cpu_ms_per_step";

namespace {

// %.6g keeps six significant figures: more than the timing noise, enough for 1e-12 errors.
std::string number(double v) {
    if (std::isnan(v)) return "";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

} // namespace

void writeCsv(std::ostream& out, std::span<const Row> rows) {
    out << kCsvHeader << '\n';
    for (const Row& r : rows) {
        const bool timed = !r.timeout;
        out << r.scene << ',' << r.engine << ',' << (r.peer ? "peer" : "rube") << ',' << number(r.timeStep) << ','
            << r.bodies << ',' << r.steps << ',' << r.repeats << ',' << (timed ? number(r.msPerStep) : "") << ','
            << (timed ? number(r.usPerBodyStep) : "") << ',' << (timed ? number(r.msPerSimSecond) : "") << ','
            << number(r.metrics.error) << ',' << r.errorName << ',' << number(r.metrics.error2) << ',' << r.error2Name
            << ',' << number(r.metrics.overlap) << ','
            << (r.metrics.tunnels >= 0 ? std::to_string(r.metrics.tunnels) : "") << ',' << r.escapes << ',' << r.capsHit
            << ',' << (r.nonFinite ? 1 : 0) << ',' << (r.timeout ? 1 : 0) << ',' << number(r.metrics.momentum) << ','
            << (timed ? number(r.msPerStepLastSecond) : "") << ',' << r.workers << ','
            << (timed ? number(r.cpuMsPerStep) : "") << '\n';
    }
}

} // namespace bench
