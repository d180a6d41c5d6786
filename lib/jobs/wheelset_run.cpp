// `mhcontact wheelset`; see wheelset_run.hpp.
#include "jobs/wheelset_run.hpp"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <ostream>
#include <thread>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/parallel.hpp"
#include "core/units.hpp"
#include "geometry/conicity.hpp"
#include "geometry/conicity_domain.hpp"
#include "geometry/wheelset.hpp"
#include "jobs/run.hpp"
#include "output/cells.hpp"
#include "output/output_file.hpp"
#include "output/run_dir.hpp"
#include "output/wheelset_tables.hpp"
#include "profile/standard_profiles.hpp"

namespace mh {

namespace {

constexpr double kHeadlineAmplitude = 3e-3;  // [m] EN 15302's headline tan γe at ŷ = 3 mm

/// Conicity at amplitude A, refused ("off_profile") when a row between its turning points is not
/// ok; then held against its domain (conicity_domain.hpp: "profile_incomplete", "flange_contact",
/// tan γe kept).
ConicityResult conicity_checked(const EquivalentConicity& C, const std::vector<double>& ys,
                                const std::vector<WheelsetState>& st, double A, const FlangewayClearance& fc,
                                std::string* why = nullptr) {
  ConicityResult c = C.at(A);
  if (c.status != "ok") return c;
  double gamma_max = 0;
  for (std::size_t k = 0; k < ys.size(); ++k) {
    if (!(ys[k] >= c.y1 - 1e-12 && ys[k] <= c.y2 + 1e-12)) continue;
    if (wheelset_row_status(st[k]) != "ok") {
      c.status = wheelset_row_status(st[k]);
      c.tan_gamma_e = std::nan("");
      return c;
    }
    gamma_max = std::max({gamma_max, std::fabs(st[k].left.gamma), std::fabs(st[k].right.gamma)});
  }
  const ConicityDomainVerdict v = conicity_domain(c, fc, gamma_max);
  c.status = v.status;
  if (why) *why = v.why;
  return c;
}

/// The wheel diameter of EN 15313's bands: the nominal (taping-line) diameter 2 R0.
double wheel_diameter(const WheelsetPlacement& P, int side) {
  return 2 * (side < 0 ? P.nominal_radius_left : P.nominal_radius_right);
}

/// summary.json's record of one wheel's measures (profile, EN 15313) and their check.
nlohmann::ordered_json measures_json(const WheelMeasures& m, double D) {
  nlohmann::ordered_json j;
  auto mm = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v * units::per_mm) : nlohmann::ordered_json(); };
  j["Sd_mm"] = m.valid ? mm(m.Sd) : nlohmann::ordered_json();
  j["Sh_mm"] = m.valid ? mm(m.Sh) : nlohmann::ordered_json();
  j["qR_mm"] = m.valid ? mm(m.qR) : nlohmann::ordered_json();
  const WheelMeasureCheck k = m.valid ? check_wheel_measures(m.Sd, m.Sh, m.qR, D) : WheelMeasureCheck{};
  j["diameter_mm"] = D * units::per_mm;
  j["check"] = k.status;
  j["message"] = m.valid ? k.text(D) : m.why;
  return j;
}

/// Δr of the rows that found both contacts (the conicity's input); NaN rows are left out.
std::unique_ptr<EquivalentConicity> conicity_of(const std::vector<double>& ys, const std::vector<WheelsetState>& st) {
  std::vector<double> y, dr;
  for (std::size_t k = 0; k < ys.size(); ++k)
    if (st[k].found && std::isfinite(st[k].delta_r())) y.push_back(ys[k]), dr.push_back(st[k].delta_r());
  if (y.size() < 3) return nullptr;
  return std::make_unique<EquivalentConicity>(y, dr);
}

/// The case's options with max_displacement the sweep's largest |y| (the wheels are smoothed only
/// over what can face the rails there).
WheelsetOptions sweep_options(const WheelsetCase& wc) {
  WheelsetOptions o = wc.options;
  o.max_displacement = 0;
  for (double y : wc.y) o.max_displacement = std::max(o.max_displacement, std::fabs(y));
  return o;
}

unsigned thread_count(unsigned t) { return std::max(1u, t ? t : std::thread::hardware_concurrency()); }

int single_job(const WheelsetCase& wc, const WheelsetRunOptions& opt, std::ostream& out, std::ostream& err) {
  const Profile wl = load_profile(wc.wheel_left, ProfileKind::Wheel);
  const Profile wr = wc.one_wheel ? wl : load_profile(wc.wheel_right, ProfileKind::Wheel);
  const Profile rl = load_profile(wc.rail_left, ProfileKind::Rail, wc.inclination);
  const Profile rr = wc.one_rail ? rl : load_profile(wc.rail_right, ProfileKind::Rail, wc.inclination);
  const Wheelset ws(wl, wc.one_wheel ? wl : wr, rl, wc.one_rail ? rl : rr, wc.placement, sweep_options(wc));
  const std::vector<WheelsetState> st = ws.sweep(wc.y, thread_count(opt.threads));
  const bool roll = wc.options.roll == WheelsetRoll::Solved;
  const WheelMeasures ml = wheel_measures(wl), mr = wc.one_wheel ? ml : wheel_measures(wr);
  const FlangewayClearance fc = flangeway_clearance(ws, ml, mr);

  RunDirectory rd(opt.out_dir);
  bool all_ok = true;
  {
    OutputFile f(rd.path("wheelset.csv"));
    std::string s = wheelset_csv_header(roll);
    for (std::size_t k = 0; k < st.size(); ++k) {
      wheelset_csv_row(s, wc.y_mm[k], st[k], roll);
      all_ok = all_ok && wheelset_row_status(st[k]) == "ok";
    }
    f.stream() << s;
    f.commit();
  }
  const auto C = conicity_of(wc.y, st);
  ConicityResult head;
  head.status = "no_centre";
  head.tan_gamma_e = std::nan("");
  {
    OutputFile f(rd.path("conicity.csv"));
    std::string s = conicity_csv_header();
    for (std::size_t i = 0; i < wc.amplitudes.size(); ++i) {
      ConicityResult c;
      std::string why;
      if (C) c = conicity_checked(*C, wc.y, st, wc.amplitudes[i], fc, &why);
      else c.status = "no_centre", c.tan_gamma_e = c.y1 = c.y2 = std::nan("");
      all_ok = all_ok && c.status == "ok";
      conicity_csv_row(s, wc.amplitudes_mm[i], c, why);
    }
    f.stream() << s;
    f.commit();
    if (C) head = conicity_checked(*C, wc.y, st, kHeadlineAmplitude, fc);
  }
  nlohmann::ordered_json sum;
  sum["schema"] = kWheelsetSchema;
  sum["inputs"] = wc.resolved_json();
  // The profiles as the case file names them (never resolved: outputs do not depend on where the
  // repository or the files live).
  sum["wheel_left"] = wc.wheel_left.label();
  sum["wheel_right"] = wc.wheel_right.label();
  sum["rail_left"] = wc.rail_left.label();
  sum["rail_right"] = wc.rail_right.label();
  sum["rail_origin_mm"] = {{"left", ws.rail_origin(-1) * units::per_mm}, {"right", ws.rail_origin(+1) * units::per_mm}};
  sum["measured_gauge_mm"] = std::isfinite(ws.measured_gauge()) ? nlohmann::json(ws.measured_gauge() * units::per_mm) : nlohmann::json();
  sum["tan_gamma_e_3mm"] = std::isfinite(head.tan_gamma_e) ? nlohmann::json(head.tan_gamma_e) : nlohmann::json();
  sum["tan_gamma_e_3mm_status"] = head.status;
  auto clearance = [&](double c) { return fc.valid ? nlohmann::ordered_json(c * units::per_mm) : nlohmann::ordered_json(); };
  sum["flangeway_clearance_mm"] = {{"left", clearance(fc.left)}, {"right", clearance(fc.right)}};
  if (!fc.valid) sum["flangeway_clearance_why"] = fc.why;
  sum["wheel_measures"] = {{"left", measures_json(ml, wheel_diameter(wc.placement, -1))},
                           {"right", measures_json(mr, wheel_diameter(wc.placement, +1))}};
  std::size_t n_two = 0;
  for (const auto& s : st) n_two += s.left.two_point || s.right.two_point;
  sum["rows_with_two_point_contact"] = n_two;
  {
    OutputFile f(rd.path("summary.json"));
    f.stream() << sum.dump(2) << '\n';
    f.commit();
  }
  rd.finish("wheelset", program_json());
  if (!opt.quiet) {
    err << "wheelset: " << st.size() << " rows, y " << format_number(wc.y_mm.front()) << " … "
        << format_number(wc.y_mm.back()) << " mm, roll " << to_string(wc.options.roll) << "; gauge "
        << format_number(std::round(ws.measured_gauge() * 1e6) / 1e3) << " mm\n";
  }
  out << "tan_gamma_e at 3 mm: ";
  if (std::isfinite(head.tan_gamma_e)) out << format_number(std::round(head.tan_gamma_e * 1e4) / 1e4) << "\n";
  else out << head.status << "\n";
  return all_ok ? kExitOk : kExitCasesFailed;
}

struct FleetRow {
  std::string source, status = "ok", message;
  double head = std::nan("");
  std::vector<double> tg;
  /// [m] Sd, Sh, qR by EN 15313 from the profile (NaN where the profile does not allow them), and
  /// as the file's header states them (NaN where it does not): two sources, two sets of columns.
  double m_en[3] = {std::nan(""), std::nan(""), std::nan("")};
  double m_file[3] = {std::nan(""), std::nan(""), std::nan("")};
  std::string measures_check;  ///< WheelMeasureCheck::status of the EN 15313 measures ("" when unread)
};

/// The wheel's Sd, Sh, qR computed from the profile (EN 15313, wheel_measures) and as its file's
/// header states them (MiniProf "Sd/Sh/qR" measures line or Sd=, Sh=, qR= keys, in mm:
/// Profile::file_measures). A header's measures may be taken at other reference heights (an old
/// MiniProf states Sh 37.11 mm where EN 15313 gives 28 mm), so they are written apart and never
/// checked against EN 15313's limits.
WheelMeasures fleet_measures(const Profile& w, FleetRow& r) {
  const WheelMeasures m = wheel_measures(w);
  const char* names[3] = {"sd", "sh", "qr"};
  const double computed[3] = {m.Sd, m.Sh, m.qR};
  for (int k = 0; k < 3; ++k) {
    if (m.valid) r.m_en[k] = computed[k];
    for (const auto& [key, val] : w.file_measures) {
      std::string lk = key;
      for (char& ch : lk) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (lk != names[k]) continue;
      char* end = nullptr;
      const double v = std::strtod(val.c_str(), &end);
      if (end != val.c_str() && std::isfinite(v)) r.m_file[k] = v * units::mm;
    }
  }
  return m;
}

/// `text` with every occurrence of `from` replaced by `to` (a reader's message naming the resolved
/// path, written with the path as given).
std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  if (from.empty()) return text;
  for (std::size_t p = 0; (p = text.find(from, p)) != std::string::npos; p += to.size()) text.replace(p, from.size(), to);
  return text;
}

int fleet_job(const WheelsetCase& wc, const WheelsetRunOptions& opt, std::ostream& out, std::ostream& err) {
  const auto t0 = std::chrono::steady_clock::now();
  const Profile rl = load_profile(wc.rail_left, ProfileKind::Rail, wc.inclination);
  const Profile rr = wc.one_rail ? rl : load_profile(wc.rail_right, ProfileKind::Rail, wc.inclination);
  // The rails are smoothed and placed once (with a stand-in wheel); each wheel then replaces it.
  const Profile stand_in = make_standard_profile("S1002");
  const Wheelset track(stand_in, stand_in, rl, wc.one_rail ? rl : rr, wc.placement, sweep_options(wc));
  const std::size_t n = wc.fleet.size();
  std::vector<FleetRow> rows(n);
  // One wheel an item, on the library's pool (core/parallel.hpp).
  parallel_for(n, opt.threads, 1, [] { return 0; }, [&](std::size_t i, int&) {
    FleetRow& r = rows[i];
    r.source = wc.fleet[i].label();
    try {
      const Profile w = load_profile(wc.fleet[i], ProfileKind::Wheel);
      const WheelMeasures m = fleet_measures(w, r);
      // The wheel is both wheels of the fleet's wheelset; EN 15313's band by the larger diameter.
      const double D = std::max(wheel_diameter(wc.placement, -1), wheel_diameter(wc.placement, +1));
      const WheelMeasureCheck mc = check_wheel_measures(r.m_en[0], r.m_en[1], r.m_en[2], D);
      r.measures_check = mc.status;
      const Wheelset ws(track, w, w);
      const std::vector<WheelsetState> st = ws.sweep(wc.y, 1);
      const auto C = conicity_of(wc.y, st);
      if (!C) throw InputError(r.source, "", "no contact found over the sweep");
      const FlangewayClearance fc = flangeway_clearance(ws, m, m);
      std::string why;
      const ConicityResult h = conicity_checked(*C, wc.y, st, kHeadlineAmplitude, fc, &why);
      r.head = h.tan_gamma_e;
      if (h.status != "ok") r.status = h.status, r.message = "tan_gamma_e at 3 mm: " + h.status + (why.empty() ? "" : ": " + why);
      for (double A : wc.amplitudes) {
        if (fleet_headline_amplitude(A)) continue;  // the tan_gamma_e_3mm column already
        const ConicityResult c = conicity_checked(*C, wc.y, st, A, fc, &why);
        r.tg.push_back(c.tan_gamma_e);
        if (c.status != "ok" && r.status == "ok")
          r.status = c.status, r.message = "amplitude " + format_number(A * 1e3) + " mm: " + c.status + (why.empty() ? "" : ": " + why);
      }
      if (!mc.violations.empty()) r.message += (r.message.empty() ? "" : "; ") + mc.text(D);
    } catch (const InputError& e) {
      r.status = kInvalidWheel;
      r.message = replace_all(e.what(), wc.fleet[i].file, wc.fleet[i].given);
      r.tg.clear();
      for (double A : wc.amplitudes)
        if (!fleet_headline_amplitude(A)) r.tg.push_back(std::nan(""));
    }
  });

  RunDirectory rd(opt.out_dir);
  std::size_t n_ok = 0;
  {
    OutputFile f(rd.path("fleet.csv"));
    std::string s = fleet_csv_header(wc.amplitudes_mm);
    for (std::size_t i = 0; i < n; ++i) {
      const FleetRow& r = rows[i];
      n_ok += r.status == "ok";
      s += std::to_string(i) + ',';
      cells::csv_text(s, r.source);
      s += ',' + r.status + ',';
      cells::num(s, r.head);
      for (double v : r.tg) {
        s += ',';
        cells::num(s, v);
      }
      for (const double* set : {r.m_en, r.m_file})
        for (int k = 0; k < 3; ++k) {
          s += ',';
          if (std::isfinite(set[k])) cells::num(s, set[k] * units::per_mm);
        }
      s += ',' + r.measures_check + ',';
      cells::csv_text(s, r.message);
      s += '\n';
    }
    f.stream() << s;
    f.commit();
  }
  rd.finish("wheelset", program_json(), {{"wheels", n}, {"wheels_ok", n_ok}});
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!opt.quiet)
    err << "wheelset fleet: " << n << " wheels, " << n_ok << " ok, " << (n - n_ok) << " refused or incomplete ("
        << format_number(std::round(secs * 100) / 100) << " s, " << parallel_threads(n, opt.threads, 1) << " threads)\n";
  out << "wrote " << opt.out_dir << "/fleet.csv (" << n << " wheels, " << n_ok << " ok)\n";
  return n_ok == n ? kExitOk : kExitCasesFailed;
}

}  // namespace

int wheelset_job(const WheelsetCase& wc, const WheelsetRunOptions& opt, std::ostream& out, std::ostream& err) {
  const cells::DigitsScope digits_scope(opt.digits);
  return wc.is_fleet ? fleet_job(wc, opt, out, err) : single_job(wc, opt, out, err);
}

}  // namespace mh
