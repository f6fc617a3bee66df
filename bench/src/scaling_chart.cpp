// The scaling chart. The target is that rube's cost per body-step stays within 1.5 x of
// itself from 100 to 20,000 bodies, so the chart draws that band above the cheapest point of rube's
// solver with sleeping off (when the run has it: with sleeping on, the curve measures how soon each
// pile rests) and a linear y axis from 0: a flat line is what the target asks for, and a log axis
// would hide a slope.

#include "scaling_chart.hpp"

#include "chart.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>

namespace bench {

std::string drawScalingChart(std::span<const Row> rows, const std::vector<std::string>& scalingScenes,
                             const std::filesystem::path& workDir, const std::filesystem::path& png,
                             const ScalingChartText& text) {
    if (std::string why = prepareGnuplot(workDir, png); !why.empty()) return why;

    // One series per engine, by body count; timed-out runs have no cost and are left out.
    std::map<std::pair<int, std::string>, std::vector<const Row*>> series;
    std::map<std::string, double> cheapest; // per rube series
    for (const Row& r : rows) {
        if (r.timeout || std::find(scalingScenes.begin(), scalingScenes.end(), r.scene) == scalingScenes.end())
            continue;
        series[{r.peer ? 1 : 0, r.engine}].push_back(&r);
        if (r.peer) continue;
        auto [it, fresh] = cheapest.try_emplace(r.engine, r.usPerBodyStep);
        if (!fresh) it->second = std::min(it->second, r.usPerBodyStep);
    }
    const auto target = cheapest.contains("rube-solver-awake") ? cheapest.find("rube-solver-awake") : cheapest.begin();

    const std::filesystem::path script = workDir / (text.name + ".gp");
    std::ofstream gp(script);
    gp << "set terminal pngcairo size 1000,650 font ',11'\n"
       << "set output " << gnuplotQuoted(png) << "\n"
       << "set termoption noenhanced\nset logscale x\nset grid\nset key top left\n"
       << "set title " << gnuplotQuoted(text.title) << "\n"
       << "set xlabel 'bodies (log)'\nset ylabel 'microseconds per body-step (median)'\nset yrange [0:*]\n"
       << "set xrange [" << text.xMin << ":" << text.xMax << "]\n";
    std::string plot;
    int colour = 1;
    for (auto& [key, list] : series) {
        std::sort(list.begin(), list.end(), [](const Row* a, const Row* b) { return a->bodies < b->bodies; });
        const std::filesystem::path data = workDir / (text.name + "." + key.second + ".dat");
        std::ofstream out(data);
        for (const Row* r : list) out << r->bodies << ' ' << r->usPerBodyStep << '\n';
        if (!plot.empty()) plot += ", ";
        plot += gnuplotQuoted(data) + " using 1:2 with linespoints linetype " + std::to_string(colour++) +
                " pointtype 7 title '" + key.second + "'";
    }
    if (target != cheapest.end())
        plot += std::string(plot.empty() ? "" : ", ") + std::to_string(1.5 * target->second) +
                " with lines dashtype 2 linecolor 'grey40' title '1.5 x the cheapest " + target->first +
                " point (the issue target)'";
    gp << (plot.empty() ? "plot 1/0 notitle" : "plot " + plot) << "\n";
    gp.close();
    const std::string command = "gnuplot " + gnuplotQuoted(script);
    if (std::system(command.c_str()) != 0) return "gnuplot failed on " + script.string();
    return {};
}

} // namespace bench
