#pragma once
// A reference table of tests/data read whole (parse_csv, the project's one CSV reader), and one
// numeric cell of it by column name; a missing file or column fails the test.
#include <catch2/catch.hpp>

#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>

#include "output/csv_table.hpp"

namespace mh::test {

/// tests/data/<relative> of the source tree.
inline CsvTable read_data_csv(const std::string& relative) {
  const std::string path = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/" + relative;
  std::ifstream in(path);
  REQUIRE(in.good());
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_csv(ss.str(), path);
}

/// Row r's value in column c, as a number.
inline double csv_num(const CsvTable& t, std::size_t r, const char* c) {
  REQUIRE(t.has_column(c));
  return std::stod(t.rows[r][static_cast<std::size_t>(t.column(c))]);
}

}  // namespace mh::test
