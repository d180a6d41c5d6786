#pragma once
// A small, strict reader for the result tables mhcontact writes (cases.csv, ellipses.csv,
// caf.csv, pressure.csv) and for users' reference copies of them.
//
// Format accepted (RFC 4180 with a header row):
//  - the first record is the header; every later record must have exactly as many fields
//    (otherwise InputError naming "file:line" of the record's first line);
//  - fields are separated by ',' ; records end at LF or CRLF; a final newline is optional and
//    trailing empty lines are ignored;
//  - a field may be quoted with '"': inside quotes ',' and line breaks are literal and '""'
//    stands for one '"' (text columns such as `message` and `warnings`). A quote inside an
//    unquoted field, or text after a closing quote, is an error (strict: no guessing);
//  - a UTF-8 byte order mark at the very start is skipped;
//  - header names must be non-empty and unique.
// Cells are kept as text exactly as read (after unquoting); interpretation is the caller's.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mh {

struct CsvTable {
  std::string source;                          ///< file name used in messages ("file:line")
  std::vector<std::string> header;             ///< column names, in file order
  std::vector<std::vector<std::string>> rows;  ///< data records, each header.size() cells
  std::vector<std::size_t> row_line;           ///< 1-based file line where each record starts
  std::size_t header_line = 1;                 ///< 1-based line of the header (after leading BOM)

  /// Index of column `name` in header, or -1 if the table has no such column.
  int column(const std::string& name) const;
  bool has_column(const std::string& name) const { return column(name) >= 0; }
};

/// Parse CSV text. `source` names the origin in error messages. Throws InputError.
CsvTable parse_csv(std::string_view text, const std::string& source);

/// Read and parse a CSV file. Throws InputError naming the file if it cannot be read, and
/// "file:line" for malformed records.
CsvTable read_csv_file(const std::string& path);

/// Quote a cell for CSV output if needed (contains ',', '"', CR or LF, or leading/trailing
/// space): the inverse of the reader's unquoting.
std::string csv_quote(std::string_view cell);

}  // namespace mh
