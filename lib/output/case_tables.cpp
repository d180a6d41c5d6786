// The per-case tables of `run` (cases.csv, ellipses.csv, pressure.csv) and the case records of
// results.json: column names and the formatting of one case's rows. The schema is documented in
// docs/outputs.md.
#include "output/case_tables.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "contact/judge/judge.hpp"
#include "contact/pressure_grid.hpp"
#include "core/units.hpp"
#include "output/case_sinks.hpp"
#include "output/cells.hpp"
#include "output/rcf_columns.hpp"

namespace mh {

using namespace cells;

namespace {

// Per-ellipse values in output units, in column order (shared by CSV and JSON): what depends on
// the load. What does not (the candidate's geometry at its t_Y) is in geometry.csv (kGeometryCols).
struct Col { const char* name; double (*get)(const LoadedEllipse&); };
const Col kEllipseCols[] = {
    {"h0_mm", [](const LoadedEllipse& e) { return e.s.h0 * units::per_mm; }},
    {"N_kN", [](const LoadedEllipse& e) { return e.s.N / units::kN; }},
    {"a_mm", [](const LoadedEllipse& e) { return e.s.a * units::per_mm; }},
    {"b_mm", [](const LoadedEllipse& e) { return e.s.b * units::per_mm; }},
    {"p0_MPa", [](const LoadedEllipse& e) { return e.s.p0 / units::MPa; }},
    {"pmean_MPa", [](const LoadedEllipse& e) { return e.s.p_mean / units::MPa; }},
    {"approach_mm", [](const LoadedEllipse& e) { return e.s.approach * units::per_mm; }},
};
// geometry.csv: one potential ellipse as a candidate at one t_Y, the same for
// every Q. `hertz`: the value exists only for a candidate with a Hertz ellipse (empty in CSV,
// null in JSON otherwise).
struct GeoCol { const char* name; double (*get)(const CandidateEllipse&); bool hertz = false; };
const GeoCol kGeometryCols[] = {
    {"y_rail_mm", [](const CandidateEllipse& e) { return e.g.y_r * units::per_mm; }},
    {"y_wheel_mm", [](const CandidateEllipse& e) { return e.g.y_w * units::per_mm; }},
    {"gamma_deg", [](const CandidateEllipse& e) { return e.g.gamma / units::deg; }},
    {"R_rxx_mm", [](const CandidateEllipse& e) { return radius_mm(e.g.k_rxx); }},
    {"R_wxx_mm", [](const CandidateEllipse& e) { return radius_mm(e.g.k_wxx); }},
    {"R_wyy_mm", [](const CandidateEllipse& e) { return e.g.R_wyy() * units::per_mm; }},
    {"A_per_mm", [](const CandidateEllipse& e) { return e.A * 1e-3; }},  // 1/m -> 1/mm, as `hertz --A`
    {"B_per_mm", [](const CandidateEllipse& e) { return e.B * 1e-3; }},
    {"lambda", [](const CandidateEllipse& e) { return e.c.lambda; }, true},
    {"m", [](const CandidateEllipse& e) { return e.c.m; }, true},
    {"n", [](const CandidateEllipse& e) { return e.c.n; }, true},
    {"gap_mm", [](const CandidateEllipse& e) { return e.g.gap * units::per_mm; }},
    {"z_rail_mm", [](const CandidateEllipse& e) { return e.z_r * 1e3; }},
    {"z_wheel_mm", [](const CandidateEllipse& e) { return e.z_w * 1e3; }},
};
const Col kPlasticCols[] = {
    {"h_y_mm", nullptr},  // filled from the law, see below
    {"p_max_MPa", [](const LoadedEllipse& e) { return e.s.p_max / units::MPa; }},
    {"plateau_a_mm", [](const LoadedEllipse& e) { return e.s.plateau_a * units::per_mm; }},
    {"plateau_b_mm", [](const LoadedEllipse& e) { return e.s.plateau_b * units::per_mm; }},
    {"a_el_mm", [](const LoadedEllipse& e) { return e.s.a_el * units::per_mm; }},
    {"b_el_mm", [](const LoadedEllipse& e) { return e.s.b_el * units::per_mm; }},
    {"area_ratio", [](const LoadedEllipse& e) { return e.s.area_ratio; }},
};
// Columns appended after all others (new columns are only ever appended: existing positions stay).
// hertz_valid is written as 1/0 (true/false in JSON), see below.
const Col kTailCols[] = {
    {"hertz_valid", nullptr},
    {"b_over_R", [](const LoadedEllipse& e) { return e.validity.b_over_R; }},
    {"gap_error", [](const LoadedEllipse& e) { return e.validity.gap_error; }},
    {"gap_mean_error", [](const LoadedEllipse& e) { return e.validity.gap_mean_error; }},
};
// Plastic mode only, appended after kTailCols: the elastic and the plastic
// patch side by side.
const Col kPlasticTailCols[] = {
    {"p0_el_MPa", [](const LoadedEllipse& e) { return e.s.p0_el / units::MPa; }},
    {"pmax_MPa", [](const LoadedEllipse& e) { return e.s.p_max / units::MPa; }},
    {"area_mm2", [](const LoadedEllipse& e) { return units::pi * e.s.a * e.s.b * units::per_mm2; }},
    {"area_el_mm2", [](const LoadedEllipse& e) { return units::pi * e.s.a_el * e.s.b_el * units::per_mm2; }},
};
// Appended last: the patch area (elastic mode only: the plastic tail already
// has area_mm2).
const Col kAreaCol = {"area_mm2", [](const LoadedEllipse& e) { return units::pi * e.s.a * e.s.b * units::per_mm2; }};

// One contact patch of a grid method, after its case, t_Y and Q (patches.csv) or in its case's
// record (results.json).
template <class Sink>
void patch_fields(Sink& k, const PatchResult& P, bool plastic, const RcfOptions& rcf, bool tangential) {
  k.integer("patch", static_cast<long long>(P.patch));
  k.number("y_rail_mm", P.y_r * units::per_mm);
  k.number("z_rail_mm", P.z_r * units::per_mm);
  k.number("y_wheel_mm", P.y_w * units::per_mm);
  k.number("gamma_deg", P.gamma / units::deg);
  k.number("N_kN", P.N / units::kN);
  k.number("pmax_MPa", P.pmax / units::MPa);
  k.number("area_mm2", P.area * units::per_mm2);
  k.number("length_x_mm", P.length_x * units::per_mm);
  k.number("width_s_mm", P.width_s * units::per_mm);
  k.number("approach_mm", P.approach * units::per_mm);
  k.number("x_centroid_mm", P.x_centroid * units::per_mm);
  k.number("s_centroid_mm", P.s_centroid * units::per_mm);
  k.integer("n_elements", static_cast<long long>(P.n_elements));
  k.integer("iterations", static_cast<long long>(P.iterations));
  // Strip method: which extents the patch kept, and the estimate's end-gap error (empty, null,
  // for the half-space method).
  const bool strips = std::isfinite(P.end_gap_error);
  k.text("extents", strips ? (P.refined ? "end_gap" : "estimate") : nullptr);
  k.optional("end_gap_error", P.end_gap_error);
  // The elements (strips) across the patch in its narrow direction and their size, smaller than
  // the method's where the patch was refined (grid_checks.hpp); before the optional blocks, which
  // end the table.
  k.integer("elements_across", static_cast<long long>(P.elements_across));
  k.number("element_mm", P.element * units::per_mm);
  if (plastic) {
    k.number("plastic_area_mm2", P.plastic_area * units::per_mm2);
    k.number("capped_load_kN", P.capped_load / units::kN);
  }
  if (rcf.enabled()) {
    rcf_fields(k, rcf, P.N, P.a_el, P.b_el, P.t, &P);  // the elastic Hertz ellipse of N (patch_elastic.hpp)
  }
  if (tangential) {
    tangential_fields(k, P.t);
    damage_fields(k, P.damage);
  }
}

// A grid point's traction cells (on the rail) [MPa] and its slip flag; empty cells where the case
// has creep forces but this point's contact kept no traction; nothing without creep forces.
void append_traction_cells(std::string& s, const GridPoint& g, bool tangential) {
  if (g.traction) {
    cnum(s, g.px / units::MPa);
    cnum(s, g.py / units::MPa);
    s += ','; s += g.slip ? '1' : '0';
  } else if (tangential) {
    s += ",,,";
  }
}

}  // namespace


// Pressure of each loaded ellipse on an N × N grid over its patch, with the traction where it was
// kept: the points of contact/pressure_grid.hpp (the C interface's mhc_result_grid gives the same).
void format_pressure(std::uint64_t idx, const CaseResult& r, bool plastic, int N,
                     std::string& s, bool tangential) {
  s.clear();
  for_each_ellipse_grid_point(r, plastic, N, tangential, [&](const GridPoint& g) {
    append_number(s, static_cast<long long>(idx));
    s += ','; append_number(s, static_cast<long long>(g.contact));
    cnum(s, g.x * units::per_mm);
    cnum(s, g.s * units::per_mm);
    cnum(s, g.p / units::MPa);
    if (plastic) { cnum(s, g.p_elastic / units::MPa); }
    append_traction_cells(s, g, tangential);
    s += '\n';
  });
}

bool is_failed_row(const CaseResult& r, const char* status_text) {
  return status_text != nullptr || r.status == CaseStatus::OutOfRange || r.status == CaseStatus::NoContact;
}

void format_case(std::uint64_t idx, const CasePoint& cp, const CaseResult& r,
                 bool plastic, bool want_csv, bool want_json, Formatted& f, const char* status_text,
                 const RcfOptions& rcf, bool tangential) {
  const char* status = status_text ? status_text : to_string(r.status);
  // The warnings' cell, their texts joined by ';' (warning_text(), appended in place).
  thread_local std::string warn;
  warn.clear();
  if (want_csv)
    for (std::size_t i = 0; i < r.warnings.size(); ++i) {
      if (i) warn += ';';
      append_warning_text(warn, r.warnings[i]);
    }
  // The main contact: the loaded ellipse carrying the largest normal force.
  const LoadedEllipse* main = nullptr;
  bool any_plastic = false;
  for (const LoadedEllipse& L : r.loaded) {
    if (!main || L.s.N > main->s.N) main = &L;
    any_plastic = any_plastic || (plastic && L.s.plastic);
  }
  double gamma_main = main ? main->g.gamma / units::deg : NAN;
  double r_roll_main = main ? main->g.r_roll * units::per_mm : NAN;
  // Grid methods: the patch carrying the largest normal force.
  const PatchResult* main_patch = nullptr;
  for (const PatchResult& P : r.patches) {
    if (!main_patch || P.N > main_patch->N) main_patch = &P;
    any_plastic = any_plastic || (plastic && P.plastic_area > 0);
  }
  if (main_patch) {
    gamma_main = main_patch->gamma / units::deg;
    r_roll_main = main_patch->r_roll * units::per_mm;
  }
  auto h_y_mm = [](const LoadedEllipse& e) { return e.h_y * units::per_mm; };  // from the ellipse law (method.md §5)
  const bool failed = is_failed_row(r, status_text);
  if (want_csv) {
    std::string& s = f.cases;
    s.clear();
    append_number(s, static_cast<long long>(idx));
    s += ','; num_repeated(s, cp.tY_mm);
    s += ','; num_repeated(s, cp.Q_kN);
    s += ','; s += status;
    s += ','; s += to_string(r.method);
    // A failed row (no solution: out_of_range, no_contact, invalid_pair) leaves every result
    // field empty in CSV and null in JSON (docs/outputs.md); n_contacts stays 0. rnum and pnum
    // write the cell with its leading separator.
    auto rnum = [&](std::string& o, double v) { if (!failed) cnum(o, v); else o += ','; };
    // A grid method's not_converged row has no peak pressure or area (NaN: grid_checks.hpp,
    // withhold_unconverged_pressures): empty as well, never "nan".
    auto pnum = [&](std::string& o, double v) { if (!failed && std::isfinite(v)) cnum(o, v); else o += ','; };
    rnum(s, r.dz * units::per_mm);
    rnum(s, r.approach * units::per_mm);
    s += ','; if (!failed) append_number(s, static_cast<long long>(r.iterations));
    rnum(s, r.residual);
    s += ','; append_number(s, static_cast<long long>(r.n_contacts));
    rnum(s, r.Fz / units::kN);
    rnum(s, r.Fy / units::kN);
    pnum(s, y_over_q(r));
    pnum(s, r.pmax / units::MPa);
    pnum(s, r.area * units::per_mm2);
    s += ','; if (!failed) num_repeated(s, gamma_main);
    s += ','; if (!failed) num_repeated(s, r_roll_main);
    s += ','; if (!failed) s += any_plastic ? '1' : '0';
    s += ','; append_number(s, static_cast<long long>(r.warnings.size()));
    s += ','; csv_text(s, warn);
    s += ','; csv_text(s, r.message);
    // The smoothing's uncertainty band (profiles.md §7): empty where not computed.
    for (double v : {r.pmax_half_L / units::MPa, r.pmax_double_L / units::MPa, r.area_half_L * units::per_mm2,
                     r.area_double_L * units::per_mm2}) {
      pnum(s, v);
    }
    if (rcf.enabled()) {
      CsvSink k{s};
      rcf_case_fields(k, rcf, r, failed);
    }
    if (tangential) {
      CsvSink k{s};
      tangential_case_fields(k, r, failed);
    }
    s += '\n';
    std::string& e = f.ellipses;
    e.clear();
    for (const LoadedEllipse& L : r.loaded) {
      append_number(e, static_cast<long long>(idx));
      e += ','; num_repeated(e, cp.tY_mm);
      e += ','; num_repeated(e, cp.Q_kN);
      e += ','; append_number(e, static_cast<long long>(L.ellipse));
      for (const Col& c : kEllipseCols) { cnum(e, c.get(L)); }
      if (plastic) {
        e += ','; e += L.s.plastic ? "1" : "0";
        cnum(e, h_y_mm(L));
        for (std::size_t k = 1; k < std::size(kPlasticCols); ++k) { cnum(e, kPlasticCols[k].get(L)); }
      }
      e += ','; e += L.validity.valid ? "1" : "0";
      for (std::size_t k = 1; k < std::size(kTailCols); ++k) { cnum(e, kTailCols[k].get(L)); }
      if (plastic)
        for (const Col& c : kPlasticTailCols) { cnum(e, c.get(L)); }
      if (!plastic) { cnum(e, kAreaCol.get(L)); }
      if (rcf.enabled()) {
        CsvSink k{e};
        rcf_fields(k, rcf, L.s.N, L.s.a_el, L.s.b_el, L.t, nullptr, ellipse_cells(r, L));  // the elastic Hertz ellipse of N
      }
      if (tangential) {
        CsvSink k{e};
        tangential_fields(k, L.t);
        damage_fields(k, L.damage);
      }
      e += '\n';
    }
  }
  if (want_json) {
    // The record as JSON (ordered keys, as in the CSV), compact on one line: written as
    // nlohmann's dump() of these values would write it (json_record.hpp).
    std::string& js = f.json;
    js.clear();
    JsonRecord j{js};
    auto jv = [&](const char* k, double v) { j.key(k); j.table_number(v); };
    auto rv = [&](const char* k, double v) { j.key(k); if (failed) j.null(); else j.table_number(v); };
    j.begin_object();
    j.key("case"); j.integer(static_cast<long long>(idx));
    jv("tY_mm", cp.tY_mm);
    jv("Q_kN", cp.Q_kN);
    j.key("status"); j.string(status);
    j.key("method"); j.string(to_string(r.method));
    rv("dz_virtual_mm", r.dz * units::per_mm);
    rv("approach_mm", r.approach * units::per_mm);
    j.key("iterations"); if (failed) j.null(); else j.integer(r.iterations);
    rv("residual", r.residual);
    j.key("n_contacts"); j.integer(r.n_contacts);
    rv("Fz_kN", r.Fz / units::kN);
    rv("Fy_kN", r.Fy / units::kN);
    rv("Y_over_Q", y_over_q(r));
    rv("pmax_MPa", r.pmax / units::MPa);
    rv("area_mm2", r.area * units::per_mm2);
    rv("gamma_main_deg", gamma_main);
    rv("r_roll_main_mm", r_roll_main);
    j.key("plastic"); if (failed) j.null(); else j.boolean(any_plastic);
    j.key("n_warnings"); j.integer(static_cast<long long>(r.warnings.size()));
    j.key("warnings");
    j.begin_array();
    for (const Warning& w : r.warnings) {
      warn.clear();
      append_warning_text(warn, w);
      j.string(warn);
    }
    j.end_array();
    j.key("message"); j.string(r.message);
    rv("pmax_half_L_MPa", r.pmax_half_L / units::MPa);
    rv("pmax_double_L_MPa", r.pmax_double_L / units::MPa);
    rv("area_half_L_mm2", r.area_half_L * units::per_mm2);
    rv("area_double_L_mm2", r.area_double_L * units::per_mm2);
    if (rcf.enabled()) {
      JsonSink k{j};
      rcf_case_fields(k, rcf, r, failed);
    }
    if (tangential) {
      JsonSink k{j};
      tangential_case_fields(k, r, failed);
    }
    j.key("ellipses");
    j.begin_array();
    for (const LoadedEllipse& L : r.loaded) {
      j.begin_object();
      j.key("ellipse"); j.integer(L.ellipse);
      for (const Col& c : kEllipseCols) jv(c.name, c.get(L));
      if (plastic) {
        j.key("plastic"); j.boolean(L.s.plastic);
        jv("h_y_mm", h_y_mm(L));
        for (std::size_t k = 1; k < std::size(kPlasticCols); ++k) jv(kPlasticCols[k].name, kPlasticCols[k].get(L));
      }
      j.key("hertz_valid"); j.boolean(L.validity.valid);
      for (std::size_t k = 1; k < std::size(kTailCols); ++k) jv(kTailCols[k].name, kTailCols[k].get(L));
      if (plastic)
        for (const Col& c : kPlasticTailCols) jv(c.name, c.get(L));
      if (!plastic) jv(kAreaCol.name, kAreaCol.get(L));
      if (rcf.enabled()) {
        JsonSink k{j};
        rcf_fields(k, rcf, L.s.N, L.s.a_el, L.s.b_el, L.t, nullptr, ellipse_cells(r, L));  // the elastic Hertz ellipse of N
      }
      if (tangential) {
        JsonSink k{j};
        tangential_fields(k, L.t);
        damage_fields(k, L.damage);
      }
      j.end_object();
    }
    j.end_array();
    // The grid methods' patches (the rows of patches.csv; empty for the multi-Hertzian method).
    j.key("patches");
    j.begin_array();
    for (const PatchResult& P : r.patches) {
      j.begin_object();
      JsonSink k{j};
      patch_fields(k, P, plastic, rcf, tangential);
      j.end_object();
    }
    j.end_array();
    j.end_object();
  }
}

void format_patches(std::uint64_t idx, const CasePoint& cp, const CaseResult& r, bool plastic, std::string& s,
                    const RcfOptions& rcf, bool tangential) {
  s.clear();
  for (const PatchResult& P : r.patches) {
    append_number(s, static_cast<long long>(idx));
    cnum(s, cp.tY_mm);
    cnum(s, cp.Q_kN);
    CsvSink k{s};
    patch_fields(k, P, plastic, rcf, tangential);
    s += '\n';
  }
}

void format_patch_pressure(std::uint64_t idx, const CaseResult& r, std::string& s, bool tangential) {
  s.clear();
  for_each_patch_grid_point(r, tangential, [&](const GridPoint& g) {
    append_number(s, static_cast<long long>(idx));
    s += ','; append_number(s, static_cast<long long>(g.contact));
    cnum(s, g.x * units::per_mm);
    cnum(s, g.s * units::per_mm);
    cnum(s, g.y_rail * units::per_mm);
    cnum(s, g.p / units::MPa);
    append_traction_cells(s, g, tangential);
    s += '\n';
  });
}

void format_strips(std::uint64_t idx, const CasePoint& cp, const CaseResult& r, std::string& s) {
  s.clear();
  for (const PatchResult& P : r.patches)
    for (const StripOut& st : P.strips) {
      append_number(s, static_cast<long long>(idx));
      cnum(s, cp.tY_mm);
      cnum(s, cp.Q_kN);
      s += ','; append_number(s, static_cast<long long>(P.patch));
      cnum(s, st.s * units::per_mm);
      cnum(s, st.y_r * units::per_mm);
      cnum(s, st.c * units::per_mm);
      cnum(s, st.a * units::per_mm);
      cnum(s, st.q / units::MPa);
      s += ','; s += st.plastic ? '1' : '0';
      s += '\n';
    }
}

std::string strips_csv_header() { return "case,tY_mm,Q_kN,patch,s_mm,y_rail_mm,x_centre_mm,half_length_mm,amplitude_MPa,plastic\n"; }

std::string patches_csv_header(bool plastic, bool rcf, bool tangential, bool subsurface) {
  std::string s = "case,tY_mm,Q_kN";
  HeaderSink k{s};
  RcfOptions o;
  if (rcf) o.f = 0;  // enabled: the header has the names only
  o.subsurface = subsurface;
  patch_fields(k, PatchResult{}, plastic, o, tangential);
  return s + "\n";
}

bool writes_ellipses(Method m) { return m == Method::MultiHertzian || m == Method::Auto; }
bool writes_patches(Method m) { return m != Method::MultiHertzian; }
std::string pressure_table_header(Method m, bool plastic, bool tangential) {
  return m == Method::MultiHertzian ? pressure_csv_header(plastic, tangential) : patch_pressure_csv_header(tangential);
}

namespace {
const char* const kTractionCols = ",px_MPa,py_MPa,slip";  // docs/outputs.md "pressure.csv"
}  // namespace

std::string patch_pressure_csv_header(bool tangential) {
  return std::string("case,patch,x_mm,s_mm,y_rail_mm,p_MPa") + (tangential ? kTractionCols : "") + "\n";
}

std::string cases_csv_header(bool tangential, bool rcf) {
  std::string s = "case,tY_mm,Q_kN,status,method,dz_virtual_mm,approach_mm,iterations,residual,n_contacts,Fz_kN,Fy_kN,Y_over_Q,"
                  "pmax_MPa,area_mm2,gamma_main_deg,r_roll_main_mm,plastic,n_warnings,warnings,message,"
                  "pmax_half_L_MPa,pmax_double_L_MPa,area_half_L_mm2,area_double_L_mm2";
  if (rcf) {
    HeaderSink k{s};
    rcf_case_fields(k, RcfOptions{}, CaseResult{}, true);
  }
  if (tangential) {
    HeaderSink k{s};
    tangential_case_fields(k, CaseResult{}, true);
  }
  return s + "\n";
}

std::string pressure_csv_header(bool plastic, bool tangential) {
  return std::string(plastic ? "case,ellipse,x_mm,y_mm,p_MPa,p_elastic_MPa" : "case,ellipse,x_mm,y_mm,p_MPa") +
         (tangential ? kTractionCols : "") + "\n";
}

std::string ellipses_csv_header(bool plastic, bool rcf, bool tangential, bool subsurface) {
  std::string s = "case,tY_mm,Q_kN,ellipse";
  for (const Col& c : kEllipseCols) { s += ','; s += c.name; }
  if (plastic) {
    s += ",plastic";
    for (const Col& c : kPlasticCols) { s += ','; s += c.name; }
  }
  for (const Col& c : kTailCols) { s += ','; s += c.name; }
  if (plastic)
    for (const Col& c : kPlasticTailCols) { s += ','; s += c.name; }
  if (!plastic) { s += ','; s += kAreaCol.name; }
  if (rcf) {
    HeaderSink k{s};
    RcfOptions o;
    o.subsurface = subsurface;
    rcf_fields(k, o, 0, 0, 0, TangentialResult{});
  }
  if (tangential) {
    HeaderSink k{s};
    tangential_fields(k, TangentialResult{});
    damage_fields(k, ContactDamage{});
  }
  return s + "\n";
}

std::string geometry_csv_header() {
  std::string s = "tY_mm,ellipse";
  for (const GeoCol& c : kGeometryCols) { s += ','; s += c.name; }
  return s + "\n";
}

void format_geometry(double tY_mm, const std::vector<CandidateEllipse>& cands, bool want_csv, bool want_json,
                     std::string& csv, std::vector<std::string>* json) {
  csv.clear();
  if (json) json->clear();
  for (const CandidateEllipse& E : cands) {
    if (want_csv) {
      num(csv, tY_mm);  // as num_repeated() writes it in ellipses.csv: the two tables join on this text
      csv += ','; append_number(csv, static_cast<long long>(E.ellipse));
      for (const GeoCol& c : kGeometryCols) {
        csv += ',';
        if (!c.hertz || E.hertzian) num(csv, c.get(E));
      }
      csv += '\n';
    }
    if (want_json && json) {
      std::string rec;
      JsonRecord j{rec};
      j.begin_object();
      j.key("tY_mm");
      j.table_number(tY_mm);
      j.key("ellipse");
      j.integer(E.ellipse);
      for (const GeoCol& c : kGeometryCols) {
        j.key(c.name);
        if (!c.hertz || E.hertzian) j.table_number(c.get(E));
        else j.null();
      }
      j.end_object();
      json->push_back(std::move(rec));
    }
  }
}


}  // namespace mh
