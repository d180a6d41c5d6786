#include "output/csv_table.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include "core/errors.hpp"

namespace mh {

int CsvTable::column(const std::string& name) const {
  for (std::size_t j = 0; j < header.size(); ++j)
    if (header[j] == name) return static_cast<int>(j);
  return -1;
}

namespace {

struct Record {
  std::size_t line;                 // 1-based line where the record starts
  std::vector<std::string> fields;
};

std::string shown(std::string_view s) {
  constexpr std::size_t kMax = 40;  // keep messages one line long
  std::string r(s.substr(0, kMax));
  if (s.size() > kMax) r += "...";
  return "\"" + r + "\"";
}

}  // namespace

CsvTable parse_csv(std::string_view text, const std::string& source) {
  std::size_t pos = 0;
  const std::size_t n = text.size();
  if (text.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;  // UTF-8 byte order mark
  std::size_t line = 1;
  std::vector<Record> records;

  while (pos < n) {
    Record rec{line, {}};
    bool end_of_record = false;
    while (!end_of_record) {
      std::string field;
      if (pos < n && text[pos] == '"') {
        const std::size_t open_line = line;
        ++pos;
        bool closed = false;
        while (pos < n) {
          const char c = text[pos];
          if (c == '"') {
            if (pos + 1 < n && text[pos + 1] == '"') {
              field += '"';
              pos += 2;
              continue;
            }
            ++pos;
            closed = true;
            break;
          }
          if (c == '\n') ++line;
          field += c;
          ++pos;
        }
        if (!closed)
          throw InputError(at_line(source, open_line), "", "quoted field is never closed",
                           "a field starting with '\"' must end with '\"'; write '\"\"' for a quote "
                           "inside it");
      } else {
        while (pos < n && text[pos] != ',' && text[pos] != '\n' && text[pos] != '\r') {
          if (text[pos] == '"')
            throw InputError(at_line(source, line), shown(field + '"'),
                             "quote character inside an unquoted field",
                             "quote the whole field and double the quote: \"a \"\"b\"\" c\"");
          field += text[pos++];
        }
      }
      rec.fields.push_back(std::move(field));

      // Field terminator: ',' (next field), LF or CRLF (end of record), end of text.
      if (pos >= n) {
        end_of_record = true;
      } else if (text[pos] == ',') {
        ++pos;
      } else if (text[pos] == '\n') {
        ++pos;
        ++line;
        end_of_record = true;
      } else if (text[pos] == '\r' && pos + 1 < n && text[pos + 1] == '\n') {
        pos += 2;
        ++line;
        end_of_record = true;
      } else if (text[pos] == '\r') {
        throw InputError(at_line(source, line), "", "carriage return without line feed",
                         "end lines with LF or CRLF");
      } else {
        throw InputError(at_line(source, line), shown(text.substr(pos, 20)),
                         "text after the closing quote of a quoted field",
                         "a quoted field must be followed by ',' or the end of the line");
      }
    }
    records.push_back(std::move(rec));
  }

  // Trailing empty lines (a record of one empty field) carry nothing.
  while (!records.empty() && records.back().fields.size() == 1 && records.back().fields[0].empty())
    records.pop_back();

  if (records.empty())
    throw InputError(source, "", "empty table: no header row",
                     "the first line must name the columns, e.g. case,Q_kN,...");

  CsvTable t;
  t.source = source;
  t.header = std::move(records.front().fields);
  t.header_line = records.front().line;
  std::unordered_set<std::string> seen;
  for (const std::string& h : t.header) {
    if (h.empty())
      throw InputError(at_line(source, t.header_line), "", "empty column name in the header");
    if (!seen.insert(h).second)
      throw InputError(at_line(source, t.header_line), h, "column name appears twice in the header");
  }

  const std::size_t m = t.header.size();
  t.rows.reserve(records.size() - 1);
  t.row_line.reserve(records.size() - 1);
  for (std::size_t i = 1; i < records.size(); ++i) {
    Record& r = records[i];
    if (r.fields.size() != m) {
      std::string hint = "every row needs one value per header column";
      if (r.fields.size() == 1 && r.fields[0].empty()) hint = "empty line inside the table";
      else if (r.fields.size() > m) hint += "; quote text containing commas: \"a, b\"";
      throw InputError(at_line(source, r.line), std::to_string(r.fields.size()) + " fields",
                       "row has " + std::to_string(r.fields.size()) + " fields but the header has " +
                           std::to_string(m),
                       hint);
    }
    t.rows.push_back(std::move(r.fields));
    t.row_line.push_back(r.line);
  }
  return t;
}

CsvTable read_csv_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "", "is a directory, not a CSV file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open file for reading", "check the path");
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "read error");
  return parse_csv(buf.str(), path);
}

std::string csv_quote(std::string_view cell) {
  bool need = cell.find_first_of(",\"\r\n") != std::string_view::npos ||
              (!cell.empty() && (cell.front() == ' ' || cell.back() == ' '));
  if (!need) return std::string(cell);
  std::string s = "\"";
  for (char c : cell) {
    if (c == '"') s += '"';
    s += c;
  }
  s += '"';
  return s;
}

}  // namespace mh
