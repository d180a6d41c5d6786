#pragma once
// The sinks the per-contact column writers write to (lib/output/case_tables.cpp,
// lib/output/rcf_columns.hpp): a CSV row, a CSV header, a JSON record. Internal to lib/output.
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "output/cells.hpp"
#include "output/json_record.hpp"

namespace mh {

// The columns of a contact written by field, in order, to a sink: one home for the names and
// the order of patches.csv and the "patches" records of results.json, and of the RCF columns of
// both per-contact tables. A sink has number(name, v) (as num() writes it in CSV; null in JSON when
// not finite), optional(name, v) (empty in CSV and null in JSON when v is not finite),
// integer(name, i) and text(name, t) (t null: empty in CSV, null in JSON).
struct CsvSink {
  std::string& s;
  void number(const char*, double v) { cells::cnum(s, v); }
  void optional(const char*, double v) { s += ','; if (std::isfinite(v)) cells::num(s, v); }
  void integer(const char*, long long i) { s += ','; append_number(s, i); }
  void text(const char*, const char* t) { s += ','; if (t) s += t; }
};
struct HeaderSink {
  std::string& s;
  void number(const char* n, double) { s += ','; s += n; }
  void optional(const char* n, double) { s += ','; s += n; }
  void integer(const char* n, long long) { s += ','; s += n; }
  void text(const char* n, const char*) { s += ','; s += n; }
};
struct JsonSink {
  JsonRecord& j;
  void number(const char* n, double v) { j.key(n); j.table_number(v); }
  void optional(const char* n, double v) { j.key(n); j.table_number(v); }
  void integer(const char* n, long long i) { j.key(n); j.integer(i); }
  void text(const char* n, const char* t) {
    j.key(n);
    if (t) j.string(t);
    else j.null();
  }
};


}  // namespace mh
