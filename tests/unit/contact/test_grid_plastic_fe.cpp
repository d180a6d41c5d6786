// The grid methods' answer from a yield stress alone — the pressure capped at
// p_lim = kPlimPerYield σ_y (lib/contact/options.hpp, docs/method.md §5.1) — against the project's
// own elastic–perfectly-plastic 3-D FE tables (tests/data/fe/ellip3d_*_sy*.csv, made by
// scripts/fe/ellip3d.py; what was validated and to what accuracy: scripts/fe/README.md).
//
// The FE pair: E = 210 GPa, ν = 0.3 for both bodies, the gap A x² + B y² of the principal relative
// radii Rw (rolling, x) × Rr (transverse, y) on each table's '# case' line (A = 1/(2 Rw),
// B = 1/(2 Rr)), the load N of each row. The same gap on a grid of boundary elements, solved by
// the capped constrained-CG solver (lib/contact/half_space/normal_cg.hpp, load control), and on
// lateral strips by the strip solver (lib/contact/strips/strip_patch.hpp): area (contact elements
// × element area; the strips' Σ 2 a_i ds), approach, peak and mean pressure against the FE rows.
// The closed-form Hertz at the load (tests/support/hertz_reference.hpp) only scales the grids.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "contact/half_space/influence.hpp"
#include "contact/half_space/normal_cg.hpp"
#include "contact/options.hpp"
#include "contact/strips/strip_patch.hpp"
#include "output/csv_table.hpp"
#include "support/fe_table.hpp"
#include "support/hertz_reference.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 210e9, kNu = 0.3;                          // the FE's material, both bodies
const double kH = 2 * (1 - kNu * kNu) / (kPi * kE);               // [1/Pa] the grid solvers' compliance of the pair
const double kEstarJ = mh::testing::johnson_modulus(kE, kNu, kE, kNu);  // [Pa] the Hertz reference's

/// A plastic FE table and its shape: the pair's curvature sums [1/m], A along the rolling
/// direction (x), B across it (y), from the table's '# case' line.
struct FeShape {
  const char* table;
  const char* name;
  double A, B;
};
const FeShape kShapes[] = {
    {"ellip3d_R460x300_sy350.csv", "R 460 x 300", 1 / (2 * 0.460), 1 / (2 * 0.300)},
    {"ellip3d_R460x300_sy500.csv", "R 460 x 300", 1 / (2 * 0.460), 1 / (2 * 0.300)},
    {"ellip3d_R460x15_sy350.csv", "R 460 x 15", 1 / (2 * 0.460), 1 / (2 * 0.015)},
    {"ellip3d_R460x3000_sy350.csv", "R 460 x 3000", 1 / (2 * 0.460), 1 / (2 * 3.000)},
};

/// What a grid solver gives for one row.
struct GridAnswer {
  bool ok = false;
  double area = 0;    ///< [m²]
  double delta = 0;   ///< [m] approach of the pair
  double p_max = 0;   ///< [Pa]
  double p_mean = 0;  ///< [Pa] N / area
  double frac_plastic = 0;  ///< share of the contact area at p_lim
};

/// The capped half-space solution of the gap A x² + B y² under N, p ≤ p_lim, on elements of
/// a_el/n × b_el/n (a_el, b_el: Hertz at N), over ±1.6 a_el × ±1.6 b_el (the capped patch grows
/// by √(area ratio) ≤ 1.2 here), an element centred on the origin. ok: converged and no pressure
/// on the grid's boundary.
GridAnswer half_space_capped(double A, double B, double N, double p_lim, int n) {
  const mh::testing::HertzReference hz = mh::testing::hertz_reference(A, B, N, kEstarJ);
  const double dx = hz.a / n, dy = hz.b / n;
  const int half = static_cast<int>(std::ceil(1.6 * n));
  const int nx = 2 * half + 1, ny = 2 * half + 1;
  std::vector<double> g(static_cast<std::size_t>(nx) * ny), p(g.size(), 0.0);
  for (int iy = 0; iy < ny; ++iy)
    for (int ix = 0; ix < nx; ++ix) {
      const double x = (ix - half) * dx, y = (iy - half) * dy;
      g[static_cast<std::size_t>(ix + nx * iy)] = A * x * x + B * y * y;
    }
  const mh::InfluenceGrid C(nx, ny, dx, dy, kH);
  mh::NormalCGOptions opt;
  opt.max_iterations = 20000;
  const mh::NormalCGResult r = mh::solve_normal_load(C, g.data(), N, p_lim, p.data(), opt);
  GridAnswer out;
  bool edge_free = true;
  double p_max = 0;
  for (int iy = 0; iy < ny; ++iy)
    for (int ix = 0; ix < nx; ++ix) {
      const double pe = p[static_cast<std::size_t>(ix + nx * iy)];
      p_max = std::max(p_max, pe);
      if (pe > 0 && (ix == 0 || iy == 0 || ix == nx - 1 || iy == ny - 1)) edge_free = false;
    }
  out.ok = r.status == mh::GridStatus::Ok && edge_free;
  out.area = r.n_contact * dx * dy;
  out.delta = r.delta;
  out.p_max = p_max;
  out.p_mean = N / out.area;
  out.frac_plastic = r.n_contact > 0 ? static_cast<double>(r.n_plastic) / r.n_contact : 0;
  return out;
}

/// The strip solution of the same gap: lateral strips of width b_el/n along y, each a
/// (capped) semi-ellipse along x (docs/method.md §9), default StripOptions.
GridAnswer strips_capped(double A, double B, double N, double p_lim, int n) {
  const mh::testing::HertzReference hz = mh::testing::hertz_reference(A, B, N, kEstarJ);
  mh::StripGeometry geo;
  geo.ds = hz.b / n;
  const int half = static_cast<int>(std::ceil(1.6 * n));
  for (int i = -half; i <= half; ++i) {
    const double s = i * geo.ds;
    geo.s.push_back(s);
    geo.g.push_back(B * s * s);
    geo.A.push_back(A);
    geo.xc.push_back(0.0);
  }
  const mh::StripResult r = mh::solve_strips_load(geo, kH, N, p_lim);
  GridAnswer out;
  out.ok = r.status == mh::StripStatus::Ok && !r.strips.empty() && r.strips.front().index > 0 &&
           r.strips.back().index < static_cast<int>(geo.s.size()) - 1;
  out.area = r.area;
  out.delta = r.delta;
  out.p_max = r.pmax;
  out.p_mean = N / r.area;
  double plastic = 0;
  for (const auto& st : r.strips) plastic += st.plastic ? 2 * st.a * geo.ds : 0;
  out.frac_plastic = r.area > 0 ? plastic / r.area : 0;
  return out;
}

/// One FE row and the grid answer at its load: the ratios the tables of method.md §5.1 show.
struct Compared {
  double p0el_sy, area_dev, delta_dev;  // p0_el/σ_y; grid/FE − 1 of area and approach
};
Compared compare(const mh::CsvTable& t, std::size_t i, const GridAnswer& s) {
  using mh::testing::fe_num;
  return {fe_num(t, i, "p0el_over_sy"), s.area * 1e6 / fe_num(t, i, "area_mm2") - 1,
          s.delta * 1e3 / fe_num(t, i, "delta_mm") - 1};
}

/// p_lim = c σ_y of a row (c = kPlimPerYield: the grid methods' cap from a yield stress).
double p_lim_of_row(const mh::CsvTable& t, std::size_t i, double c) {
  return c * mh::testing::fe_num(t, i, "sigma_y_MPa") * 1e6;
}

}  // namespace

// The measured comparison of docs/method.md §5.1 (the grid methods from a yield stress): every row
// of the four plastic FE tables, the capped half-space on two grids (n = 20, 40 and 64 elements per
// elastic semi-axis) and the strips (the same n of strips per elastic lateral semi-axis). Prints
// the table; checks only that every solve converged. Hidden (it takes minutes); run with
//   build/tests/mhcontact_tests "[grid_fe_table]"
// and, for another cap c σ_y, MHCONTACT_PLIM_PER_YIELD=c in the environment.
TEST_CASE("grid methods capped at kPlimPerYield sigma_y against the 3-D FE tables: the measured table",
          "[.][grid_fe_table]") {
  double c = mh::kPlimPerYield;
  if (const char* e = std::getenv("MHCONTACT_PLIM_PER_YIELD")) c = std::stod(e);
  std::printf("p_lim = %.3g sigma_y\n", c);
  std::printf("shape | p0el/sy | FE area/el | FE d/d_el | FE pmax/sy | FE pmean/sy | method n | pmax/sy | pmean/sy | "
              "area/el | d/d_el | plastic share | area/FE | d/FE\n");
  for (const FeShape& f : kShapes) {
    const mh::CsvTable t = mh::testing::read_fe_table(f.table);
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      using mh::testing::fe_num;
      const double sy = fe_num(t, i, "sigma_y_MPa") * 1e6, N = fe_num(t, i, "N_N");
      const double area_el = kPi * fe_num(t, i, "a_el_mm") * fe_num(t, i, "b_el_mm") * 1e-6;
      const double delta_el = fe_num(t, i, "delta_el_mm") * 1e-3;
      for (int method = 0; method < 2; ++method)
        for (int n : {20, 40, 64}) {
          const GridAnswer s = method == 0 ? half_space_capped(f.A, f.B, N, p_lim_of_row(t, i, c), n)
                                           : strips_capped(f.A, f.B, N, p_lim_of_row(t, i, c), n);
          const Compared d = compare(t, i, s);
          std::printf("%s (%s) | %.2f | %.3f | %.3f | %.2f | %.2f | %s %d | %.2f | %.2f | %.3f | %.3f | %.2f | %+.1f %% | "
                      "%+.1f %%%s\n",
                      f.name, f.table, d.p0el_sy, fe_num(t, i, "area_mm2") * 1e-6 / area_el,
                      fe_num(t, i, "delta_mm") * 1e-3 / delta_el, fe_num(t, i, "pmax_MPa") * 1e6 / sy,
                      fe_num(t, i, "pmean_MPa") * 1e6 / sy, method == 0 ? "half-space" : "strips", n,
                      s.p_max / sy, s.p_mean / sy, s.area / area_el, s.delta / delta_el, s.frac_plastic,
                      100 * d.area_dev, 100 * d.delta_dev, s.ok ? "" : "  NOT OK");
          std::fflush(stdout);
          CHECK(s.ok);
        }
    }
  }
}

TEST_CASE("capped half-space (p_lim = kPlimPerYield sigma_y) against the 3-D FE tables: the deviations method.md §5.1 states",
          "[half_space][plastic][fe]") {
  // What the half-space method gives from a yield stress alone (cap 2.1 σ_y), at each FE row's
  // load, against the FE area π a b and block-corrected approach (docs/method.md §5.1, measured on
  // n = 40 and 64 elements per elastic semi-axis by the hidden table above: the two grids within
  // 0.4 % in area and 0.1 % in approach). Here n = 20 for speed (1 s): measured within 1.0 % in
  // area (biased high: fewer, larger edge elements) and 0.1 % in approach of n = 64; each band
  // spans the n = 20 and n = 64 values with 1 % of room.
  // Rows below the cap (p0_el/σ_y ≤ 2.1, elastic in the solver): within the 5 % aim (measured
  // area −3.4 … −0.6 %, approach −0.6 … +0.1 %). Capped rows: a KNOWN LIMIT, held at its measured
  // size, not tuned away: the area is 7 … 12 % smaller than the FE's (R 460 × 300: −8.0, −12.1,
  // −10.2, −6.4 % at p0_el/σ_y = 2.53, 2.99, 3.44, 3.88; flange −6.8 % at 2.99; conformal −8.1,
  // −8.3 % at 2.99, 3.88), the approach within 2 % (−2.0 … +0.2 %). Cause: a cap truncates at 2.1 σ_y
  // and is elastic below it, while the FE pressure is flattened from first yield (p0 ≈ 1.6 σ_y)
  // on, its peak saturating at 2.1–2.3 σ_y: the same peak on a larger patch (FE p_mean 1.63 σ_y
  // at 2.99 against the cap's 1.85). The flange row at 3.90 (added with the FE's p0_el/σ_y 1.5 and
  // 3.9 rows): area −3.1 % (n = 20), −3.5 % (n = 40), approach +0.7 %; there the FE's b edge is
  // clipped at its last closed node, a lower bound of its area (scripts/fe/README.md), so the
  // flange band reaches −2.1 %.
  struct Band {
    const char* table;
    double area_lo, area_hi, approach_lo, approach_hi;
  };
  const Band bands[] = {{"ellip3d_R460x300_sy350.csv", -0.131, -0.049, -0.030, 0.006},
                        {"ellip3d_R460x300_sy500.csv", -0.088, -0.056, -0.028, -0.008},
                        {"ellip3d_R460x15_sy350.csv", -0.078, -0.021, -0.017, 0.017},
                        {"ellip3d_R460x3000_sy350.csv", -0.093, -0.062, -0.023, 0.012}};
  for (const FeShape& f : kShapes) {
    const Band* band = nullptr;
    for (const Band& b : bands)
      if (std::string(b.table) == f.table) band = &b;
    REQUIRE(band != nullptr);
    const mh::CsvTable t = mh::testing::read_fe_table(f.table);
    REQUIRE(t.rows.size() >= 2);
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const double N = mh::testing::fe_num(t, i, "N_N");
      const GridAnswer s = half_space_capped(f.A, f.B, N, p_lim_of_row(t, i, mh::kPlimPerYield), 20);
      const Compared d = compare(t, i, s);
      CAPTURE(f.table, i, d.p0el_sy, d.area_dev, d.delta_dev, s.p_max, s.frac_plastic);
      REQUIRE(s.ok);
      if (d.p0el_sy <= mh::kPlimPerYield) {
        CHECK(s.frac_plastic == 0);
        CHECK(std::fabs(d.area_dev) <= 0.05);
        CHECK(std::fabs(d.delta_dev) <= 0.05);
      } else {
        CHECK(d.area_dev >= band->area_lo);
        CHECK(d.area_dev <= band->area_hi);
        CHECK(d.delta_dev >= band->approach_lo);
        CHECK(d.delta_dev <= band->approach_hi);
      }
    }
  }
}
