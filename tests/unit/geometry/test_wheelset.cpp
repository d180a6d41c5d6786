// Wheelset geometry (geometry/wheelset.hpp) and equivalent conicity (geometry/conicity.hpp):
// closed forms (a cone), the EN 15302 reference tables of wheel A on rail A, placement and roll.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "geometry/conicity.hpp"
#include "geometry/wheelset.hpp"
#include "profile/standard_profiles.hpp"

using mh::Profile;

namespace {

constexpr double mm = 1e-3;

/// The first `ncols` columns of a CSV of numbers with a header line (tests/data/<dir>/<name>),
/// column by column.
std::vector<std::vector<double>> read_columns(const std::string& name, const std::string& dir, std::size_t ncols) {
  std::ifstream in(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/" + dir + "/" + name);
  REQUIRE(in.good());
  std::vector<std::vector<double>> cols(ncols);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    const char* p = line.c_str();
    for (std::size_t c = 0; c < ncols; ++c) {
      char* end = nullptr;
      cols[c].push_back(std::strtod(p, &end));
      INFO(name << ": " << line);
      REQUIRE(end != p);
      p = *end == ',' ? end + 1 : end;
    }
  }
  return cols;
}

struct Table { std::vector<double> x, v; };
/// First two columns of a CSV with a header line (tests/data/en15302/, or `dir`).
Table read_table(const std::string& name, const std::string& dir = "en15302") {
  auto c = read_columns(name, dir, 2);
  return {std::move(c[0]), std::move(c[1])};
}

/// Largest |Δv/Δx| of the table on either side of point i.
double table_slope(const Table& t, std::size_t i) {
  double s = 0;
  if (i > 0) s = std::max(s, std::fabs((t.v[i] - t.v[i - 1]) / (t.x[i] - t.x[i - 1])));
  if (i + 1 < t.x.size()) s = std::max(s, std::fabs((t.v[i + 1] - t.v[i]) / (t.x[i + 1] - t.x[i])));
  return s;
}

/// y = −8 … 8 mm every 0.01 mm [m], each an integer number of hundredths.
std::vector<double> sweep_y() {
  std::vector<double> ys;
  for (int k = -800; k <= 800; ++k) ys.push_back(k / 100.0 * mm);
  return ys;
}

/// The EN 15302 reference placement (tests/data/en15302/README.md): rail origins at ±750 mm
/// under the taping lines, rail A as given, no roll, R0 = 460 mm.
mh::WheelsetPlacement en15302_placement() {
  mh::WheelsetPlacement P;
  P.rails = mh::WheelsetPlacement::Rails::Absolute;
  P.rail_origin_left = P.rail_origin_right = 750 * mm;
  return P;
}

}  // namespace

TEST_CASE("conicity of a cone: tan γe = λ at every amplitude, symmetric and offset", "[wheelset][conicity]") {
  // A conical wheelset, Δr = 2 λ y + d: S = λ y² + d y, a parabola; the oscillation is harmonic
  // about y0 = −d/(2λ) with I = π/√λ exactly, so tan γe = λ whatever the amplitude and offset
  // (the turning points sit symmetrically about y0). Tolerance 1e-7 (quadrature goal 1e-7).
  for (double d_mm : {0.0, 0.03, -0.1}) {  // y0 = 0, −0.3, +1 mm
    const double lambda = 0.05;
    std::vector<double> ys = sweep_y(), dr;
    for (double y : ys) dr.push_back(2 * lambda * y + d_mm * mm);
    const mh::EquivalentConicity C(ys, dr);
    CHECK(C.centre() == Approx(-d_mm * mm / (2 * lambda)).margin(1e-12));
    for (double A_mm : {0.5, 1.0, 3.0, 5.5}) {
      CAPTURE(d_mm, A_mm);
      const mh::ConicityResult r = C.at(A_mm * mm);
      REQUIRE(r.status == "ok");
      CHECK(r.tan_gamma_e == Approx(lambda).epsilon(1e-7));
      CHECK(r.y1 == Approx(C.centre() - A_mm * mm).margin(1e-10));
      CHECK(r.y2 == Approx(C.centre() + A_mm * mm).margin(1e-10));
    }
    // Turning points beyond the table: refused with a status, not extrapolated.
    CHECK(C.at(7.9 * mm).status == (d_mm == 0 ? "ok" : "out_of_range"));
    CHECK(C.at(8.5 * mm).status == "out_of_range");
  }
  // Δr that never changes sign: no equilibrium.
  std::vector<double> ys = sweep_y(), dr(ys.size(), 1 * mm);
  CHECK(mh::EquivalentConicity(ys, dr).at(3 * mm).status == "no_centre");
}

TEST_CASE("conicity: no tan γe where S rises above the turning level between the turning points", "[wheelset][conicity]") {
  // Δr = 2λ y (y − p)(y − q)/(p q), 0 < p < q: S(y) = (2λ/(p q)) (y⁴/4 − (p + q) y³/3 + p q y²/2)
  // has its minimum at y0 = 0, a maximum at p and a second, higher minimum at q (p = 2, q = 3.5
  // mm: S(q) − S(0) is 0.54 of S(p) − S(0)). Where the turning
  // points enclose p and S(p) > S(y2), the wheelset would turn back at the hump before reaching
  // y2: no oscillation of that amplitude exists, and the status says so (no number). The closed
  // form decides, at the turning points the code reports (which it checks: S(y1) = S(y2)).
  const double lambda = 0.05, p = 2 * mm, q = 3.5 * mm;
  auto S = [&](double y) { return 2 * lambda / (p * q) * (y * y * y * y / 4 - (p + q) * y * y * y / 3 + p * q * y * y / 2); };
  std::vector<double> ys = sweep_y(), dr;
  for (double y : ys) dr.push_back(2 * lambda * y * (y - p) * (y - q) / (p * q));
  const mh::EquivalentConicity C(ys, dr);
  int n_ok = 0, n_none = 0;
  for (double A_mm = 0.5; A_mm <= 5.51; A_mm += 0.25) {
    CAPTURE(A_mm);
    const mh::ConicityResult r = C.at(A_mm * mm);
    REQUIRE((r.status == "ok" || r.status == "no_oscillation"));
    const double depth = S(r.y2) - S(0);
    REQUIRE(depth > 0);
    CHECK(S(r.y1) == Approx(S(r.y2)).margin(1e-3 * depth));  // the table's S: the trapezoid rule's
    const bool hump = r.y1 < p && p < r.y2 && S(p) > S(r.y2);
    if (std::fabs(S(p) - S(r.y2)) < 1e-3 * depth) continue;  // at the boundary the table's S decides
    CHECK(r.status == (hump ? "no_oscillation" : "ok"));
    CHECK(std::isfinite(r.tan_gamma_e) == !hump);
    (hump ? n_none : n_ok)++;
  }
  CHECK(n_ok >= 3);
  CHECK(n_none >= 3);
}

TEST_CASE("conicity: a two-slope Δr against its closed form", "[wheelset][conicity]") {
  // Δr = 2 λ1 y for |y| ≤ b, steeper (2 λ2) beyond: S is λ1 y² inside and a second parabola
  // outside, continuous with its slope. Reference: I from S written in closed form, integrated
  // by a 10⁶-point midpoint rule on θ (independent of the library's S, its quadrature and its
  // turning points); tolerance 1e-5 relative (the midpoint rule's error on the kink at |y| = b).
  const double l1 = 0.05, l2 = 0.4, b = 3 * mm, A = 5 * mm;
  auto S = [&](double y) {
    const double u = std::fabs(y);
    return u <= b ? l1 * u * u : l1 * b * b + 2 * l1 * b * (u - b) + l2 * (u - b) * (u - b);
  };
  double I = 0;
  const int N = 1000000;
  for (int i = 0; i < N; ++i) {
    const double th = -M_PI / 2 + M_PI * (i + 0.5) / N;
    I += A * std::cos(th) / std::sqrt(S(A) - S(A * std::sin(th))) * (M_PI / N);
  }
  const double ref = M_PI * M_PI / (I * I);
  std::vector<double> ys, dr;
  for (int k = -800; k <= 800; ++k) {
    const double y = k / 100.0 * mm, u = std::fabs(y);
    ys.push_back(y);
    dr.push_back(u <= b ? 2 * l1 * y : std::copysign(2 * l1 * b + 2 * l2 * (u - b), y));
  }
  CHECK(mh::EquivalentConicity(ys, dr).at(A).tan_gamma_e == Approx(ref).epsilon(1e-5));
}

TEST_CASE("conicity of a rough measured Δr against 30-digit quadrature", "[wheelset][conicity]") {
  // Δr of a measured MiniProf wheel on EN 15302 rail A (801 rows, 0.02 mm: a kink at every row)
  // and tan γe at its 33 amplitudes (an oscillation exists at each), by scripts/conicity_reference.py (mpmath, 30 digits: its own S,
  // turning points and tanh–sinh on every table interval; tests/data/conicity/README.md).
  // Tolerance 1e-7 relative: the goal of I is 1e-7 (tan γe 2e-7), met here with a factor 5 to
  // spare; the adaptive rule over the whole θ range at once missed it (1.9e-7 at 1.8 mm).
  const Table D = read_table("mbench_s1002_v3_rail_a_delta_r.csv", "conicity");
  std::vector<double> ys, dr;
  for (std::size_t i = 0; i < D.x.size(); ++i) ys.push_back(D.x[i] * mm), dr.push_back(D.v[i] * mm);
  const mh::EquivalentConicity C(ys, dr);
  // amplitude_mm, tan_gamma_e, well_posed (S below S(y2) between the turning points: all 33).
  const auto R = read_columns("mbench_s1002_v3_rail_a_conicity.csv", "conicity", 3);
  Table K;
  for (std::size_t i = 0; i < R[0].size(); ++i)
    if (R[2][i] != 0) K.x.push_back(R[0][i]), K.v.push_back(R[1][i]);
  REQUIRE(K.x.size() == 33);
  for (std::size_t i = 0; i < K.x.size(); ++i) {
    INFO("amplitude " << K.x[i] << " mm");
    const mh::ConicityResult c = C.at(K.x[i] * mm);
    REQUIRE(c.status == "ok");
    CHECK(std::fabs(c.tan_gamma_e / K.v[i] - 1) <= 1e-7);
  }
}

TEST_CASE("EN 15302 wheel A on rail A: Δr and tan γe reproduce the standard's tables", "[wheelset][en15302]") {
  // Reference: tests/data/en15302/ (EN 15302:2021 J.2 and K.2 via rohrbecka/EN15302). The tables
  // print 3 decimals (rounding ±0.0005). Targets: Δr within 0.005 mm where the
  // table's Δr changes by less than 1 mm per mm of y; tan γe within 0.005 where the table's
  // changes by less than 0.1 per mm of amplitude, inside the standard's window ± min(0.05,
  // 0.5 tan γe) elsewhere. Steep Δr (the flange root, |y| ≥ 6.2 mm) is held to 0.05 mm.
  const Profile w = mh::make_standard_profile("EN15302-wheel-A");
  const Profile r = mh::make_standard_profile("EN15302-rail-A");
  const mh::Wheelset ws(w, w, r, r, en15302_placement());
  // The gauge of the reference placement (README): 1435.164 mm.
  CHECK(ws.measured_gauge() / mm == Approx(1435.164).margin(0.002));
  const std::vector<double> ys = sweep_y();
  const std::vector<mh::WheelsetState> st = ws.sweep(ys);
  std::vector<double> dr;
  for (const auto& s : st) {
    REQUIRE(s.found);
    CHECK(!s.left.off_profile);
    CHECK(!s.right.off_profile);
    dr.push_back(s.delta_r());
  }

  const Table T = read_table("wheelA_railA_delta_r.csv");
  REQUIRE(T.x.size() == 137);
  double worst_flat = 0, worst_steep = 0;
  for (std::size_t i = 0; i < T.x.size(); ++i) {
    const std::size_t k = static_cast<std::size_t>(std::lround(T.x[i] * 100) + 800);
    REQUIRE(ys[k] / mm == Approx(T.x[i]).margin(1e-12));
    const double dev = std::fabs(dr[k] / mm - T.v[i]);
    const bool flat = table_slope(T, i) < 1.0;
    CAPTURE(T.x[i], T.v[i], dr[k] / mm, flat);
    CHECK(dev <= (flat ? 0.005 : 0.05));
    (flat ? worst_flat : worst_steep) = std::max(flat ? worst_flat : worst_steep, dev);
    // Antisymmetry of the symmetric pair: Δr(−y) = −Δr(y) (1e-9 mm).
    CHECK(dr[k] + dr[1600 - k] == Approx(0).margin(1e-9 * mm));
  }
  WARN("EN 15302 Δr: worst deviation " << worst_flat << " mm (flat), " << worst_steep << " mm (steep)");

  const mh::EquivalentConicity C(ys, dr);
  const Table K = read_table("wheelA_railA_conicity.csv");
  REQUIRE(K.x.size() == 33);
  double worst = 0;
  for (std::size_t i = 0; i < K.x.size(); ++i) {
    const mh::ConicityResult c = C.at(K.x[i] * mm);
    CAPTURE(K.x[i], K.v[i], c.tan_gamma_e);
    REQUIRE(c.status == "ok");
    const double dev = std::fabs(c.tan_gamma_e - K.v[i]);
    CHECK(dev <= (table_slope(K, i) < 0.1 ? 0.005 : mh::en15302_window(K.v[i])));
    worst = std::max(worst, dev);
    CHECK(c.y1 == Approx(-K.x[i] * mm).margin(1e-9));  // symmetric pair
  }
  WARN("EN 15302 tan γe: worst deviation " << worst);
}

TEST_CASE("placement by gauge equals the absolute placement it implies, one profile mirrored", "[wheelset]") {
  const Profile w = mh::make_standard_profile("EN15302-wheel-A");
  const Profile r = mh::make_standard_profile("EN15302-rail-A");
  const mh::Wheelset ref(w, w, r, r, en15302_placement());
  mh::WheelsetPlacement P;  // by gauge: the reference placement's own gauge
  P.gauge = ref.measured_gauge();
  const Profile w2 = w, r2 = r;  // distinct objects: smoothed twice, same numbers
  const mh::Wheelset g(w, w2, r, r2, P);
  CHECK(g.rail_origin(+1) / mm == Approx(750).margin(1e-9));
  for (double y_mm : {-6.5, -3.0, 0.0, 2.2, 5.9}) {
    const mh::WheelsetState a = ref.at(y_mm * mm), b = g.at(y_mm * mm);
    CHECK(b.delta_r() == Approx(a.delta_r()).margin(1e-9 * mm));
  }
  // The standard gauge 1435.000 moves the rails 0.082 mm inwards: Δr changes by 0.02–0.13 mm
  // (README), not nothing.
  P.gauge = 1.435;
  const mh::Wheelset s(w, w, r, r, P);
  CHECK(std::fabs(s.at(3 * mm).delta_r() - ref.at(3 * mm).delta_r()) > 0.01 * mm);
}

TEST_CASE("solved roll: both wheels touch at one axle height, none and solved agree at y = 0", "[wheelset][roll]") {
  const Profile w = mh::make_standard_profile("EN15302-wheel-A");
  const Profile r = mh::make_standard_profile("EN15302-rail-A");
  mh::WheelsetOptions o;
  o.roll = mh::WheelsetRoll::Solved;
  const mh::Wheelset solved(w, w, r, r, en15302_placement(), o);
  const mh::Wheelset none(w, w, r, r, en15302_placement());
  const mh::WheelsetState s0 = solved.at(0), n0 = none.at(0);
  REQUIRE(s0.converged);
  CHECK(s0.roll == Approx(0).margin(1e-12));
  CHECK(s0.delta_r() == Approx(n0.delta_r()).margin(1e-9 * mm));
  for (double y_mm : {-5.0, 2.0, 4.0}) {
    CAPTURE(y_mm);
    const mh::WheelsetState s = solved.at(y_mm * mm);
    REQUIRE(s.converged);
    CHECK(s.left.h == Approx(s.right.h).margin(1e-9));  // one axle height (1 nm)
    // First order from the unrolled state (docs/wheelset.md "Roll"): rolling by φ raises the
    // right wheel's contact by (a − R0 tan γ_R) φ and lowers the left one's by (a − R0 tan γ_L) φ
    // (a = 750 mm, R0 = 460 mm; the wheel's lateral shift R0 φ climbs the rail's slope), so
    // φ ≈ (h_R − h_L) / (2a − R0 (tan γ_R + tan γ_L)), h the axle heights without roll. Not
    // Δr / 2a: h_R − h_L = ∫ Δtan γ dy is far smaller than Δr on curved profiles. 10 %.
    const mh::WheelsetState n = none.at(y_mm * mm);
    const double phi1 = (n.right.h - n.left.h) /
                        (1500 * mm - 460 * mm * (std::tan(n.right.gamma) + std::tan(n.left.gamma)));
    CHECK(s.roll * y_mm > 0);  // y > 0 lifts the right end of the axle
    CHECK(s.roll == Approx(phi1).epsilon(0.1));
  }
  // Asymmetric wheels (EN 15302: 920 and 918 mm): at y = 0 the right wheel is 1 mm smaller, the
  // axle's right end is lower, and Δr(0) = −1 mm without roll.
  mh::WheelsetPlacement P = en15302_placement();
  P.nominal_radius_right = 459 * mm;
  const mh::Wheelset asym_none(w, w, r, r, P), asym(w, w, r, r, P, o);
  CHECK(asym_none.at(0).delta_r() / mm == Approx(-1.0).margin(1e-9));
  const mh::WheelsetState a0 = asym.at(0), n0a = asym_none.at(0);
  CHECK(a0.roll < 0);
  CHECK(a0.roll == Approx(-1 * mm / (1500 * mm - 460 * mm * (std::tan(n0a.right.gamma) + std::tan(n0a.left.gamma))))
                       .epsilon(0.1));
}

TEST_CASE("wheelset input errors name the profile and the rule", "[wheelset]") {
  const Profile w = mh::make_standard_profile("EN15302-wheel-A");
  Profile r = mh::make_standard_profile("EN15302-rail-A");
  // A rail cut above the gauge height has no gauge point: placement by gauge is refused.
  Profile cut = r;
  cut.y.clear();
  cut.z.clear();
  for (std::size_t i = 0; i < r.size(); ++i)
    if (r.z[i] > -5 * mm) cut.y.push_back(r.y[i]), cut.z.push_back(r.z[i]);
  try {
    mh::Wheelset(w, w, cut, cut, mh::WheelsetPlacement{});
    FAIL("no exception");
  } catch (const mh::InputError& e) {
    CHECK(std::string(e.what()).find("no gauge point found 14 mm below the top") != std::string::npos);
  }
  // A wheel that does not reach its taping line.
  Profile half = w;
  half.y.resize(500);
  half.z.resize(500);
  REQUIRE(half.y.back() < 0);
  REQUIRE_THROWS_AS(mh::Wheelset(half, half, r, r, en15302_placement()), mh::InputError);
  mh::WheelsetOptions o;
  o.scan_step = 0;
  REQUIRE_THROWS_AS(mh::Wheelset(w, w, r, r, en15302_placement(), o), mh::InputError);
}
