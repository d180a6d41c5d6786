// `mhcontact diff` and the library behind it: the strict CSV reader (csv_table.hpp) and the
// tolerance comparison of result tables (table_diff.hpp). Reference values are hand-computed
// from the tables written inline below; tolerances are checked just inside and just outside
// (by 10 % of the tolerance, far above the double rounding of |out - ref|, ~1e-16 relative).
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "output/csv_table.hpp"
#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "output/table_diff.hpp"

namespace {

using mh::CsvTable;
using mh::DiffOptions;
using mh::InputError;
using mh::TableDiffResult;

const std::string kData = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/diff/";

CsvTable T(const std::string& text, const std::string& name = "t.csv") {
  return mh::parse_csv(text, name);
}

TableDiffResult D(const std::string& ref, const std::string& out, const DiffOptions& opt = {}) {
  return mh::diff_tables(T(ref, "ref.csv"), T(out, "out.csv"), opt);
}

struct Cli {
  int code;
  std::string out, err;
};
Cli cli(std::vector<std::string> args) {
  std::ostringstream out, err;
  args.insert(args.begin(), "diff");
  int code = mh::run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

/// The `where` of the InputError thrown by f ("" if none is thrown).
template <class F>
std::string where_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.where();
  }
  return "";
}

const mh::ColumnDiff* column(const TableDiffResult& r, const std::string& name) {
  for (const auto& c : r.columns)
    if (c.column == name) return &c;
  return nullptr;
}

const char* const kCases =
    "case,Q_kN,status,dz_mm,Fz_kN,message\n"
    "c1,100,ok,0.0812345678901,100,\n"
    "c2,100,ok,0.0901,100,\"two patches, flange and tread\"\n"
    "c3,100,no_contact,nan,0,\"no contact found for tY=5 mm\"\n";

}  // namespace

// ------------------------------------------------------------------------------------------
// CSV reader
// ------------------------------------------------------------------------------------------

TEST_CASE("csv: quoted fields keep commas, doubled quotes and line breaks", "[diff][csv]") {
  const CsvTable t = T("\xEF\xBB\xBF" "case,warnings,message\r\n"
                       "c1,\"near flange, check\",\"say \"\"hi\"\"\"\r\n"
                       "c2,,\"two\nlines\"\n"
                       "c3,x,\n");
  REQUIRE(t.header == std::vector<std::string>{"case", "warnings", "message"});
  REQUIRE(t.rows.size() == 3);
  CHECK(t.rows[0][1] == "near flange, check");
  CHECK(t.rows[0][2] == "say \"hi\"");
  CHECK(t.rows[1][1].empty());
  CHECK(t.rows[1][2] == "two\nlines");
  CHECK(t.rows[2][2].empty());
  // Line numbers are where each record starts (c2's message spans lines 3-4).
  CHECK(t.row_line == std::vector<std::size_t>{2, 3, 5});
  CHECK(t.column("message") == 2);
  CHECK(t.column("nope") == -1);
}

TEST_CASE("csv: no final newline, trailing empty lines ignored", "[diff][csv]") {
  CHECK(T("a,b\n1,2").rows.size() == 1);
  CHECK(T("a,b\n1,2\n\n\n").rows.size() == 1);
  CHECK(T("a,b\n").rows.empty());
  CHECK(T("a,b\n1,\n").rows[0][1].empty());  // an empty last field is a field
}

TEST_CASE("csv: malformed input names file and line", "[diff][csv]") {
  struct Bad {
    const char* text;
    const char* where;
  };
  const Bad bad[] = {
      {"a,b\n1,2\n1,2,3\n", "t.csv:3"},            // ragged: too many fields
      {"a,b\n1,2\n1\n", "t.csv:3"},                // ragged: too few
      {"a,b\n1,2\n\n3,4\n", "t.csv:3"},            // empty line inside the table
      {"a,b\n1,\"x\n\ny\n", "t.csv:2"},           // quote never closed: line where it opens
      {"a,b\n1,x\"y\"\n", "t.csv:2"},             // quote inside an unquoted field
      {"a,b\n1,\"x\"y\n", "t.csv:2"},             // text after a closing quote
      {"a,b\r1,2\n", "t.csv:1"},                  // bare CR
      {"a,a\n1,2\n", "t.csv:1"},                  // duplicate column name
      {"a,,c\n1,2,3\n", "t.csv:1"},               // empty column name
      {"", "t.csv"},                              // no header
      {"\n\n", "t.csv"},
  };
  for (const Bad& b : bad) {
    INFO(b.text);
    CHECK(where_of([&] { T(b.text); }) == b.where);
  }
}

TEST_CASE("csv: ragged file and missing file through read_csv_file", "[diff][csv]") {
  CHECK(where_of([] { mh::read_csv_file(kData + "ragged.csv"); }) == kData + "ragged.csv:3");
  CHECK(where_of([] { mh::read_csv_file(kData + "no_such_file.csv"); }) ==
        kData + "no_such_file.csv");
  CHECK(where_of([] { mh::read_csv_file(kData + "cases_ref.csv"); }).empty());
}

TEST_CASE("csv: csv_quote round-trips through the reader", "[diff][csv]") {
  const std::vector<std::string> cells{"plain", "a, b", "say \"hi\"", "two\nlines", " padded ", ""};
  std::string text = "c0,c1,c2,c3,c4,c5\n";
  for (std::size_t i = 0; i < cells.size(); ++i) text += (i ? "," : "") + mh::csv_quote(cells[i]);
  text += "\n";
  CHECK(T(text).rows.at(0) == cells);
}

// ------------------------------------------------------------------------------------------
// Numbers in cells
// ------------------------------------------------------------------------------------------

TEST_CASE("diff: what counts as a number", "[diff]") {
  struct Num {
    const char* text;
    bool is_number;
    double value;  // NaN: expect NaN
  };
  const double nan = std::nan("");
  const Num nums[] = {
      {"1", true, 1.0},           {"-2.5e-3", true, -2.5e-3},  {"+3", true, 3.0},
      {"0.1", true, 0.1},         {"nan", true, nan},          {"NaN", true, nan},
      {"-nan", true, nan},        {"inf", true, HUGE_VAL},     {"-inf", true, -HUGE_VAL},
      {"Infinity", true, HUGE_VAL},
      {"", false, 0},             {" 1", false, 0},            {"1 ", false, 0},
      {"1,0", false, 0},          {"abc", false, 0},           {"1e", false, 0},
      {".", false, 0},            {"0x10", false, 0},          {"+", false, 0},
      {"ok", false, 0},
  };
  for (const Num& n : nums) {
    INFO(n.text);
    double v = 0;
    REQUIRE(mh::parse_cell_number(n.text, v) == n.is_number);
    if (!n.is_number) continue;
    if (std::isnan(n.value)) CHECK(std::isnan(v));
    else CHECK(v == n.value);  // exact: from_chars is correctly rounded
  }
}

// ------------------------------------------------------------------------------------------
// Comparison
// ------------------------------------------------------------------------------------------

TEST_CASE("diff: identical tables are OK", "[diff]") {
  const TableDiffResult r = D(kCases, kCases);
  CHECK(r.ok());
  CHECK(r.key_columns == std::vector<std::string>{"case"});
  CHECK(r.rows_compared == 3);
  CHECK(r.cells_compared == 3 * 5);
  CHECK(r.columns.empty());
  CHECK(mh::diff_summary_line(r) == "diff: OK");
}

TEST_CASE("diff: reordered rows and columns are OK", "[diff]") {
  const char* reordered =
      "message,Fz_kN,case,dz_mm,status,Q_kN\n"
      "\"no contact found for tY=5 mm\",0,c3,nan,no_contact,100\n"
      ",100,c1,0.0812345678901,ok,100\n"
      "\"two patches, flange and tread\",100,c2,0.0901,ok,100\n";
  const TableDiffResult r = D(kCases, reordered);
  CHECK(r.ok());
  CHECK(r.rows_compared == 3);
}

TEST_CASE("diff: absolute tolerance, just inside and just outside", "[diff]") {
  // |out - ref| <= atol with rtol = 0; atol = 1e-3 mm: 0.9e-3 passes, 1.1e-3 fails.
  DiffOptions opt;
  opt.rtol = 0;
  opt.atol = 1e-3;
  const char* ref = "case,dz_mm\nc1,0.5\nc2,0\n";
  CHECK(D(ref, "case,dz_mm\nc1,0.5009\nc2,-0.0009\n", opt).ok());
  const TableDiffResult r = D(ref, "case,dz_mm\nc1,0.5011\nc2,0.00105\n", opt);
  CHECK_FALSE(r.ok());
  CHECK(r.cells_out == 2);
  const auto* c = column(r, "dz_mm");
  REQUIRE(c);
  CHECK(c->cells_out == 2);
  CHECK(c->worst_abs == Approx(1.1e-3).margin(1e-15));  // 0.5011 - 0.5 in doubles
  CHECK(c->worst_abs_at.key == "case=c1");
  // ref = 0: the relative deviation is infinite and reported at c2.
  CHECK(std::isinf(c->worst_rel));
  CHECK(c->worst_rel_at.key == "case=c2");
  CHECK(mh::diff_summary_line(r) == "diff: 2 cells out of tolerance, 0 missing rows, 0 extra rows");
}

TEST_CASE("diff: relative tolerance, just inside and just outside", "[diff]") {
  // rtol = 1e-6 at ref 200 kN: tolerance 2e-4 kN. 1.9e-4 passes, 2.1e-4 fails.
  DiffOptions opt;
  opt.rtol = 1e-6;
  const char* ref = "case,Fz_kN\nc1,200\nc2,-200\n";
  CHECK(D(ref, "case,Fz_kN\nc1,200.00019\nc2,-199.99981\n", opt).ok());
  const TableDiffResult r = D(ref, "case,Fz_kN\nc1,200.00021\nc2,-200\n", opt);
  CHECK(r.cells_out == 1);
  const auto* c = column(r, "Fz_kN");
  REQUIRE(c);
  CHECK(c->worst_rel == Approx(1.05e-6).epsilon(1e-9));
  CHECK(c->worst_rel_at.ref == "200");
  CHECK(c->worst_rel_at.out == "200.00021");

  // Default rtol = 1e-9 (atol 0): a relative change of 0.5e-9 passes, 2e-9 fails.
  const double dz = 0.0812345678901;
  auto table = [](double v) { return "case,dz_mm\nc1," + mh::format_number(v) + "\n"; };
  CHECK(D(table(dz), table(dz * (1 + 0.5e-9))).ok());
  CHECK_FALSE(D(table(dz), table(dz * (1 + 2e-9))).ok());
}

TEST_CASE("diff: column tolerance replaces atol and rtol for its column", "[diff]") {
  const char* ref = "case,Fz_kN,Fy_kN\nc1,100,-2.5\n";
  DiffOptions opt;
  opt.rtol = 0;
  opt.column_tol["Fz_kN"] = 1e-3;  // kN
  CHECK(D(ref, "case,Fz_kN,Fy_kN\nc1,100.0009,-2.5\n", opt).ok());
  CHECK_FALSE(D(ref, "case,Fz_kN,Fy_kN\nc1,100.0011,-2.5\n", opt).ok());
  // Other columns keep atol/rtol: Fy_kN must still be exact with rtol = 0.
  CHECK_FALSE(D(ref, "case,Fz_kN,Fy_kN\nc1,100,-2.5000001\n", opt).ok());
  // Replaces, not adds to: rtol 1e-3 alone would allow 0.1 kN at 100 kN, the column tol does not.
  opt.rtol = 1e-3;
  opt.column_tol["Fz_kN"] = 1e-4;
  const TableDiffResult r = D(ref, "case,Fz_kN,Fy_kN\nc1,100.001,-2.5\n", opt);
  CHECK_FALSE(r.ok());
  REQUIRE(column(r, "Fz_kN"));
  CHECK(column(r, "Fz_kN")->tolerance_abs == 1e-4);
}

TEST_CASE("diff: missing and extra rows are listed by key", "[diff]") {
  const char* out =
      "case,Q_kN,status,dz_mm,Fz_kN,message\n"
      "c1,100,ok,0.0812345678901,100,\n"
      "c4,100,ok,0.05,50,\n"
      "c5,100,ok,0.05,50,\n";
  const TableDiffResult r = D(kCases, out);
  CHECK_FALSE(r.ok());
  CHECK(r.rows_compared == 1);
  CHECK(r.missing_rows == std::vector<std::string>{"case=c2", "case=c3"});
  CHECK(r.extra_rows == std::vector<std::string>{"case=c4", "case=c5"});
  CHECK(r.cells_out == 0);
  CHECK(mh::diff_summary_line(r) == "diff: 0 cells out of tolerance, 2 missing rows, 2 extra rows");
  std::ostringstream os;
  DiffOptions opt;
  opt.max_listed = 1;
  mh::write_diff_report(os, r, opt);
  CHECK_THAT(os.str(), Catch::Contains("rows missing in OUT (2): case=c2; ... and 1 more"));
  CHECK_THAT(os.str(), Catch::Contains("rows extra in OUT (2): case=c4; ... and 1 more"));
}

TEST_CASE("diff: text cells must be equal", "[diff]") {
  std::string out = kCases;
  out.replace(out.find("c2,100,ok"), 9, "c2,100,max_iterations");
  const TableDiffResult r = D(kCases, out);
  CHECK(r.cells_out == 1);
  const auto* c = column(r, "status");
  REQUIRE(c);
  CHECK(c->text_out == 1);
  CHECK(c->first_text.key == "case=c2");
  CHECK(c->first_text.ref == "ok");
  CHECK(c->first_text.out == "max_iterations");
  // A quoted message with a comma that changes by one character.
  std::string out2 = kCases;
  out2.replace(out2.find("flange and tread"), 16, "flange and Tread");
  CHECK(D(kCases, out2).cells_out == 1);
  // An empty cell against a number is a text difference, not a numeric one.
  const TableDiffResult e = D("case,x_mm\nc1,\n", "case,x_mm\nc1,0\n");
  REQUIRE(column(e, "x_mm"));
  CHECK(column(e, "x_mm")->text_out == 1);
}

TEST_CASE("diff: NaN equals NaN, NaN against a number differs, infinities", "[diff]") {
  const char* ref = "case,dz_mm\nc1,nan\nc2,inf\nc3,0\n";
  DiffOptions loose;
  loose.atol = 1e300;  // even a huge tolerance does not make NaN or inf equal a number
  CHECK(D(ref, "case,dz_mm\nc1,NaN\nc2,Infinity\nc3,-0\n", loose).ok());
  const TableDiffResult r = D(ref, "case,dz_mm\nc1,0.07\nc2,1e308\nc3,nan\n", loose);
  CHECK(r.cells_out == 3);
  const auto* c = column(r, "dz_mm");
  REQUIRE(c);
  CHECK(c->nonfinite_out == 3);
  CHECK(c->first_nonfinite.key == "case=c1");
  CHECK(c->worst_abs == 0);  // no finite difference to report
  CHECK_FALSE(D(ref, "case,dz_mm\nc1,nan\nc2,-inf\nc3,0\n").ok());
}

TEST_CASE("diff: default keys, row-number mode and --key", "[diff]") {
  // pair and case in front: key pair,case.
  const TableDiffResult pc = D("pair,case,Fz_kN\nA,c1,1\nB,c1,2\n", "pair,case,Fz_kN\nB,c1,2\nA,c1,1\n");
  CHECK(pc.key_columns == std::vector<std::string>{"pair", "case"});
  CHECK(pc.ok());
  // ellipses.csv: key case,ellipse.
  const TableDiffResult ce = D("case,ellipse,a_mm\nc1,1,6\nc1,2,3\n", "case,ellipse,a_mm\nc1,2,3\nc1,1,6\n");
  CHECK(ce.key_columns == std::vector<std::string>{"case", "ellipse"});
  CHECK(ce.ok());
  // A key column in only one table is not a default key.
  CHECK(D("pair,case,x\nA,c1,1\n", "case,x\nc1,1\n").key_columns == std::vector<std::string>{"case"});
  // None of pair/case/ellipse: rows compared by position, the row number is the key.
  const TableDiffResult rn = D("tY_mm,caf_deg\n0,1\n2.5,2\n5,3\n", "tY_mm,caf_deg\n0,1\n2.5,2.5\n");
  CHECK(rn.by_row_number);
  CHECK(rn.missing_rows == std::vector<std::string>{"row=3"});
  REQUIRE(column(rn, "caf_deg"));
  CHECK(column(rn, "caf_deg")->worst_abs_at.key == "row=2");
  std::ostringstream os;
  mh::write_diff_report(os, rn, {});
  CHECK_THAT(os.str(), Catch::Contains("rows compared by position"));
  // --key tY_mm: numeric keys are exact text, "5" and "5.0" are different rows.
  DiffOptions k;
  k.key = {"tY_mm"};
  const TableDiffResult ty = D("tY_mm,caf_deg\n0,1\n5,3\n", "tY_mm,caf_deg\n0,1\n5.0,3\n", k);
  CHECK(ty.missing_rows == std::vector<std::string>{"tY_mm=5"});
  CHECK(ty.extra_rows == std::vector<std::string>{"tY_mm=5.0"});
}

TEST_CASE("diff: duplicate keys are input errors naming file and line", "[diff]") {
  CHECK(where_of([] { D("case,x\nc1,1\nc2,2\nc1,3\n", "case,x\nc1,1\n"); }) == "ref.csv:4");
  CHECK(where_of([] { D("case,x\nc1,1\n", "case,x\nc1,1\nc1,1\n"); }) == "out.csv:3");
  // caf.csv-like: the key `ellipse` alone repeats; --key tY_mm resolves it.
  const char* caf = "tY_mm,y_rail_mm,ellipse\n0,-1.25,1\n2.5,2.1,1\n";
  DiffOptions ke;
  ke.key = {"ellipse"};
  CHECK(where_of([&] { D(caf, caf, ke); }) == "ref.csv:3");
  DiffOptions k;
  k.key = {"tY_mm"};
  CHECK(D(caf, caf, k).ok());
}

TEST_CASE("diff: without a case column, tY_mm joins the default key (geometry.csv, caf.csv)", "[diff]") {
  const char* geo = "tY_mm,ellipse,gamma_deg\n0,1,1.4\n0,2,20\n0.5,1,1.5\n0.5,2,21\n";
  const TableDiffResult r = D(geo, "tY_mm,ellipse,gamma_deg\n0,1,1.4\n0,2,20\n0.5,2,21\n0.5,1,1.5\n");
  CHECK(r.key_columns == std::vector<std::string>{"tY_mm", "ellipse"});
  CHECK(r.ok());
  const char* batch = "pair,tY_mm,ellipse,gamma_deg\n0,0,1,1.4\n1,0,1,1.6\n";
  CHECK(D(batch, batch).key_columns == std::vector<std::string>{"pair", "tY_mm", "ellipse"});
  // With a case column the key stays case, ellipse (ellipses.csv: tY_mm is a value of the case).
  CHECK(D("case,tY_mm,ellipse,x\n0,0,1,1\n", "case,tY_mm,ellipse,x\n0,0,1,1\n").key_columns ==
        std::vector<std::string>{"case", "ellipse"});
}

TEST_CASE("diff: missing and extra columns make the tables differ", "[diff]") {
  const TableDiffResult r = D("case,a_mm,b_mm\nc1,1,2\n", "case,b_mm,p0_MPa\nc1,2,900\n");
  CHECK_FALSE(r.ok());
  CHECK(r.missing_columns == std::vector<std::string>{"a_mm"});
  CHECK(r.extra_columns == std::vector<std::string>{"p0_MPa"});
  CHECK(r.cells_compared == 1);  // b_mm only
  CHECK(mh::diff_summary_line(r) ==
        "diff: 0 cells out of tolerance, 0 missing rows, 0 extra rows, 1 missing columns, 1 extra columns");
}

TEST_CASE("diff: invalid options are input errors", "[diff]") {
  const char* t = "case,Fz_kN\nc1,1\n";
  DiffOptions o;
  o.column_tol["nope"] = 1;
  CHECK(where_of([&] { D(t, t, o); }) == "--column-tol");
  o.column_tol = {{"case", 1.0}};  // a key column
  CHECK(where_of([&] { D(t, t, o); }) == "--column-tol");
  o.column_tol = {{"Fz_kN", -1.0}};
  std::string why;
  CHECK_FALSE(o.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("Fz_kN"));
  CHECK(where_of([&] { D(t, t, o); }) == "diff options");
  DiffOptions k;
  k.key = {"tY_mm"};
  CHECK(where_of([&] { D(t, t, k); }) == "ref.csv");
  DiffOptions r;
  r.rtol = std::nan("");
  CHECK_FALSE(r.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("rtol"));
}

// ------------------------------------------------------------------------------------------
// Command line (run_cli), on the files in tests/data/diff
// ------------------------------------------------------------------------------------------

TEST_CASE("diff cli: exit codes 0, 1, 2", "[diff][cli]") {
  const std::string ref = kData + "cases_ref.csv";
  CHECK(cli({ref, ref}).code == 0);
  Cli same = cli({ref, kData + "cases_reordered.csv"});
  CHECK(same.code == 0);
  CHECK_THAT(same.out, Catch::EndsWith("diff: OK\n"));

  Cli changed = cli({ref, kData + "cases_changed.csv"});
  CHECK(changed.code == 1);
  CHECK_THAT(changed.out, Catch::Contains("rows missing in OUT (1): case=c4"));
  CHECK_THAT(changed.out, Catch::Contains("rows extra in OUT (1): case=c5"));
  CHECK_THAT(changed.out, Catch::Contains("column status: 1 of 3 cells out of tolerance"));
  CHECK_THAT(changed.out, Catch::Contains("worst abs deviation 0.002 at case=c1: ref 100, out 100.002"));
  CHECK_THAT(changed.out, Catch::Contains("first at case=c3: ref nan, out 0.07"));
  CHECK_THAT(changed.out,
             Catch::EndsWith("diff: 4 cells out of tolerance, 1 missing rows, 1 extra rows\n"));

  Cli quiet = cli({ref, kData + "cases_changed.csv", "--quiet"});
  CHECK(quiet.code == 1);
  CHECK(quiet.out == "diff: 4 cells out of tolerance, 1 missing rows, 1 extra rows\n");

  // Column tolerances for the two drifting numeric columns leave the text and NaN differences.
  Cli tol = cli({"--column-tol", "Fz_kN=0.01", "--column-tol", "dz_mm=1e-9", ref,
                 kData + "cases_changed.csv", "--quiet"});
  CHECK(tol.code == 1);
  CHECK(tol.out == "diff: 2 cells out of tolerance, 1 missing rows, 1 extra rows\n");

  Cli ell = cli({kData + "ellipses_ref.csv", kData + "ellipses_out.csv", "--column-tol", "p0_MPa=0.5"});
  CHECK(ell.code == 0);
  CHECK_THAT(ell.out, Catch::Contains("key: case, ellipse"));
  Cli ell_rtol = cli({kData + "ellipses_ref.csv", kData + "ellipses_out.csv", "--rtol", "1e-4"});
  CHECK(ell_rtol.code == 1);  // 0.4/1650 = 2.4e-4 > 1e-4
  CHECK(cli({kData + "ellipses_ref.csv", kData + "ellipses_out.csv", "--rtol", "3e-4"}).code == 0);
  CHECK(cli({kData + "ellipses_ref.csv", kData + "ellipses_out.csv", "--atol", "0.5"}).code == 0);
}

TEST_CASE("diff cli: bad input exits 2 naming file, line or option", "[diff][cli]") {
  const std::string ref = kData + "cases_ref.csv";
  struct Bad {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Bad> bad = {
      {{ref, kData + "ragged.csv"}, kData + "ragged.csv:3: value 12 fields"},
      {{kData + "missing.csv", ref}, kData + "missing.csv: cannot open file"},
      {{kData + "dupkey.csv", ref}, kData + "dupkey.csv:4: value case=c1: duplicate key"},
      {{ref, ref, "--column-tol", "Fz_kN:1e-3"}, "--column-tol: value \"Fz_kN:1e-3\": expected COL=TOL"},
      {{ref, ref, "--column-tol", "Fz_kN="}, "expected COL=TOL"},
      {{ref, ref, "--column-tol", "=1"}, "expected COL=TOL"},
      {{ref, ref, "--column-tol", "Fz_kN=abc"}, "not a number"},
      {{ref, ref, "--column-tol", "Fz_kN=-1"}, "must be finite and >= 0"},
      {{ref, ref, "--column-tol", "Fz_kN=1", "--column-tol", "Fz_kN=2"}, "column given twice"},
      {{ref, ref, "--column-tol", "F_kN=1"}, "F_kN: not a column"},
      {{ref, ref, "--rtol", "-1e-9"}, "--rtol: value -1e-9"},
      {{ref, ref, "--atol", "inf"}, "--atol: value inf"},
      {{ref, ref, "--key", "pair"}, "pair: key column is not in the header"},
      {{kData + "caf_ref.csv", kData + "caf_out.csv", "--key", "ellipse"}, "caf_ref.csv:3: value ellipse=1: duplicate key"},
  };
  for (const Bad& b : bad) {
    INFO(b.args.back());
    Cli r = cli(b.args);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Catch::Contains(b.message));
  }
}

TEST_CASE("diff cli: --key for caf.csv, numeric keys as exact text", "[diff][cli]") {
  Cli r = cli({kData + "caf_ref.csv", kData + "caf_out.csv", "--key", "tY_mm"});
  CHECK(r.code == 1);
  CHECK_THAT(r.out, Catch::Contains("rows missing in OUT (1): tY_mm=5"));
  CHECK_THAT(r.out, Catch::Contains("rows extra in OUT (1): tY_mm=5.0"));
  CHECK(cli({kData + "caf_ref.csv", kData + "caf_ref.csv", "--key", "tY_mm,ellipse"}).code == 0);
}

TEST_CASE("diff cli: --json report", "[diff][cli]") {
  Cli r = cli({kData + "cases_ref.csv", kData + "cases_changed.csv", "--json"});
  CHECK(r.code == 1);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j.at("schema") == "mhcontact.diff");
  CHECK(j.at("version") == 1);
  CHECK(j.at("ok") == false);
  CHECK(j.at("key") == nlohmann::json{"case"});
  CHECK(j.at("missing_rows") == nlohmann::json{"case=c4"});
  CHECK(j.at("extra_rows") == nlohmann::json{"case=c5"});
  CHECK(j.at("cells_out_of_tolerance") == 4);
  CHECK(j.at("tolerance").at("rtol") == 1e-9);
  bool found = false;
  for (const auto& c : j.at("columns")) {
    if (c.at("column") != "Fz_kN") continue;
    found = true;
    CHECK(c.at("worst_abs").at("key") == "case=c1");
    CHECK(c.at("worst_abs").at("deviation").get<double>() == Approx(0.002).margin(1e-12));
  }
  CHECK(found);
  CHECK(j.at("summary") == "diff: 4 cells out of tolerance, 1 missing rows, 1 extra rows");
}

// ------------------------------------------------------------------------------------------
// --ignore-columns, and warnings compared by their names with the numbers inside
// within tolerance
// ------------------------------------------------------------------------------------------

TEST_CASE("diff: text cells split into words and numbers", "[diff][text]") {
  const auto P = mh::detail::split_text_cell("non_hertzian:ellipse=2:gap_error=0.525>0.5;edge_gap_mm=-0.049<8");
  std::vector<std::string> text;
  std::vector<int> kind;  // 0 word, 1 integer, 2 decimal
  for (const auto& p : P) {
    text.push_back(p.text);
    kind.push_back(!p.number ? 0 : p.integer ? 1 : 2);
  }
  CHECK(text == std::vector<std::string>{"non_hertzian:ellipse=", "2", ":gap_error=", "0.525", ">", "0.5",
                                         ";edge_gap_mm=", "-0.049", "<", "8"});
  CHECK(kind == std::vector<int>{0, 1, 0, 2, 0, 2, 0, 2, 0, 1});
  // Digits inside a name stay in the word; an exponent belongs to the number; '+' between two
  // integers is a word.
  const auto Q = mh::detail::split_text_cell("p0_MPa=1.5e-05 R13 ellipses=1+2");
  REQUIRE(Q.size() == 6);
  CHECK(Q[0].text == "p0_MPa=");
  CHECK(Q[1].text == "1.5e-05");
  CHECK(Q[1].value == 1.5e-05);
  CHECK(Q[2].text == " R13 ellipses=");
  CHECK(Q[3].text == "1");
  CHECK(Q[4].text == "+");
  CHECK(Q[5].text == "2");
}

TEST_CASE("diff: warnings compared by their names, decimal numbers with the tolerance", "[diff][text]") {
  const char* ref = "case,status,warnings,message\n"
                    "0,outside_validity,non_hertzian:ellipse=2:gap_error=0.525>0.5,relative residual 1.2e-05\n";
  const auto out = [](const std::string& w, const std::string& m = "relative residual 1.2e-05") {
    return "case,status,warnings,message\n0,outside_validity," + w + "," + m + "\n";
  };
  DiffOptions loose;
  loose.rtol = 1e-2;
  // The pair: 0.525 against 0.527 is 0.4 %: within 1e-2, beyond the default 1e-9.
  CHECK(D(ref, out("non_hertzian:ellipse=2:gap_error=0.527>0.5"), loose).ok());
  const TableDiffResult strict = D(ref, out("non_hertzian:ellipse=2:gap_error=0.527>0.5"));
  CHECK(strict.cells_out == 1);
  REQUIRE(column(strict, "warnings"));
  CHECK(column(strict, "warnings")->text_out == 1);
  CHECK(D(ref, out("non_hertzian:ellipse=2:gap_error=0.54>0.5"), loose).cells_out == 1);  // 2.9 %
  // Numbers inside a message too.
  CHECK(D(ref, out("non_hertzian:ellipse=2:gap_error=0.525>0.5", "relative residual 1.21e-05"), loose).ok());
  // Names, classes and integers (indices, counts) must be equal whatever the tolerance.
  DiffOptions huge;
  huge.rtol = 10;
  CHECK(D(ref, out("non_hertzian:ellipse=3:gap_error=0.525>0.5"), huge).cells_out == 1);
  CHECK(D(ref, out("non_hertzian:ellipse=2:gap_mean_error=0.525>0.5"), huge).cells_out == 1);
  CHECK(D(ref, out("off_profile:ellipse=2:gap_error=0.525>0.5"), huge).cells_out == 1);
  CHECK(D(ref, out("non_hertzian:ellipse=2:gap_error=0.525>0.5;flange_climb:ellipse=4"), huge).cells_out == 1);
  CHECK(D(ref, out(""), huge).cells_out == 1);
  // A column tolerance applies to the numbers inside its cells (absolute, in the column's "unit").
  DiffOptions col;
  col.column_tol["warnings"] = 0.005;
  CHECK(D(ref, out("non_hertzian:ellipse=2:gap_error=0.529>0.5"), col).ok());
  CHECK_FALSE(D(ref, out("non_hertzian:ellipse=2:gap_error=0.531>0.5"), col).ok());
  // The status column has no numbers: exact.
  CHECK_FALSE(D(ref, "case,status,warnings,message\n0,ok,non_hertzian:ellipse=2:gap_error=0.525>0.5,"
                     "relative residual 1.2e-05\n", huge).ok());
}

TEST_CASE("diff: --ignore-columns leaves columns out of the comparison", "[diff][ignore]") {
  const char* ref = "case,residual,iterations,area_mm2\nc1,1e-16,3,56.8\nc2,0,2,113.9\n";
  const char* out = "case,residual,iterations,area_mm2\nc1,-2e-16,4,56.81\nc2,3e-17,2,113.9\n";
  DiffOptions o;
  o.rtol = 1e-2;
  CHECK(D(ref, out, o).ok());  // residual and iterations by their solver-noise rules
  o.noise_rules = false;       // --exact-noise
  const TableDiffResult all = D(ref, out, o);
  CHECK(all.cells_out == 3);  // residual twice (no atol), iterations once
  o.ignore_columns = {"residual", "iterations"};
  const TableDiffResult r = D(ref, out, o);
  CHECK(r.ok());
  CHECK(r.cells_compared == 2);  // area_mm2 only
  // An ignored column may be on one side only: not reported missing or extra.
  DiffOptions one;
  one.ignore_columns = {"extents"};
  CHECK(D("case,x\nc1,1\n", "case,x,extents\nc1,1,refined\n", one).ok());
  CHECK_FALSE(D("case,x\nc1,1\n", "case,x,extents\nc1,1,refined\n").ok());
  // Not a column, a key column, twice, with a tolerance too: input errors.
  DiffOptions bad;
  bad.ignore_columns = {"resid"};
  CHECK(where_of([&] { D(ref, out, bad); }) == "--ignore-columns");
  bad.ignore_columns = {"case"};
  CHECK(where_of([&] { D(ref, out, bad); }) == "--ignore-columns");
  bad.ignore_columns = {"residual", "residual"};
  CHECK(where_of([&] { D(ref, out, bad); }) == "diff options");
  bad.ignore_columns = {"residual"};
  bad.column_tol["residual"] = 1e-9;
  CHECK(where_of([&] { D(ref, out, bad); }) == "diff options");
}

TEST_CASE("diff: the solver-noise rules (issue 38: residual 1e-16 against 0 failed a --rtol 0.03 check)", "[diff][noise]") {
  const char* ref = "case,residual,iterations\nc1,0,3\nc2,1e-9,10\nc3,0,0\n";
  // Converged residuals and iteration counts within 2 ref + 3: equal by their rules.
  CHECK(D(ref, "case,residual,iterations\nc1,1e-16,9\nc2,-4e-7,23\nc3,0,3\n").ok());
  // An unconverged residual, a count above 2 ref + 3: out, whatever rtol says.
  DiffOptions loose;
  loose.rtol = 1e6;
  const TableDiffResult r = D(ref, "case,residual,iterations\nc1,2e-6,10\nc2,1e-9,24\nc3,0,4\n", loose);
  CHECK(r.cells_out == 4);  // c1's residual; iterations 10 > 9, 24 > 23, 4 > 3
  REQUIRE(r.columns.size() == 2);
  CHECK(r.columns[0].noise != nullptr);
  // A column tolerance replaces the rule.
  DiffOptions ct;
  ct.column_tol["residual"] = 0;
  CHECK(D(ref, "case,residual,iterations\nc1,1e-16,3\nc2,1e-9,10\nc3,0,0\n", ct).cells_out == 1);
}

TEST_CASE("diff cli: --ignore-columns in the report and in --json", "[diff][cli][ignore]") {
  const Cli a = cli({kData + "cases_ref.csv", kData + "cases_changed.csv", "--ignore-columns", "dz_mm,Fz_kN", "--ignore-columns", "status"});
  CHECK(a.code == 1);  // the missing and extra rows remain
  CHECK_THAT(a.out, Catch::Contains("ignored columns: dz_mm, Fz_kN, status\n"));
  CHECK_THAT(a.out, Catch::Contains("diff: 0 cells out of tolerance, 1 missing rows, 1 extra rows"));
  const Cli j = cli({kData + "cases_ref.csv", kData + "cases_ref.csv", "--ignore-columns", "Fz_kN", "--json"});
  CHECK(j.code == 0);
  CHECK(nlohmann::json::parse(j.out).at("ignored_columns") == nlohmann::json::array({"Fz_kN"}));
  const Cli e = cli({kData + "cases_ref.csv", kData + "cases_ref.csv", "--ignore-columns", "nope"});
  CHECK(e.code == 2);
  CHECK_THAT(e.err, Catch::Contains("--ignore-columns: value nope: not a column of"));
}
