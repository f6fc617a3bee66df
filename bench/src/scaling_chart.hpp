#pragma once
/// The scaling chart: cost per body-step against the number of bodies (log x), one line per engine.

#include "runner.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace bench {

/// Draws the rows whose scene is one of `scalingScenes` (other rows are skipped) into `png` with
/// gnuplot, the data files and script going to `workDir`. Returns "" on success, or why not.
/// `title` heads the chart, `xMin`..`xMax` bound its body axis; `name` keeps its data files apart.
struct ScalingChartText {
    std::string name = "scaling";
    std::string title = "The pile widened to N balls (the same 50 rows, a box N/1000 times as wide), 600 steps at "
                        "60 Hz: cost per body-step";
    double xMin = 70.0, xMax = 28000.0;
};
std::string drawScalingChart(std::span<const Row> rows, const std::vector<std::string>& scalingScenes,
                             const std::filesystem::path& workDir, const std::filesystem::path& png,
                             const ScalingChartText& text = {});

} // namespace bench
