#pragma once
/// The results file: one row per scene, engine and time step, as Box2D's benchmark/ keeps them.

#include "runner.hpp"

#include <iosfwd>
#include <span>

namespace bench {

/// The header line, naming every column (units in the names).
extern const char* const kCsvHeader;

/// Writes the header and every row; empty fields mean "not measured for this scene".
void writeCsv(std::ostream& out, std::span<const Row> rows);

} // namespace bench
