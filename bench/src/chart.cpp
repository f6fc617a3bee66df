// The chart. Each rube method is a line through its time-step sweep (cheapest and coarsest at
// the left); each peer is a point. Errors of exactly 0 cannot sit on a log axis, so they are
// drawn at a floor, and the panel says so.

#include "chart.hpp"
#include "front.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

namespace bench {
namespace {

std::string quoted(const std::filesystem::path& p) { return gnuplotQuoted(p); }

} // namespace

// Built by appending: GCC 12 gives a false -Wrestrict on "'" + std::string. Inside gnuplot's single
// quotes a quote is written twice ("Box2D's" as 'Box2D''s'), as its manual says.
std::string gnuplotQuoted(const std::filesystem::path& p) {
    std::string q(1, '\'');
    for (const char c : p.string()) {
        q += c;
        if (c == '\'') q += '\'';
    }
    q += '\'';
    return q;
}

std::string prepareGnuplot(const std::filesystem::path& workDir, const std::filesystem::path& png) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
        return "gnuplot not found (apt-get install gnuplot-nox): no chart drawn";
    std::filesystem::create_directories(workDir);
    if (png.has_parent_path()) std::filesystem::create_directories(png.parent_path());
    return {};
}

std::string drawChart(std::span<const Row> rows, const std::vector<std::string>& sceneOrder,
                      const std::filesystem::path& workDir, const std::filesystem::path& png) {
    if (std::string why = prepareGnuplot(workDir, png); !why.empty()) return why;

    const std::filesystem::path script = workDir / "chart.gp";
    std::ofstream gp(script);
    // Two rows of panels, each panel about 480 pixels wide however many scenes there are.
    const std::size_t columns = (sceneOrder.size() + 1) / 2;
    gp << "set terminal pngcairo size " << std::max<std::size_t>(1500, 480 * columns) << ",950 font ',10'\n"
       << "set output " << quoted(png) << "\n"
       << "set multiplot layout 2," << columns
       << " title 'rube: error against cost (rube methods over dt = 1/30 .. 1/240 s, auto drawn thick; peers at 1/60 "
          "s)'\n"
       << "set termoption noenhanced\nset logscale x\nset grid\nset key top right font ',8'\n"
       << "set xlabel 'ms of CPU per simulated second'\n";

    // One colour per engine in every panel: its place among the engines as they first appear.
    std::vector<std::string> engineOrder;
    for (const Row& r : rows)
        if (std::find(engineOrder.begin(), engineOrder.end(), r.engine) == engineOrder.end())
            engineOrder.push_back(r.engine);
    const auto colour = [&](const std::string& engine) {
        return std::to_string(1 + (std::find(engineOrder.begin(), engineOrder.end(), engine) - engineOrder.begin()));
    };

    for (const std::string& scene : sceneOrder) {
        // One data file per engine: rows of this scene sorted by cost, so each line reads left to right.
        std::map<std::pair<int, std::string>, std::vector<const Row*>> series;
        bool logAxis = true;
        std::string errorName;
        for (const Row& r : rows) {
            if (r.scene != scene || r.timeout || std::isnan(chartError(r))) continue;
            series[{r.peer ? 1 : 0, r.engine}].push_back(&r);
            logAxis = r.metrics.tunnels < 0;
            errorName = r.metrics.tunnels >= 0 ? "tunnels" : r.errorName;
        }
        gp << (logAxis ? "set logscale y\n" : "unset logscale y\n") << "set ylabel '" << errorName << "'\n"
           << "set title '" << scene << (logAxis ? " (an error of 0 is drawn at 1e-13)" : "") << "'\n";
        std::string plot;
        for (auto& [key, list] : series) {
            std::sort(list.begin(), list.end(),
                      [](const Row* a, const Row* b) { return a->msPerSimSecond < b->msPerSimSecond; });
            const std::filesystem::path data = workDir / (scene + "." + key.second + ".dat");
            std::ofstream out(data);
            for (const Row* r : list)
                out << r->msPerSimSecond << ' ' << (logAxis ? std::max(chartError(*r), kErrorFloor) : chartError(*r))
                    << '\n';
            if (!plot.empty()) plot += ", ";
            // auto is drawn thick: the chart shows where it lies against the other methods.
            const bool isAuto = key.second == "rube-auto";
            plot += quoted(data) + " using 1:2 with " +
                    (key.first ? "points pointsize 2"
                     : isAuto  ? "linespoints linewidth 3"
                               : "linespoints") +
                    " linetype " + colour(key.second) + " title '" + key.second + "'";
        }
        gp << (plot.empty() ? "plot 1/0 notitle" : "plot " + plot) << "\n";
    }
    gp << "unset multiplot\n";
    gp.close();
    const std::string command = "gnuplot " + quoted(script);
    if (std::system(command.c_str()) != 0) return "gnuplot failed on " + script.string();
    return {};
}

} // namespace bench
