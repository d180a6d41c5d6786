#pragma once
// The per-case tables of `run`: cases.csv (one row per case), ellipses.csv (one row per loaded
// ellipse), pressure.csv (pressure grids) and the case records of results.json. One function
// formats one case into strings, so that cases can be formatted in parallel and written in order.
#include <cstdint>
#include <string>
#include <vector>

#include "contact/multi_hertz/multi_hertz.hpp"
#include "input/case_file.hpp"

namespace mh {

/// One case's rows, formatted.
struct Formatted {
  std::string cases, ellipses, patches, json, pressure, strips;
};

/// Format case `idx` (its sweep point `cp`, its result `r`) into f.cases/f.ellipses (CSV rows)
/// and/or f.json (its record in results.json's "cases" array: one line of JSON). `status_text`
/// overrides the solver's status (a batch's `invalid_pair`); default: to_string(r.status).
/// True for a row without a solution (out_of_range, no_contact, or a status_text such as
/// invalid_pair): its result fields are written empty in CSV and null in JSON.
bool is_failed_row(const CaseResult& r, const char* status_text = nullptr);

void format_case(std::uint64_t idx, const CasePoint& cp, const CaseResult& r,
                 bool plastic, bool want_csv, bool want_json, Formatted& f,
                 const char* status_text = nullptr, const RcfOptions& rcf = {}, bool tangential = false);

/// The pressure of each loaded ellipse of `r` on an N × N grid over its patch (method.md §5),
/// into `s` (pressure.csv rows). `tangential` (friction given): the rows end with the traction
/// columns px_MPa, py_MPa, slip (docs/outputs.md), from r.ellipse_traction (empty cells where it
/// was not kept: TangentialOptions::keep_traction).
void format_pressure(std::uint64_t idx, const CaseResult& r, bool plastic, int N,
                     std::string& s, bool tangential = false);

/// patches.csv rows of a grid method's case (one row per contact patch), into `s`.
/// With rcf.enabled() (k resolved: rcf_shear_yield) both tables end with the RCF columns
/// (docs/outputs.md "RCF columns").
/// With `tangential` (friction given) every per-contact and per-case table ends with the
/// tangential columns (docs/tangential.md).
void format_patches(std::uint64_t idx, const CasePoint& cp, const CaseResult& r, bool plastic, std::string& s,
                    const RcfOptions& rcf = {}, bool tangential = false);
/// The element pressures of every patch of a grid method's case (elements in contact only), into
/// `s` (pressure.csv rows of the grid methods). `tangential`: with the traction columns, from
/// each PatchResult::traction where kept (then on its grid: strips' rows exist only there).
void format_patch_pressure(std::uint64_t idx, const CaseResult& r, std::string& s, bool tangential = false);

/// strips.csv rows of a strip-method case (one row per loaded strip), into `s`.
void format_strips(std::uint64_t idx, const CasePoint& cp, const CaseResult& r, std::string& s);
std::string strips_csv_header();

/// The column names of the tables (docs/outputs.md).
std::string patches_csv_header(bool plastic, bool rcf = false, bool tangential = false, bool subsurface = false);
/// Which per-contact tables a method writes: ellipses.csv (multi-Hertzian, and "auto" for the cases
/// it keeps), patches.csv (grid methods, and "auto" for the cases it hands to the strip method).
bool writes_ellipses(Method m);
bool writes_patches(Method m);
/// The header of pressure.csv of a method ("auto" writes none).
std::string pressure_table_header(Method m, bool plastic, bool tangential = false);
std::string patch_pressure_csv_header(bool tangential = false);
std::string cases_csv_header(bool tangential = false, bool rcf = false);
std::string ellipses_csv_header(bool plastic, bool rcf = false, bool tangential = false, bool subsurface = false);

/// geometry.csv: what ellipses.csv would repeat for every Q, once per (t_Y,
/// potential ellipse). Its header, and the rows of the candidates `cands` at the case t_Y `tY_mm`
/// (as given: written exactly as in ellipses.csv, so the tables join on the text of tY_mm and
/// ellipse) into `csv`, and/or one JSON record per candidate (results.json "geometry") into `json`.
/// λ, m, n of a candidate without a Hertz ellipse are empty (null in JSON).
std::string geometry_csv_header();
void format_geometry(double tY_mm, const std::vector<CandidateEllipse>& cands, bool want_csv, bool want_json,
                     std::string& csv, std::vector<std::string>* json);
std::string pressure_csv_header(bool plastic, bool tangential = false);

}  // namespace mh
