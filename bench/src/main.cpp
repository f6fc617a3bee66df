// rube_bench: every bench scene on each of rube's methods over a sweep of time steps and on the
// peer engines linked into this build, written as a CSV and drawn as an error-against-cost chart.

#include "chart.hpp"
#include "csv.hpp"
#include "runner.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

namespace {

// The default CSV name: the machine and the date, so runs on other machines sit side by side.
std::string resultsName() {
    char host[64] = "machine";
    gethostname(host, sizeof host - 1);
    const std::time_t now = std::time(nullptr);
    char date[16];
    std::strftime(date, sizeof date, "%Y-%m-%d", std::localtime(&now));
    return std::string(date) + "-" + host + ".csv";
}

bool selected(const std::vector<std::string>& filter, const std::string& name) {
    return filter.empty() || std::find(filter.begin(), filter.end(), name) != filter.end();
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"rube_bench: rube's time-step methods against Box2D 2.4.1 and Chipmunk 7.0.3, speed against accuracy"};
    bool quick = false, list = false;
    std::string csvPath, chartPath;
    std::vector<std::string> sceneFilter, engineFilter;
    std::vector<int> rates;
    int repeats = 5;
    double runTimeLimit = 8.0;
    app.add_flag("--quick", quick, "tiny scenes, one repeat, two time steps: checks the bench runs, not its speed");
    app.add_flag("--list", list, "list the scenes and engines and exit");
    app.add_option("--csv", csvPath, "results file (default: bench/results/<date>-<host>.csv; --quick: ./bench-quick.csv)");
    app.add_option("--chart", chartPath, "chart PNG (default: screenshots/speed-vs-accuracy.png; --quick: none)");
    app.add_option("--scene", sceneFilter, "run only these scenes (repeatable)");
    app.add_option("--engine", engineFilter, "run only these engines, e.g. rube-solver, box2d-2.4.1 (repeatable)");
    app.add_option("--rate", rates, "rube's time steps as rates in Hz (default 30 60 120 240; peers run at 60)");
    app.add_option("--repeats", repeats, "most timed repeats per configuration; the median is kept")->check(CLI::Range(1, 100));
    app.add_option("--run-limit", runTimeLimit, "seconds before one run is abandoned and flagged as a timeout");
    CLI11_PARSE(app, argc, argv);

    auto& engines = bench::engines();
    std::stable_sort(engines.begin(), engines.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
    if (list) {
        for (const auto& s : bench::scenes()) std::cout << "scene  " << s.name << "  (" << s.errorName << ")\n";
        for (const auto& e : engines) std::cout << "engine " << e.name << '\n';
        return 0;
    }

    const std::filesystem::path source = RUBE_SOURCE_DIR;
    if (rates.empty()) rates = quick ? std::vector<int>{30, 60} : std::vector<int>{30, 60, 120, 240};
    if (csvPath.empty()) csvPath = quick ? "bench-quick.csv" : (source / "bench/results" / resultsName()).string();
    if (chartPath.empty() && !quick) chartPath = (source / "screenshots/speed-vs-accuracy.png").string();

    bench::RunOptions options;
    options.size.quick = quick;
    options.maxRepeats = quick ? 1 : repeats;
    options.minRepeats = std::min(options.maxRepeats, 3);
    options.runTimeLimit = runTimeLimit;

    std::vector<bench::Row> rows;
    std::vector<std::string> sceneOrder;
    const auto start = std::chrono::steady_clock::now();
    for (const auto& scene : bench::scenes()) {
        if (!selected(sceneFilter, scene.name)) continue;
        sceneOrder.push_back(scene.name);
        for (const auto& engine : engines) {
            if (!selected(engineFilter, engine.name)) continue;
            // Peers run at the 60 Hz step their users run them at: one point each on the chart.
            const std::vector<int> engineRates = engine.kind == bench::EngineKind::peer ? std::vector<int>{60} : rates;
            for (const int rate : engineRates) {
                const bench::Row row = bench::runScene(scene, engine, 1.0 / rate, options);
                std::fprintf(stderr, "%-18s %-16s %4d Hz  %10.4f ms/step  error %-12.4g %s%s\n", scene.name.c_str(),
                             engine.name.c_str(), rate, row.msPerStep, row.metrics.tunnels >= 0 ? row.metrics.tunnels : row.metrics.error,
                             row.timeout ? " TIMEOUT" : "", row.nonFinite ? " NaN" : "");
                rows.push_back(row);
            }
        }
    }

    if (std::filesystem::path(csvPath).has_parent_path())
        std::filesystem::create_directories(std::filesystem::path(csvPath).parent_path());
    std::ofstream csv(csvPath);
    bench::writeCsv(csv, rows);
    csv.close();
    if (!csv) {
        std::cerr << "rube_bench: could not write " << csvPath << '\n';
        return 1;
    }
    std::cerr << "rube_bench: wrote " << csvPath << " (" << rows.size() << " rows) in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";

    if (!chartPath.empty()) {
        const std::string why = bench::drawChart(rows, sceneOrder, std::filesystem::temp_directory_path() / "rube-bench-chart", chartPath);
        std::cerr << "rube_bench: " << (why.empty() ? "drew " + chartPath : why) << '\n';
    }
    return 0;
}
