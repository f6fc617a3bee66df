// rube_bench: every bench scene on each of rube's methods over a sweep of time steps and on the
// peer engines linked into this build, written as a CSV and drawn as an error-against-cost chart.

#include "chart.hpp"
#include "csv.hpp"
#include "failure_sweep.hpp"
#include "front.hpp"
#include "runner.hpp"
#include "scaling_chart.hpp"
#include "rube/physics/world.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace {

// The default CSV name: the machine and the date, so runs on other machines sit side by side.
std::string resultsName(const std::string& suffix) {
    char host[64] = "machine";
    gethostname(host, sizeof host - 1);
    const std::time_t now = std::time(nullptr);
    char date[16];
    std::strftime(date, sizeof date, "%Y-%m-%d", std::localtime(&now));
    return std::string(date) + "-" + host + suffix + ".csv";
}

// A results file, its folder made first (bench/results/ on a fresh clone, or wherever a flag points).
std::ofstream openResultFile(const std::string& path) {
    const std::filesystem::path file(path);
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    return std::ofstream(file);
}

bool selected(const std::vector<std::string>& filter, const std::string& name) {
    return filter.empty() || std::find(filter.begin(), filter.end(), name) != filter.end();
}

// --quick runs the scaling sweep's smallest point only: it checks that it runs, in a few seconds.
constexpr int kQuickScalingBodies = 100;
// The peers' cost grows past rube's (Box2D 2.4.1 takes about 9 s a run at 5000 balls): the full run
// takes them to 5000 balls to stay under 5 minutes; --scaling takes every engine to 20,000.
constexpr int kFullRunPeerScalingBodies = 5000;
// A scaling run of 20,000 balls takes over 8 s on every engine; none of them can get stuck (each
// step's work is bounded), so the sweep gives its runs longer before abandoning them.
constexpr double kScalingRunLimit = 120.0;

// The scaling sweep measures rube's solver (the method made for piles: the exact method takes over
// 8 s a run on the 1000-ball pile already) against the peers, all at 60 Hz.
bool runsInScaling(const bench::Engine& engine) {
    return engine.kind == bench::EngineKind::peer || engine.name == "rube-solver";
}

// With sleeping, a pile's cost per body-step is mostly how soon it comes to rest (the 100-ball pile
// sleeps at 3 s, the 20,000-ball one, wide on its frictionless floor, not within the 10 s), not how
// the solver's work grows with N. So the sweep runs rube's solver a second time with sleeping off:
// every body solved every step, the curve the scaling target is about.
bench::Engine awakeVariant(const bench::Engine& engine) {
    bench::Engine awake = engine;
    awake.name = engine.name + "-awake";
    awake.make = [make = engine.make](bench::WorldSpec spec) {
        spec.rubeSleep = false;
        return make(spec);
    };
    return awake;
}

// The failure table: every probe on every method, written as Markdown. Returns false if unwritable.
bool writeFailures(const std::string& path, bool quick) {
    const auto start = std::chrono::steady_clock::now();
    const bench::failures::Sweep sweep = bench::failures::runSweep(quick);
    std::ofstream out = openResultFile(path);
    bench::failures::writeMarkdown(out, sweep, quick ? "rube_bench --quick" : "rube_bench --failures");
    out.close();
    if (!out) {
        std::cerr << "rube_bench: could not write " << path << '\n';
        return false;
    }
    std::cerr << "rube_bench: wrote " << path << " in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
    return true;
}

/// Whether two rows measured the same world: every error figure equal, bit for bit (NaN where a
/// scene has no such figure).
bool sameMeasurements(const bench::Row& a, const bench::Row& b) {
    const auto same = [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; };
    return same(a.metrics.error, b.metrics.error) && same(a.metrics.error2, b.metrics.error2) &&
           same(a.metrics.overlap, b.metrics.overlap) && same(a.metrics.momentum, b.metrics.momentum) &&
           a.metrics.tunnels == b.metrics.tunnels && a.escapes == b.escapes && a.nonFinite == b.nonFinite;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"rube_bench: rube's time-step methods against Box2D 2.4.1 and Chipmunk 7.0.3, speed against accuracy"};
    bool quick = false, list = false, failuresOnly = false, noScaling = false, scalingOnly = false;
    std::string csvPath, chartPath, scalingChartPath, boxScalingChartPath, failuresPath, frontPath;
    std::vector<std::string> sceneFilter, engineFilter;
    std::vector<int> rates;
    int repeats = 5;
    int minRepeats = 0; // 0: not given
    double runTimeLimit = 8.0;
    bool rubeNoSleep = false, chipmunkSleep = false;
    std::vector<int> rubeWorkers;
    app.add_flag("--quick", quick, "tiny scenes, one repeat, two time steps: checks the bench runs, not its speed");
    app.add_flag("--list", list, "list the scenes and engines and exit");
    app.add_option("--csv", csvPath,
                   "results file (default: bench/results/<date>-<host>.csv, --scaling: <date>-<host>-scaling.csv; "
                   "--quick: ./bench-quick.csv)");
    app.add_option("--chart", chartPath,
                   "chart PNG (default: screenshots/speed-vs-accuracy.png; --quick: none; \"\": none)");
    app.add_option("--scaling-chart", scalingChartPath,
                   "scaling chart PNG (default: screenshots/scaling.png; --quick: none; \"\": none)");
    app.add_option("--box-scaling-chart", boxScalingChartPath,
                   "the boxes' scaling chart PNG (default: screenshots/scaling-boxes.png; --quick: none; \"\": none)");
    app.add_flag("--no-scaling", noScaling, "leave out the scaling sweeps (pile-scaling-*, pyramid-scaling-*)");
    app.add_flag("--scaling", scalingOnly,
                 "only the scaling sweep, with the peers up to 20,000 balls too (the full run stops them at 5000)");
    app.add_flag("--failures", failuresOnly, "only sweep where rube's methods fail and write the table (no timing)");
    app.add_option("--failures-md", failuresPath,
                   "failure table (default: bench/results/failures.md; --quick: ./failures-quick.md)");
    app.add_option("--front-md", frontPath,
                   "where auto stands against the other methods and peers, per scene and step (default: "
                   "bench/results/auto-front.md; --quick: ./auto-front-quick.md; \"\": none)");
    app.add_option("--scene", sceneFilter, "run only these scenes (repeatable)");
    app.add_option("--engine", engineFilter, "run only these engines, e.g. rube-solver, box2d-2.4.1 (repeatable)");
    app.add_option("--rate", rates, "rube's time steps as rates in Hz (default 30 60 120 240; peers run at 60)");
    app.add_option("--repeats", repeats, "most timed repeats per configuration; the median is kept")
        ->check(CLI::Range(1, 100));
    app.add_option("--min-repeats", minRepeats,
                   "timed repeats made of every configuration, even one slower than 4 s a run (default: 3, and 1 "
                   "for such slow runs; at most --repeats)")
        ->check(CLI::Range(1, 100));
    app.add_option("--run-limit", runTimeLimit, "seconds before one run is abandoned and flagged as a timeout");
    app.add_flag("--rube-no-sleep", rubeNoSleep,
                 "rube's methods without sleeping islands (sleep_speed 0): what a pile costs while it never rests");
    app.add_option("--rube-workers", rubeWorkers,
                   "rube's worker threads (WorldDef::workers), one or more counts: every rube row is run once per "
                   "count, the counts' timed runs taking turns (1, 2, 1, 2, ...), the count in the CSV's workers "
                   "column, processor time beside the wall clock in cpu_ms_per_step (default 1; the chart and "
                   "the auto table take the first count's rows)")
        ->check(CLI::Range(1, rube::kMaxWorkers));
    app.add_flag("--chipmunk-sleep", chipmunkSleep,
                 "Chipmunk with sleeping on (0.5 s idle; Chipmunk's default is off, Box2D's on)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e); // --help
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
        std::cerr << "rube_bench: " << message << " (see rube_bench --help)\n";
        return 2;
    }
    if (minRepeats > repeats) {
        std::cerr << "rube_bench: --min-repeats " << minRepeats << " is more than --repeats " << repeats
                  << " (see rube_bench --help)\n";
        return 2;
    }

    auto& engines = bench::engines();
    std::stable_sort(engines.begin(), engines.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
    if (list) {
        for (const auto& s : bench::scenes()) std::cout << "scene  " << s.name << "  (" << s.errorName << ")\n";
        for (const auto& e : engines) {
            std::cout << "engine " << e.name << '\n';
            if (e.kind == bench::EngineKind::rubeMethod && runsInScaling(e))
                std::cout << "engine " << awakeVariant(e).name << "  (scaling sweep only: sleeping off)\n";
        }
        return 0;
    }

    const std::filesystem::path source = RUBE_SOURCE_DIR;
    if (failuresPath.empty())
        failuresPath = quick ? "failures-quick.md" : (source / "bench/results/failures.md").string();
    // Defaults only for what was not asked for: an explicit "" writes no file.
    const auto given = [&app](const char* option) { return app.count(option) > 0; };
    if (frontPath.empty() && !given("--front-md"))
        frontPath = quick ? "auto-front-quick.md" : (source / "bench/results/auto-front.md").string();
    if (failuresOnly) return writeFailures(failuresPath, quick) ? 0 : 1;
    if (rates.empty()) rates = quick ? std::vector<int>{30, 60} : std::vector<int>{30, 60, 120, 240};
    if (csvPath.empty())
        csvPath = quick ? "bench-quick.csv"
                        : (source / "bench/results" / resultsName(scalingOnly ? "-scaling" : "")).string();
    if (chartPath.empty() && !quick && !given("--chart"))
        chartPath = (source / "screenshots/speed-vs-accuracy.png").string();
    if (scalingChartPath.empty() && !quick && !given("--scaling-chart"))
        scalingChartPath = (source / "screenshots/scaling.png").string();
    if (boxScalingChartPath.empty() && !quick && !given("--box-scaling-chart"))
        boxScalingChartPath = (source / "screenshots/scaling-boxes.png").string();

    bench::RunOptions options;
    options.size.quick = quick;
    options.maxRepeats = quick ? 1 : repeats;
    options.minRepeats = std::min(options.maxRepeats, minRepeats > 0 ? minRepeats : 3);
    options.slowRunRepeats = quick ? 1 : std::max(1, minRepeats);
    options.runTimeLimit = runTimeLimit;
    options.rubeSleep = !rubeNoSleep;
    options.chipmunkSleep = chipmunkSleep;
    if (rubeWorkers.empty()) rubeWorkers = {1};

    std::vector<bench::Row> rows;
    std::vector<std::string> sceneOrder, scalingOrder, boxScalingOrder;
    const auto start = std::chrono::steady_clock::now();
    for (const auto& scene : bench::scenes()) {
        if (!selected(sceneFilter, scene.name)) continue;
        const bool scaling = scene.scalingBodies > 0;
        if (scaling ? noScaling || (quick && scene.scalingBodies > kQuickScalingBodies) : scalingOnly) continue;
        (scaling ? (scene.boxes ? boxScalingOrder : scalingOrder) : sceneOrder).push_back(scene.name);
        bench::RunOptions sceneOptions = options;
        if (scaling) sceneOptions.runTimeLimit = std::max(options.runTimeLimit, kScalingRunLimit);
        std::vector<bench::Engine> sceneEngines;
        for (const auto& engine : engines) {
            if (!scaling || !runsInScaling(engine)) continue;
            sceneEngines.push_back(engine);
            // Boxes sleep too (issue 26): an exactly stacked pyramid is asleep after timeToSleep, so
            // the boxes' sweep needs the awake variant as much as the piles' does.
            if (engine.kind == bench::EngineKind::rubeMethod && options.rubeSleep)
                sceneEngines.push_back(awakeVariant(engine));
        }
        for (const auto& engine : scaling ? sceneEngines : engines) {
            if (!selected(engineFilter, engine.name)) continue;
            if (scene.boxes && !engine.boxes) continue; // only the solver moves boxes that turn
            if (scaling && engine.kind == bench::EngineKind::peer && !scalingOnly && !scene.boxes &&
                scene.scalingBodies > kFullRunPeerScalingBodies) {
                std::fprintf(stderr, "%-18s %-16s left out of the full run (cost): rube_bench --scaling runs it\n",
                             scene.name.c_str(), engine.name.c_str());
                continue;
            }
            // Peers run at the 60 Hz step their users run them at: one point each on the chart; the
            // scaling sweep runs everything at 60 Hz, since it measures cost against N, not dt.
            const std::vector<int> engineRates = engine.kind == bench::EngineKind::peer || scaling || scene.boxes
                                                     ? std::vector<int>{60}
                                                     : rates;
            // Coarse steps first: once a step times out, every finer one would too (more steps for
            // the same simulated time, and no method's work per simulated second falls as dt shrinks
            // in these scenes), so it is flagged as a timeout without spending the run limit again.
            std::vector<int> ordered = engineRates;
            std::sort(ordered.begin(), ordered.end());
            const std::vector<int> workerCounts = engine.kind == bench::EngineKind::peer ? std::vector<int>{1}
                                                                                         : rubeWorkers;
            std::optional<bench::Row> timedOut; // the coarsest step that timed out, at any worker count
            for (const int rate : ordered) {
                if (timedOut) {
                    for (const int workers : workerCounts) {
                        bench::Row row = *timedOut;
                        row.workers = workers; // workerCounts is {1} for a peer
                        row.timeStep = 1.0 / rate;
                        row.steps = static_cast<int>(std::lround(timedOut->steps * timedOut->timeStep * rate));
                        std::fprintf(stderr, "%-18s %-16s %4d Hz %2d w  TIMEOUT (not run: %d Hz timed out)\n",
                                     scene.name.c_str(), engine.name.c_str(), rate, row.workers,
                                     static_cast<int>(std::lround(1.0 / timedOut->timeStep)));
                        rows.push_back(row);
                    }
                    continue;
                }
                const std::vector<bench::Row> counted = bench::runScene(scene, engine, 1.0 / rate, sceneOptions,
                                                                        workerCounts);
                if (counted.empty()) {
                    std::fprintf(stderr, "%-18s %-16s does not have the scene's joint: not run\n", scene.name.c_str(),
                                 engine.name.c_str());
                    break;
                }
                for (const bench::Row& row : counted) {
                    if (row.timeout && !timedOut) timedOut = row;
                    std::fprintf(
                        stderr,
                        "%-18s %-16s %4d Hz %2d w  %10.4f ms/step (cpu %9.4f, last 1 s %9.4f)  error %-12.4g %s%s\n",
                        scene.name.c_str(), engine.name.c_str(), rate, row.workers, row.msPerStep, row.cpuMsPerStep,
                        row.msPerStepLastSecond, row.metrics.tunnels >= 0 ? row.metrics.tunnels : row.metrics.error,
                        row.timeout ? " TIMEOUT" : "", row.nonFinite ? " NaN" : "");
                    rows.push_back(row);
                }
                // Several worker counts: how much faster each is than the first, and whether it
                // measured the same world (it must: the counts give the same bits).
                for (std::size_t w = 1; w < counted.size(); ++w) {
                    const bench::Row &base = counted.front(), &row = counted[w];
                    if (base.timeout || row.timeout || row.msPerStep <= 0.0 || base.cpuMsPerStep <= 0.0) continue;
                    std::fprintf(stderr,
                                 "%-18s %-16s %4d Hz %2d w  %.2f x faster than %d (wall), %.2f x its processor "
                                 "time, %s\n",
                                 scene.name.c_str(), engine.name.c_str(), rate, row.workers,
                                 base.msPerStep / row.msPerStep, base.workers, row.cpuMsPerStep / base.cpuMsPerStep,
                                 sameMeasurements(base, row) ? "the same measurements"
                                                             : "OTHER MEASUREMENTS (the counts must agree)");
                }
            }
        }
    }

    std::ofstream csv = openResultFile(csvPath);
    bench::writeCsv(csv, rows);
    csv.close();
    if (!csv) {
        std::cerr << "rube_bench: could not write " << csvPath << '\n';
        return 1;
    }
    std::cerr << "rube_bench: wrote " << csvPath << " (" << rows.size() << " rows) in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";

    // Where auto stands: written whenever auto ran, so a reader sees every step it was beaten, if any.
    // The chart and the auto table compare one row per engine: the first worker count's.
    std::erase_if(rows, [&](const bench::Row& r) { return !r.peer && r.workers != rubeWorkers.front(); });
    const std::vector<bench::AutoVerdict> verdicts = bench::judgeAuto(rows, sceneOrder);
    if (!verdicts.empty() && !frontPath.empty()) {
        std::ofstream front = openResultFile(frontPath);
        bench::writeAutoTable(front, verdicts);
        const auto beaten = std::count_if(verdicts.begin(), verdicts.end(),
                                          [](const auto& v) { return !v.beatenBy.empty(); });
        std::cerr << "rube_bench: auto is on the front at " << verdicts.size() - static_cast<std::size_t>(beaten)
                  << " of " << verdicts.size() << " scene steps; wrote " << frontPath << '\n';
    }

    if (!chartPath.empty() && !sceneOrder.empty()) {
        const std::string why = bench::drawChart(
            rows, sceneOrder, std::filesystem::temp_directory_path() / "rube-bench-chart", chartPath);
        std::cerr << "rube_bench: " << (why.empty() ? "drew " + chartPath : why) << '\n';
    }
    if (!scalingChartPath.empty() && !scalingOrder.empty()) {
        const std::string why = bench::drawScalingChart(
            rows, scalingOrder, std::filesystem::temp_directory_path() / "rube-bench-chart", scalingChartPath);
        std::cerr << "rube_bench: " << (why.empty() ? "drew " + scalingChartPath : why) << '\n';
    }
    if (!boxScalingChartPath.empty() && !boxScalingOrder.empty()) {
        const bench::ScalingChartText text{
            "scaling-boxes",
            "Box2D's pyramid of unit boxes with base 20, 40 and 70 (180 steps) and 100 (large-pyramid, 500 steps) "
            "at 60 Hz: cost per body-step",
            150.0, 7000.0};
        const std::string why = bench::drawScalingChart(rows, boxScalingOrder,
                                                        std::filesystem::temp_directory_path() / "rube-bench-chart",
                                                        boxScalingChartPath, text);
        std::cerr << "rube_bench: " << (why.empty() ? "drew " + boxScalingChartPath : why) << '\n';
    }
    // The failure table is part of every full run (it takes about a second) unless scenes were picked.
    if (sceneFilter.empty() && engineFilter.empty() && !scalingOnly && !writeFailures(failuresPath, quick)) return 1;
    std::cerr << "rube_bench: done in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
    return 0;
}
