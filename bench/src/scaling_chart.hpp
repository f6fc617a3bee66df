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
std::string drawScalingChart(std::span<const Row> rows, const std::vector<std::string>& scalingScenes,
                             const std::filesystem::path& workDir, const std::filesystem::path& png);

} // namespace bench
