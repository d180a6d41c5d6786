// Sweeps and case lists of the case file; see case_sweep.hpp.
#include "input/case_sweep.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/plausible.hpp"
#include "core/units.hpp"

namespace mh {

using nlohmann::json;

namespace {

using detail::Ctx;

// Decimal places of the shortest representation of v ("0.3" -> 1, "1e-05" -> 5, "2.5e-07" -> 8,
// "1e+20" -> 0).
int decimals(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  const std::string t(buf, r.ptr);
  const auto e = t.find('e');
  const std::string mant = t.substr(0, e);
  const int exp10 = e == std::string::npos ? 0 : std::stoi(t.substr(e + 1));
  const auto dot = mant.find('.');
  const int frac = dot == std::string::npos ? 0 : static_cast<int>(mant.size() - dot - 1);
  return std::max(0, frac - exp10);
}

// A range {from, to, step} counted and, where the inputs are short decimals, scaled to integers:
// F = from·10^d, S = step·10^d, T = to·10^d with d the most decimals of the three. Values are
// F + i·S for i = 0 … n−1 with n = floor((T − F) / S) + 1: `to` is included when it lies on the
// grid (exactly, in the decimals given), otherwise the last value is the largest grid value below
// `to`. Long decimals (d > 15) or huge integers fall back to from + i·step with a 1e-9 tolerance.
struct RangeCount {
  double count = 0;
  long long F = 0, S = 0;
  double scale = 0;
};
RangeCount range_count(double from, double to, double step) {
  RangeCount rc;
  const int d = std::max({decimals(from), decimals(to), decimals(step)});
  if (d <= 15) {
    const double sc = std::pow(10.0, d);
    const double f = std::round(from * sc), t = std::round(to * sc), st = std::round(step * sc);
    const double lim = 9007199254740992.0;  // 2^53: integers exact in a double
    if (std::fabs(f) < lim && std::fabs(t) < lim && st >= 1 && st < lim && f / sc == from && t / sc == to && st / sc == step) {
      rc.F = static_cast<long long>(f);
      rc.S = static_cast<long long>(st);
      rc.scale = sc;
      rc.count = static_cast<double>((static_cast<long long>(t) - rc.F) / rc.S) + 1;
      return rc;
    }
  }
  rc.count = std::floor((to - from) / step + 1e-9) + 1;
  return rc;
}

// Number of values an axis will have (0 when malformed: parse_axis then reports the error).
double axis_count(const json& v) {
  if (v.is_array()) return static_cast<double>(v.size());
  if (v.is_number()) return 1;
  if (v.is_object() && v.contains("from") && v.contains("to") && v.contains("step") && v["from"].is_number() &&
      v["to"].is_number() && v["step"].is_number()) {
    const double from = v["from"].get<double>(), to = v["to"].get<double>(), step = v["step"].get<double>();
    if (std::isfinite(from) && std::isfinite(to) && step > 0 && to >= from && std::isfinite((to - from) / step))
      return range_count(from, to, step).count;
  }
  return 0;
}

// A sweep axis: a list of numbers or {"from", "to", "step"} (a range is not materialised).
// Every value lies in the plausible range `r` (core/plausible.hpp): each list entry is checked,
// a range by its first and last value.
SweepAxis parse_axis(const Ctx& c, const json& v, const std::string& path, const plausible::Range& r) {
  SweepAxis out;
  if (v.is_array()) {
    if (v.empty()) c.fail(path, &v, "an empty list gives no cases");
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string p = path + "/" + std::to_string(i);
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) c.fail(p, &v[i], "must be a finite number");
      const double d = v[i].get<double>();
      c.check(d, p, v[i], r);
      out.list.push_back(d);
    }
    out.n = out.list.size();
    return out;
  }
  if (v.is_number()) {
    const double d = v.get<double>();
    if (!std::isfinite(d)) c.fail(path, &v, "must be a finite number");
    c.check(d, path, v, r);
    out.list = {d};
    out.n = 1;
    return out;
  }
  if (!v.is_object()) c.fail(path, &v, "a sweep axis is a list of numbers or {\"from\", \"to\", \"step\"}");
  c.only_keys(v, path, {"from", "to", "step"});
  for (const char* k : {"from", "to", "step"})
    if (!v.contains(k)) c.fail(path, &v, std::string("a range needs \"") + k + "\"");
  const double from = c.number(v, path, "from"), to = c.number(v, path, "to");
  const double step = c.number(v, path, "step");
  if (!(step > 0)) c.fail(path + "/step", &v.at("step"), "must be > 0");
  if (to < from) c.fail(path + "/to", &v.at("to"), "must be >= from (" + format_number(from) + ")");
  const RangeCount rc = range_count(from, to, step);
  if (!(rc.count <= static_cast<double>(kMaxCases)))
    c.fail(path, &v, "gives " + format_number(rc.count) + " values, more than the limit of " + std::to_string(kMaxCases) + " cases");
  out.from = from;
  out.step = step;  // values from + i·step, by multiplication (or scaled integers): no accumulated drift
  out.n = static_cast<std::uint64_t>(rc.count);
  out.F = rc.F;
  out.S = rc.S;
  out.scale = rc.scale;
  c.check(out.at(0), path + "/from", v.at("from"), r);
  c.check(out.at(out.n - 1), path + "/to", v.at("to"), r);
  return out;
}

}  // namespace

double SweepAxis::min() const {
  return list.empty() ? from : *std::min_element(list.begin(), list.end());
}
double SweepAxis::max() const {
  return list.empty() ? at(n - 1) : *std::max_element(list.begin(), list.end());
}

std::uint64_t CaseFile::case_count() const {
  if (!cases.empty()) return cases.size();
  return static_cast<std::uint64_t>(sweep_tY_mm.size()) * sweep_Q_kN.size();
}

void CaseFile::refuse_table_axes() const {
  if (sweep_roll_mrad.size() > 0)
    throw InputError(path + ": /sweep/roll_mrad", format_number(sweep_roll_mrad.at(0)),
                     "the roll is an axis of contact tables (`mhcontact table`); a run solves the wheel upright",
                     "remove roll_mrad from the sweep, or make a table; the library solves a rolled wheel "
                     "(the C interface's roll_rad, pair.solve(..., roll_rad=))");
}

CasePoint CaseFile::case_at(std::uint64_t i) const {
  if (!cases.empty()) return cases[i];
  const std::uint64_t nq = sweep_Q_kN.size();
  const double t = sweep_tY_mm.at(i / nq), q = sweep_Q_kN.at(i % nq);
  return {t * units::mm, q * units::kN, t, q};
}

namespace detail {

void parse_sweep_or_cases(const Ctx& c, const json& j, CaseFile& cf) {
  if (j.contains("sweep") && j.contains("cases")) c.fail("/cases", nullptr, "give either \"sweep\" or \"cases\", not both");
  if (j.contains("sweep")) {
    const json& s = j.at("sweep");
    c.only_keys(s, "/sweep", {"tY_mm", "Q_kN", "roll_mrad"});
    if (!s.contains("tY_mm")) c.fail("/sweep/tY_mm", nullptr, "required");
    if (!s.contains("Q_kN")) c.fail("/sweep/Q_kN", nullptr, "required");
    // Count before materialising anything: a sweep of 10^12 cases is refused up front.
    const double n = axis_count(s.at("tY_mm")) * axis_count(s.at("Q_kN"));
    if (n > static_cast<double>(kMaxCases))
      c.fail("/sweep", nullptr, "gives " + format_number(n) + " cases, more than the limit of " + std::to_string(kMaxCases),
             "split the study (shards) or coarsen the steps");
    cf.sweep_tY_mm = parse_axis(c, s.at("tY_mm"), "/sweep/tY_mm", plausible::kTY_mm);
    cf.sweep_Q_kN = parse_axis(c, s.at("Q_kN"), "/sweep/Q_kN", plausible::kQ_kN);
    if (s.contains("roll_mrad")) {
      if (axis_count(s.at("roll_mrad")) > 1000) c.fail("/sweep/roll_mrad", nullptr, "more than 1000 roll values", "coarsen the step");
      cf.sweep_roll_mrad = parse_axis(c, s.at("roll_mrad"), "/sweep/roll_mrad", plausible::kRoll_mrad);
    }
    cf.has_cases = true;
  } else if (j.contains("cases")) {
    const json& a = j.at("cases");
    if (!a.is_array() || a.empty()) c.fail("/cases", &a, "must be a non-empty list of {\"tY_mm\", \"Q_kN\"}");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = "/cases/" + std::to_string(i);
      c.only_keys(a[i], p, {"tY_mm", "Q_kN"});
      if (!a[i].contains("tY_mm") || !a[i].contains("Q_kN")) c.fail(p, &a[i], "needs tY_mm and Q_kN");
      // Every entry is checked (not a sample), whatever the length of the list.
      const double t = c.plausible(a[i], p, "tY_mm", plausible::kTY_mm), q = c.plausible(a[i], p, "Q_kN", plausible::kQ_kN);
      cf.cases.push_back({t * units::mm, q * units::kN, t, q});
    }
    cf.has_cases = true;
  }
}

}  // namespace detail

}  // namespace mh
