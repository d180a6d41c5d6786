#pragma once
// A reference table of tests/data read whole (parse_csv, the project's one CSV reader), and one
// numeric cell of it by column name, or every row as numbers by column name (leading '#' lines,
// a table's provenance, skipped), or a run's output CSV as text by column name; a missing file or
// column fails the test.
#include <catch2/catch.hpp>

#include <cstddef>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "output/csv_table.hpp"

namespace mh::test {

/// tests/data/<relative> of the source tree; leading lines that start with '#' are skipped.
inline CsvTable read_data_csv(const std::string& relative) {
  const std::string path = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/" + relative;
  std::ifstream in(path);
  REQUIRE(in.good());
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  std::size_t start = 0;
  while (start < text.size() && text[start] == '#') {
    const std::size_t eol = text.find('\n', start);
    start = eol == std::string::npos ? text.size() : eol + 1;
  }
  return parse_csv(text.substr(start), path);
}

/// One row of a numeric reference table, its cells by column name (a missing name fails).
struct DataRow {
  std::map<std::string, double> v;
  double operator[](const std::string& k) const {
    const auto it = v.find(k);
    REQUIRE(it != v.end());
    return it->second;
  }
};

/// Every row of tests/data/<relative>, each cell as a number.
inline std::vector<DataRow> read_data_rows(const std::string& relative) {
  const CsvTable t = read_data_csv(relative);
  std::vector<DataRow> rows(t.rows.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    for (std::size_t c = 0; c < t.header.size(); ++c) rows[r].v[t.header[c]] = std::stod(t.rows[r][c]);
  return rows;
}

/// Every record of a CSV file a run wrote (cases.csv, pressure.csv: any path), each cell as text
/// by column name (read_csv_file: quoted cells unquoted); an unreadable file fails the test.
using TextRow = std::map<std::string, std::string>;
inline std::vector<TextRow> read_text_rows(const std::string& path) {
  const CsvTable t = read_csv_file(path);
  std::vector<TextRow> rows(t.rows.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    for (std::size_t c = 0; c < t.header.size(); ++c) rows[r][t.header[c]] = t.rows[r][c];
  return rows;
}

/// Row r's value in column c, as a number.
inline double csv_num(const CsvTable& t, std::size_t r, const char* c) {
  REQUIRE(t.has_column(c));
  return std::stod(t.rows[r][static_cast<std::size_t>(t.column(c))]);
}

}  // namespace mh::test
