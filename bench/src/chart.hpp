#pragma once
/// The chart: error against cost on log axes, one panel per scene, drawn by gnuplot.

#include "runner.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace bench {

/// A path in gnuplot's single quotes.
std::string gnuplotQuoted(const std::filesystem::path& p);

/// Checks gnuplot is installed and makes `workDir` and the folder of `png`; returns why not, or "".
std::string prepareGnuplot(const std::filesystem::path& workDir, const std::filesystem::path& png);

/// Writes the data files and gnuplot script into `workDir` and runs gnuplot to draw `png`.
/// Returns an empty string on success, or why there is no chart (gnuplot missing, failed).
std::string drawChart(std::span<const Row> rows, const std::vector<std::string>& sceneOrder,
                      const std::filesystem::path& workDir, const std::filesystem::path& png);

} // namespace bench
