#pragma once
// The project's own finite-element reference tables (tests/data/fe/, made by scripts/fe/; what
// was validated and to what accuracy: scripts/fe/README.md): the reader every test of them uses.
// Each table is '#' provenance lines, then a CSV with a header whose columns carry their units.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "output/csv_table.hpp"

namespace mh::testing {

/// The table tests/data/fe/<name>, its '#' lines dropped.
inline CsvTable read_fe_table(const std::string& name) {
  const std::string path = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/fe/" + name;
  std::ifstream in(path);
  REQUIRE(in.good());
  std::string line, text;
  while (std::getline(in, line))
    if (line.empty() || line[0] != '#') text += line + "\n";
  return parse_csv(text, path);
}

/// The value of column `col` in row `row` (the column must exist).
inline double fe_num(const CsvTable& t, std::size_t row, const char* col) {
  REQUIRE(t.has_column(col));
  return std::stod(t.rows[row][static_cast<std::size_t>(t.column(col))]);
}

}  // namespace mh::testing
