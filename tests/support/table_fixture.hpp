#pragma once
// A contact table made in a test from a case file of tests/data/tables (docs/tables.md): the case,
// its pair's geometry and the made table, with the maker's options of the tests (two threads,
// quiet, default tolerances and refinement).
#include <sstream>
#include <string>

#include "input/case_file.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/run.hpp"

namespace mh::test {

/// Made in place (the pair's geometry is not moved): `name` a file of tests/data/tables, e.g.
/// `const TestTable t("worn-table.json");`, or a path from the source tree's root with a '/'
/// (`"cases/s1002-60e1-roll-table.json"`).
struct TestTable {
  explicit TestTable(const std::string& name)
      : cf(load_case_file(std::string(MHCONTACT_SOURCE_DIR) +
                              (name.find('/') == std::string::npos ? "/tests/data/tables/" : "/") + name,
                          true)),
        pg(build_pair_geometry(cf)),
        made(make(cf, pg)) {}
  TestTable(const TestTable&) = delete;
  TestTable& operator=(const TestTable&) = delete;
  const CaseFile cf;
  const PairGeometry pg;
  const TableMade made;

 private:
  static TableMade make(const CaseFile& cf, const PairGeometry& pg) {
    TableMakeOptions opt;
    opt.threads = 2;
    opt.quiet = true;
    std::ostringstream err;
    return make_contact_table(cf, pg, opt, err);
  }
};

}  // namespace mh::test
