// The domain in which an equivalent conicity is ok; see conicity_domain.hpp.
#include "geometry/conicity_domain.hpp"

#include <cmath>

#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {

const std::vector<ConicityEvidenceRow>& conicity_evidence() {
  static const std::vector<ConicityEvidenceRow> rows = {
      {"Δr(y), rigid contact search",
       "EN 15302 wheel A on rail A (absolute at 750 mm, no roll, R0 460 mm), y −6.8 … 6.8 mm, 137 points, "
       "contact angle 0 … 70°: within 0.0016 mm at every point",
       "test_wheelset.cpp \"EN 15302 wheel A on rail A\"; EN 15302:2021 J.2"},
      {"tan γe, symmetric pair",
       "the same pair, ŷ 1 … 7.4 mm (33 amplitudes): within 0.0005",
       "same test; EN 15302:2021 K.2"},
      {"tan γe, the integral alone",
       "a cone (tan γe = λ, symmetric and offset), a two-slope Δr, S with two wells (no oscillation), a measured "
       "wheel's rough Δr at ŷ 1 … 7.4 mm: 1e-7 relative",
       "test_wheelset.cpp: closed forms; 30-digit quadrature (scripts/conicity_reference.py)"},
      {"amplitude against the flangeway clearance",
       "the reference pair's clearance is 4.89 mm per side (TG 1435.164 mm, Sd 32.69 mm): ŷ 1 … 4.8 mm inside it, "
       "contact angle up to 11.09°; ŷ 5.0 … 7.4 mm (flange root and flank) agree with the standard's table but are "
       "flange_contact, as is any oscillation whose contact angle exceeds 11.1°",
       "test_conicity_domain.cpp; TSI LOC&PAS §4.2.3.4.3 (ŷ inside TG − SR)"},
      {"profiles",
       "wheels with a flange face at the Sd level and rails with a gauge point; a wheel without a flange is "
       "profile_incomplete",
       "test_conicity_domain.cpp (flat_wheel.txt, S1002 cut to y −8 … 8 mm)"},
      {"wheel measures",
       "the reference wheel A: Sd 32.69, Sh 28.00, qR 10.98 mm, inside EN 15313 (D 920 mm: Sd 22 … 33, Sh 27.5 … 36, "
       "qR ≥ 6.5 mm); a wheel outside is flagged outside_en15313 in fleet.csv and summary.json",
       "test_conicity_domain.cpp"},
  };
  return rows;
}

std::string conicity_evidence_markdown() {
  std::string s = "| what | covered | test, reference |\n|---|---|---|\n";
  for (const auto& r : conicity_evidence()) s += std::string("| ") + r.quantity + " | " + r.covered + " | " + r.test + " |\n";
  return s;
}

FlangewayClearance flangeway_clearance(const Wheelset& ws, const WheelMeasures& left, const WheelMeasures& right) {
  FlangewayClearance fc;
  const WheelMeasures* m[2] = {&left, &right};
  const char* side[2] = {"left", "right"};
  double c[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const int s = k == 0 ? -1 : 1;
    if (!m[k]->valid) {
      fc.why = std::string("the ") + side[k] + " wheel has no flange face at the Sd level (" + m[k]->why + ")";
      return fc;
    }
    if (!std::isfinite(ws.gauge_point(s))) {
      fc.why = std::string("the ") + side[k] + " rail has no gauge point (gauge_height below its top, gauge side)";
      return fc;
    }
    // The flange face at the Sd level: wheel y = Sd − 70 mm (profile.hpp, wheel_measures), at
    // |Y| = taping line + that y on the centred wheelset.
    const double face = ws.taping_line(s) + (m[k]->Sd - 0.070);
    c[k] = ws.gauge_point(s) - face;
  }
  fc.left = c[0];
  fc.right = c[1];
  fc.valid = true;
  return fc;
}

ConicityDomainVerdict conicity_domain(const ConicityResult& c, const FlangewayClearance& fc, double gamma_max) {
  ConicityDomainVerdict v;
  v.status = c.status;
  if (c.status != "ok") return v;
  if (!fc.valid) {
    v.status = "profile_incomplete";
    v.why = fc.why;
    return v;
  }
  auto mm = [](double x) { return format_number(std::round(x * 1e5) / 1e2); };
  // The rounding of the turning points (1e-12 m) is far below any clearance that matters.
  constexpr double kSlack = 1e-9;  // [m]
  const bool beyond_r = c.y2 > fc.right + kSlack, beyond_l = -c.y1 > fc.left + kSlack;
  if (beyond_l && beyond_r) {
    v.status = "flange_contact";
    v.why = "turning points " + mm(c.y1) + " / " + mm(c.y2) + " mm beyond the flangeway clearances " + mm(fc.left) +
            " / " + mm(fc.right) + " mm (left / right)";
    return v;
  }
  if (beyond_l || beyond_r) {
    v.status = "flange_contact";
    v.why = std::string("turning point ") + mm(beyond_r ? c.y2 : c.y1) + " mm beyond the " + (beyond_r ? "right" : "left") +
            " flangeway clearance " + mm(beyond_r ? fc.right : fc.left) + " mm";
    return v;
  }
  if (gamma_max > kTreadContactAngleMax) {
    v.status = "flange_contact";
    v.why = "contact angle " + format_number(std::round(gamma_max / units::deg * 10) / 10) + " deg > " +
            format_number(kTreadContactAngleMax / units::deg) + " deg inside the oscillation (flange root)";
  }
  return v;
}

const WheelMeasureLimits* wheel_measure_limits(double D) {
  // EN 15313:2016 in-service limits, as the TSI restates them (Regulation (EU) 1302/2014 LOC&PAS
  // §4.2.3.5.2.2 Table 2; 321/2013 WAG Table 6), lengths [m]: flange thickness Sd, flange height
  // Sh, flange slope qR, by wheel diameter D.
  static const WheelMeasureLimits bands[] = {
      {0.840, INFINITY, 22.0e-3, 33.0e-3, 27.5e-3, 36.0e-3, 6.5e-3},
      {0.760, 0.840, 25.0e-3, 33.0e-3, 27.5e-3, 36.0e-3, 6.5e-3},
      {0.630, 0.760, 27.5e-3, 33.0e-3, 29.5e-3, 36.0e-3, 6.5e-3},
      {0.330, 0.630, 27.5e-3, 33.0e-3, 31.5e-3, 36.0e-3, 6.5e-3},
  };
  for (const auto& b : bands)
    if (D >= b.D_min && D < b.D_max) return &b;
  return nullptr;
}

WheelMeasureCheck check_wheel_measures(double Sd, double Sh, double qR, double D) {
  WheelMeasureCheck r;
  const WheelMeasureLimits* L = wheel_measure_limits(D);
  if (!L) return r;
  auto check = [&](const char* name, double v, double lo, double hi) {
    if (!std::isfinite(v)) return false;
    if (v > hi) r.violations.push_back({name, v, hi, true});
    else if (v < lo) r.violations.push_back({name, v, lo, false});
    return true;
  };
  bool known = check("Sd", Sd, L->Sd_min, L->Sd_max);
  known = check("Sh", Sh, L->Sh_min, L->Sh_max) && known;
  known = check("qR", qR, L->qR_min, INFINITY) && known;
  r.status = !r.violations.empty() ? "outside_en15313" : known ? "ok" : "unknown";
  return r;
}

std::string WheelMeasureCheck::text(double D) const {
  std::string s;
  for (const auto& v : violations) {
    if (!s.empty()) s += "; ";
    s += std::string(v.measure) + " " + format_number(std::round(v.value * 1e5) / 1e2) + " mm " + (v.above ? "> " : "< ") +
         format_number(std::round(v.limit * 1e5) / 1e2) + " mm (EN 15313, D " + format_number(std::round(D * 1e4) / 10) + " mm)";
  }
  return s;
}

}  // namespace mh
