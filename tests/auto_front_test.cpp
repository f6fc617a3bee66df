// The rule that says whether auto lies on the error-against-cost front (bench/src/front.cpp), on
// made-up rows: what beats auto, what does not, and what counts as a failed configuration.
#include "front.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

using bench::Row;

namespace {

Row row(const std::string& engine, double dt, double msPerSimSecond, double error, bool peer = false) {
    Row r;
    r.scene = "scene";
    r.engine = engine;
    r.peer = peer;
    r.timeStep = dt;
    r.msPerSimSecond = msPerSimSecond;
    r.metrics.error = error;
    return r;
}

std::string beatenBy(const std::vector<Row>& rows) {
    const auto verdicts = bench::judgeAuto(rows, {"scene"});
    REQUIRE(verdicts.size() == 1);
    return verdicts.front().beatenBy;
}

} // namespace

TEST_CASE("auto is beaten only by a configuration both cheaper and more accurate beyond the margins", "[front]") {
    const Row autoRow = row("rube-auto", 1.0 / 60, 10.0, 1e-3);
    // Cheaper by 20 % and 10x more accurate at the same step: beaten.
    CHECK(beatenBy({autoRow, row("rube-exact", 1.0 / 60, 8.0, 1e-4)}) == "rube-exact");
    // Cheaper but less accurate, or more accurate but dearer: a trade, not a win.
    CHECK(beatenBy({autoRow, row("rube-discrete", 1.0 / 60, 1.0, 1e-1)}).empty());
    CHECK(beatenBy({autoRow, row("rube-solver", 1.0 / 60, 20.0, 1e-6)}).empty());
    // Within the cost margin (5 % cheaper) or the error margin (0.5 % more accurate): noise.
    CHECK(beatenBy({autoRow, row("rube-exact", 1.0 / 60, 9.5, 1e-4)}).empty());
    CHECK(beatenBy({autoRow, row("rube-exact", 1.0 / 60, 5.0, 0.995e-3)}).empty());
    // Another rube method competes at auto's own time step only: auto picks a method, not dt.
    CHECK(beatenBy({autoRow, row("rube-exact", 1.0 / 30, 5.0, 1e-4)}).empty());
    // A peer competes at the step it runs at.
    CHECK(beatenBy({autoRow, row("box2d-2.4.1", 1.0 / 30, 5.0, 1e-4, true)}) == "box2d-2.4.1");
}

TEST_CASE("errors at round-off are all equal, and a failed configuration never beats auto", "[front]") {
    // Both at round-off: a cheaper exact run is not "more accurate" than auto's 1e-14.
    CHECK(beatenBy({row("rube-auto", 1.0 / 60, 10.0, 1e-14), row("rube-exact", 1.0 / 60, 5.0, 1e-16)}).empty());
    Row timedOut = row("rube-exact", 1.0 / 60, 1.0, 1e-9);
    timedOut.timeout = true;
    Row escaped = row("rube-solver", 1.0 / 60, 1.0, 1e-9);
    escaped.escapes = 3;
    Row nan = row("rube-discrete", 1.0 / 60, 1.0, std::numeric_limits<double>::quiet_NaN());
    CHECK(beatenBy({row("rube-auto", 1.0 / 60, 10.0, 1e-3), timedOut, escaped, nan}).empty());
    // But an auto that failed is beaten by any cheaper configuration that did not.
    Row failedAuto = row("rube-auto", 1.0 / 60, 10.0, 1e-3);
    failedAuto.nonFinite = true;
    CHECK(beatenBy({failedAuto, row("rube-solver", 1.0 / 60, 5.0, 1.0)}) == "rube-solver");
}

TEST_CASE("the bullet's tunnels are compared as counts", "[front]") {
    Row autoRow = row("rube-auto", 1.0 / 60, 10.0, 0.0);
    autoRow.metrics.tunnels = 2;
    Row fewer = row("rube-exact", 1.0 / 60, 5.0, 0.0);
    fewer.metrics.tunnels = 0;
    CHECK(bench::chartError(autoRow) == 2.0);
    CHECK(beatenBy({autoRow, fewer}) == "rube-exact");
    autoRow.metrics.tunnels = 0;
    CHECK(beatenBy({autoRow, fewer}).empty());
}
