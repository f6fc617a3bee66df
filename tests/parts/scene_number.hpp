#pragma once
// A number for the scene text the parts' tests write: printed so that it reads back exactly (%.17g), so a
// test's positions and speeds are the ones its formulas use (std::to_string keeps 6 decimals: 5e-7 m off).
#include <cstdio>
#include <string>

namespace test {

inline std::string num(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

} // namespace test
