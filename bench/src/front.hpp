#pragma once
/// The error-against-cost front: which configurations no other beats on both error and cost, and
/// whether `rube-auto` is the cheapest that holds at each time step (issue 6: "auto lies on the front").

#include "runner.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace bench {

/// A configuration beats another only if it is both cheaper and more accurate by more than noise:
/// cost lower by kCostMargin (timing repeats on a shared 2-core machine differ by a few per cent)
/// and error lower by kErrorMargin (relative; errors at round-off, below kErrorFloor, are equal).
inline constexpr double kCostMargin = 0.10;
inline constexpr double kErrorMargin = 0.01;
inline constexpr double kErrorFloor = 1e-13;

/// The value the chart draws and the front compares: tunnels for the bullet, else the headline error.
double chartError(const Row& row);

/// True when `a` beats `b`: both measured, `a` neither failed (NaN, timeout, escapes) nor worse,
/// and it is cheaper and more accurate by more than the margins.
bool beats(const Row& a, const Row& b);

/// One auto point of one scene: who, if anyone, beats it among the other engines' rows (rube's
/// methods at the same time step, the peers at theirs).
struct AutoVerdict {
    std::string scene;
    double timeStep = 0.0;
    double msPerSimSecond = 0.0;
    double error = 0.0;
    std::string beatenBy; ///< empty: auto is on the front at this step
};

/// Every rube-auto row of `scenes`, judged against the rows of the same scene.
std::vector<AutoVerdict> judgeAuto(const std::vector<Row>& rows, const std::vector<std::string>& scenes);

/// The verdicts as a Markdown table.
void writeAutoTable(std::ostream& out, const std::vector<AutoVerdict>& verdicts);

} // namespace bench
