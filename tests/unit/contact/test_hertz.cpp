// One Hertzian ellipse (hertz.hpp, ellipse_law.hpp) and `mhcontact hertz`. Each block names
// its source and its tolerance.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "contact/ellipse/ellipse_law.hpp"
#include "core/numfmt.hpp"
#include "support/hertz_reference.hpp"

using namespace mh;

namespace {

double rel(double x, double ref) { return std::fabs(x / ref - 1.0); }

struct CliRun {
  int code;
  std::string out, err;
};
CliRun run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = run_cli(args, out, err);
  return {code, out.str(), err.str()};
}
}  // namespace

TEST_CASE("Hertz m, n: reference values of method.md §2", "[hertz]") {
  // Source: method.md §2 table (4 decimals). Tolerance 5e-4 absolute, both paths.
  struct Row { double lambda, m, n; };
  const Row rows[] = {{0.1, 2.3905, 0.5313}, {0.5, 1.2758, 0.8045}, {1, 1, 1},
                      {2, 0.8045, 1.2758}, {10, 0.5313, 2.3905}};
  for (const Row& r : rows) {
    CAPTURE(r.lambda);
    for (bool fast : {false, true}) {
      CAPTURE(fast);
      const HertzCoefficients c = fast ? hertz_coefficients(r.lambda) : hertz_coefficients_exact(r.lambda);
      CHECK(c.lambda == r.lambda);
      CHECK(c.m == Approx(r.m).margin(5e-4));
      CHECK(c.n == Approx(r.n).margin(5e-4));
    }
  }
}

TEST_CASE("Hertz coefficients exact at λ = 1 and continuous across it", "[hertz]") {
  // Circle: m = n = ρ = 1 (method.md §2), to 1e-12, both paths.
  for (const HertzCoefficients& c : {hertz_coefficients_exact(1.0), hertz_coefficients(1.0)}) {
    CHECK(std::fabs(c.m - 1) <= 1e-12);
    CHECK(std::fabs(c.n - 1) <= 1e-12);
    CHECK(std::fabs(c.rho - 1) <= 1e-12);
  }
  // Continuity and smoothness across λ = 1 (the coefficients are analytic there; the code swaps
  // the axes at λ = 1): the one-sided slopes dm/dλ from the left and from the right agree, for
  // ε from 1e-3 down to 1e-9, to 1e-6 + 2ε (truncation O(ε) plus rounding O(1e-16/ε)).
  for (double eps : {1e-3, 1e-5, 1e-7, 1e-9}) {
    CAPTURE(eps);
    const HertzCoefficients lo = hertz_coefficients_exact(1 - eps), hi = hertz_coefficients_exact(1 + eps);
    const double sl_m = (1 - lo.m) / eps, sr_m = (hi.m - 1) / eps;
    const double sl_n = (1 - lo.n) / eps, sr_n = (hi.n - 1) / eps;
    CHECK(std::fabs(sl_m - sr_m) <= 1e-6 + 2 * eps);
    CHECK(std::fabs(sl_n - sr_n) <= 1e-6 + 2 * eps);
    CHECK(std::fabs(lo.rho - 1) <= 2 * eps);  // ρ even in ln λ: 1 + O(ε²)
    CHECK(std::fabs(hi.rho - 1) <= 2 * eps);
  }
}

TEST_CASE("Hertz coefficients: symmetry m(λ) = n(1/λ) over 1e-4 … 1e4", "[hertz]") {
  // method.md §2: swapping the axes swaps m and n; ρ is the same. Tolerance 1e-12 relative.
  for (int i = 0; i <= 160; ++i) {
    const double l = std::pow(10.0, -4.0 + 0.05 * i);
    CAPTURE(l);
    for (bool fast : {false, true}) {
      const HertzCoefficients a = fast ? hertz_coefficients(l) : hertz_coefficients_exact(l);
      const HertzCoefficients b = fast ? hertz_coefficients(1 / l) : hertz_coefficients_exact(1 / l);
      CHECK(rel(a.m, b.n) <= 1e-12);
      CHECK(rel(a.n, b.m) <= 1e-12);
      CHECK(rel(a.rho, b.rho) <= 1e-12);
    }
  }
}

TEST_CASE("Hertz coefficients: monotone in λ, ρ largest at λ = 1", "[hertz]") {
  // a = m C shrinks and b = n C grows as the curvature along x grows (Hertz): m strictly
  // decreasing, n strictly increasing; ρ(λ) = ρ(1/λ) ≤ 1, decreasing away from λ = 1.
  HertzCoefficients prev = hertz_coefficients_exact(1e-4);
  for (int i = 1; i <= 400; ++i) {
    const double l = std::pow(10.0, -4.0 + 0.02 * i);
    CAPTURE(l);
    const HertzCoefficients c = hertz_coefficients_exact(l), f = hertz_coefficients(l);
    CHECK(c.m < prev.m);
    CHECK(c.n > prev.n);
    CHECK(c.rho <= 1 + 1e-15);
    if (l < 1) CHECK(c.rho > prev.rho);
    if (l > 1.0001) CHECK(c.rho < prev.rho);
    CHECK(f.m < hertz_coefficients(std::pow(10.0, -4.0 + 0.02 * (i - 1))).m);
    prev = c;
  }
}

TEST_CASE("Hertz exact path: m, n, ρ against the closed-form reference", "[hertz]") {
  // Independent of the Carlson form used inside: the closed-form Hertz contact of
  // tests/support/hertz_reference.hpp (Johnson §3.6, §4.2; Boost's K and D of the modulus) at
  // any load N gives m = a/C, n = b/C, ρ = δ/(C² (A+B)), with C = [3N/(4 E*_J (A+B))]^(1/3)
  // (eqs. 2–3 with E/(1−ν²) = 2 E*_J). Tolerance 3e-13 relative: measured at most 7.6e-14, at
  // the ends of the list (λ = 1e-3 and 2000), where the reference's modulus loses digits.
  const double EJ = 1e11, N = 1e4, B = 3.0;
  for (double l : {1e-3, 0.01, 0.1, 0.3, 0.5, 0.9, 1.0, 1.5, 4.0, 50.0, 2000.0}) {
    CAPTURE(l);
    const double A = l * B;
    const HertzCoefficients c = hertz_coefficients_exact(l);
    const testing::HertzReference h = testing::hertz_reference(A, B, N, EJ);
    const double C = std::cbrt(3 * N / (4 * EJ * (A + B)));
    const double w = std::max({rel(c.m, h.a / C), rel(c.n, h.b / C), rel(c.rho, h.delta / (C * C * (A + B)))});
    CHECK(w <= 3e-13);
  }
}

TEST_CASE("Hertz fast path against the exact path over 1e-4 … 1e4", "[hertz][fast]") {
  // hertz.hpp kFastPathMaxRelError: worst relative error of m, n, ρ on a dense log grid
  // (step 0.0004 decade, offset so that the points fall between the table nodes), plus the
  // ends. Outside [1e-4, 1e4] the fast path falls back to the exact one (identical results).
  double worst = 0, worst_at = 0;
  const int npts = 20000;
  for (int i = 0; i <= npts; ++i) {
    double x = -4.0 + 8.0 * i / npts + 1.234567e-5;
    if (i == npts) x = 4.0;
    const double l = std::pow(10.0, x);
    const HertzCoefficients e = hertz_coefficients_exact(l), f = hertz_coefficients(l);
    const double w = std::max({rel(f.m, e.m), rel(f.n, e.n), rel(f.rho, e.rho)});
    if (w > worst) { worst = w; worst_at = l; }
  }
  WARN("hertz fast path: worst relative error of m, n, rho over 1e-4..1e4 = " << worst << " at lambda = " << worst_at);
  // The bound at the method's accuracy: measured 4.7e-11 (at λ = 1.013, the cubic spline's
  // interpolation error between table nodes); a table half as dense (7.8e-10) or a coarser
  // interpolation exceeds it.
  CHECK(worst <= kFastPathMaxRelError);
  for (double l : {1e-5, 9.99e-5, 1.001e4, 1e6}) {
    CAPTURE(l);
    const HertzCoefficients e = hertz_coefficients_exact(l), f = hertz_coefficients(l);
    CHECK(f.m == e.m);
    CHECK(f.n == e.n);
    CHECK(f.rho == e.rho);
  }
}

TEST_CASE("sphere: closed-form Hertz", "[hertz]") {
  // Johnson, Contact Mechanics (1985) §4.2, two equal spheres of composite radius R with
  // composite modulus E*_J = E/(2(1−ν²)): a = (3NR/(4E*_J))^(1/3), p0 = 3N/(2πa²), δ = a²/R
  // (tests/support/hertz_reference.hpp); with A = B = 1/(2R), and h0 = δ/2 (method.md §2).
  // Tolerance 1e-14 relative, both paths (λ = 1 is a node of the fast path's table): measured at
  // most 1.1e-15.
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.3;
  const double EJ = testing::johnson_modulus(mat.E, mat.nu, mat.E, mat.nu);
  for (double R : {0.01, 0.1, 0.46}) {
    for (bool exact : {true, false}) {
      const EllipseLaw L = make_ellipse_law(1 / (2 * R), 1 / (2 * R), mat, exact);
      for (double N : {1.0, 5e3, 100e3}) {
        CAPTURE(R, exact, N);
        const EllipseState s = ellipse_state_for_force(L, N);
        const testing::HertzReference h = testing::hertz_reference(1 / (2 * R), 1 / (2 * R), N, EJ);
        CHECK(rel(s.a, h.a) <= 1e-14);
        CHECK(rel(s.b, h.b) <= 1e-14);
        CHECK(rel(s.p0, h.p0) <= 1e-14);
        CHECK(rel(s.p_mean, h.p_mean) <= 1e-14);
        CHECK(rel(s.approach, h.delta) <= 1e-14);
        CHECK(rel(s.h0, h.delta / 2) <= 1e-14);
        CHECK(rel(s.N, N) <= 1e-12);
        CHECK_FALSE(s.plastic);
        CHECK(s.area_ratio == 1);
      }
    }
  }
}

TEST_CASE("elliptic contact: Hertz relations of Johnson §4.2 for both orientations", "[hertz]") {
  // The closed-form Hertz contact of tests/support/hertz_reference.hpp (Johnson (1985) §3.6,
  // §4.2): a, b, p0 and the approach δ of the exact path, tolerance 5e-15 relative (measured at
  // most 6.7e-16, a few roundings). This pins the meaning of ρ for A > B (ρ(λ) = ρ(1/λ)).
  // Swapping A and B at the same load swaps a and b and leaves δ unchanged; h0 = b² B (eq. 6)
  // in both orientations (1e-12).
  Material mat;
  mat.E = 200e9;
  mat.nu = 0.25;
  const double EJ = testing::johnson_modulus(mat.E, mat.nu, mat.E, mat.nu);
  const double N = 80e3;
  for (double l : {0.02, 0.2, 0.7, 1.3, 5.0, 60.0}) {
    CAPTURE(l);
    const double B = 2.0, A = l * B;
    const EllipseState s = ellipse_state_for_force(make_ellipse_law(A, B, mat, true), N);
    const EllipseState t = ellipse_state_for_force(make_ellipse_law(B, A, mat, true), N);
    const testing::HertzReference h = testing::hertz_reference(A, B, N, EJ);
    CHECK(rel(s.a, h.a) <= 5e-15);
    CHECK(rel(s.b, h.b) <= 5e-15);
    CHECK(rel(s.p0, h.p0) <= 5e-15);
    CHECK(rel(s.approach, h.delta) <= 5e-15);
    CHECK(rel(t.a, s.b) <= 1e-12);
    CHECK(rel(t.b, s.a) <= 1e-12);
    CHECK(rel(t.approach, s.approach) <= 1e-12);
    CHECK(rel(s.h0, s.b * s.b * B) <= 1e-12);  // (eq. 6)
    CHECK(rel(t.h0, t.b * t.b * A) <= 1e-12);
  }
}

TEST_CASE("cylinder-like extreme: slender ellipse against line contact", "[hertz]") {
  // λ = 1e-6 (long along x) and 1e6 (long along y). Closed forms of the slender limit g → 0:
  // across the ellipse the section is a 2-D Hertz line contact of radius R = 1/(2 B_M), B_M =
  // max(A, B): minor semi-axis c_m = 2 R p0 / E*_J = p0/(B_M E*_J) (Johnson §4.2, cylinders: b² = 4PR/(πE*),
  // p0 = 2P/(πb)); the approach δ = (p0 c_m / E*_J) ln(4 c_M/c_m) (K(e) ≈ ln(4/g), Abramowitz &
  // Stegun 17.3.26). Both hold up to O(g² ln(1/g)) ≈ 1e-6 here: tolerance 1e-5 relative.
  Material mat;
  mat.E = 210e9;
  mat.nu = 0.3;
  const double EJ = mat.E / (2 * (1 - mat.nu * mat.nu));
  const double N = 10e3;
  for (double l : {1e-6, 1e6}) {
    CAPTURE(l);
    const double B = 1.0, A = l * B;
    for (bool exact : {true, false}) {
      const EllipseState s = ellipse_state_for_force(make_ellipse_law(A, B, mat, exact), N);
      const double cM = std::max(s.a, s.b), cm = std::min(s.a, s.b), Bm = std::max(A, B);
      CHECK(rel(cm, s.p0 / (Bm * EJ)) <= 1e-5);
      CHECK(rel(s.approach, s.p0 * cm / EJ * std::log(4 * cM / cm)) <= 1e-5);
      CHECK(cM / cm > 1000);
    }
  }
}

TEST_CASE("elastic stiffness k_e (eq. 8) is consistent with eqs. 2-3 and 6", "[hertz]") {
  // N = k_e h0^(3/2) with h0 = b² B and b = n C, C of eqs. 2–3: for any λ the state at N
  // reproduces b = n C and a = m C to 1e-12 relative (the fast path's own m, n).
  Material mat;
  for (double l : {1e-3, 0.05, 0.652, 1.0, 3.0, 700.0}) {
    CAPTURE(l);
    const double B = 1.7, A = l * B, N = 123e3;
    const EllipseLaw L = make_ellipse_law(A, B, mat);
    const EllipseState s = ellipse_state_for_force(L, N);
    const double C = hertz_C(N, A, B, mat.E_star());
    CHECK(rel(s.a, L.c.m * C) <= 1e-12);
    CHECK(rel(s.b, L.c.n * C) <= 1e-12);
    CHECK(rel(L.force(s.h0), N) <= 1e-12);
    CHECK(rel(L.h0_for_force(L.force(1e-4)), 1e-4) <= 1e-12);
    double d = 0;
    L.force(1e-4, &d);
    CHECK(rel(d, 1.5 * L.k_e * 1e-2) <= 1e-12);  // dN/dh0 = (3/2) k_e √h0
  }
}

TEST_CASE("zero and negative penetration carry nothing", "[hertz]") {
  const EllipseLaw L = make_ellipse_law(1.0, 2.0, Material{});
  double d = 1;
  CHECK(L.force(0.0, &d) == 0);
  CHECK(d == 0);
  CHECK(L.force(-1e-5, &d) == 0);
  CHECK(L.force(std::nan(""), &d) == 0);
  CHECK(L.h0_for_force(0.0) == 0);
  CHECK_THROWS_AS(L.h0_for_force(-1.0), std::invalid_argument);
  const EllipseState s = ellipse_state(L, -1e-6);
  CHECK(s.N == 0);
  CHECK(s.a == 0);
  CHECK(s.p0 == 0);
  CHECK_THROWS_AS(ellipse_state(L, INFINITY), std::invalid_argument);
}

TEST_CASE("non-Hertzian and invalid inputs are refused with the rule", "[hertz]") {
  Material mat;
  CHECK_THROWS_WITH(make_ellipse_law(1, -0.5, mat), Catch::Contains("B = -0.5 1/m") && Catch::Contains("conformal"));
  CHECK_THROWS_WITH(make_ellipse_law(1, 0, mat), Catch::Contains("B = 0 1/m"));
  CHECK_THROWS_WITH(make_ellipse_law(-1, 1, mat), Catch::Contains("A = -1 1/m"));
  CHECK_THROWS_WITH(make_ellipse_law(0, 1, mat), Catch::Contains("line contact"));
  CHECK_THROWS_WITH(make_ellipse_law(1e-12, 1, mat), Catch::Contains("outside the supported range"));
  Material bad = mat;
  bad.nu = 0.5;
  CHECK_THROWS_WITH(make_ellipse_law(1, 1, bad), Catch::Contains("nu = 0.5"));
  bad = mat;
  bad.E = 0;
  CHECK_THROWS_WITH(make_ellipse_law(1, 1, bad), Catch::Contains("E = 0"));
  bad = mat;
  bad.p_lim = -5;
  CHECK_THROWS_WITH(make_ellipse_law(1, 1, bad), Catch::Contains("p_lim = -5"));
  CHECK_THROWS_AS(hertz_coefficients(-1.0), std::invalid_argument);
  CHECK_THROWS_AS(hertz_coefficients_exact(std::nan("")), std::invalid_argument);
  std::string why;
  CHECK(mat.valid(&why));
  CHECK_FALSE(bad.valid(&why));
  CHECK(why.find("p_lim") != std::string::npos);
}

// ---- `mhcontact hertz` ------------------------------------------------------------------------

TEST_CASE("cli hertz: worked example of method.md §5, JSON", "[hertz][cli]") {
  // README example. Source: method.md §5; tolerances: the printed digits (± half a unit).
  const CliRun r = run({"hertz", "--R-wyy", "460", "--R-rxx", "300", "--N", "100", "--E", "210",
                        "--nu", "0.3", "--p-lim", "800", "--json"});
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j.at("schema") == "mhcontact.hertz/1");
  CHECK(j.at("lambda").get<double>() == Approx(300.0 / 460.0).epsilon(1e-15));
  CHECK(j.at("a_el_mm").get<double>() == Approx(7.162).margin(5e-4));
  CHECK(j.at("b_el_mm").get<double>() == Approx(5.387).margin(5e-4));
  CHECK(j.at("h_y_mm").get<double>() == Approx(0.02021).margin(5e-6));
  CHECK(j.at("N_y_kN").get<double>() == Approx(27.0).margin(0.05));
  CHECK(j.at("a_mm").get<double>() == Approx(7.748).margin(5e-4));
  CHECK(j.at("b_mm").get<double>() == Approx(5.829).margin(5e-4));
  CHECK(j.at("area_ratio").get<double>() == Approx(1.171).margin(5e-4));
  CHECK(j.at("p_max_MPa").get<double>() == 800);
  CHECK(j.at("plastic").get<bool>());
  for (const char* k : {"m", "n", "p0_MPa", "pmean_MPa", "h0_mm", "approach_mm", "plateau_a_mm", "plateau_b_mm"})
    CHECK(j.contains(k));
}

TEST_CASE("cli hertz: elastic text output, --A/--B and the radii give the same", "[hertz][cli]") {
  // README example: the elastic ellipse of the worked example (method.md §5: a = 7.162 mm,
  // b = 5.387 mm, p0 = 1238 MPa). A = 1/(2·460) 1/mm, B = 1/(2·300) 1/mm.
  const CliRun r = run({"hertz", "--R-wyy", "460", "--R-rxx", "300", "--N", "100", "--E", "210", "--nu", "0.3"});
  REQUIRE(r.code == 0);
  auto value = [&](const std::string& name, const std::string& unit) {
    const std::string key = "\n" + name + " = ";
    const std::size_t p = ("\n" + r.out).find(key);
    REQUIRE(p != std::string::npos);
    const std::size_t e = ("\n" + r.out).find('\n', p + 1);
    const std::string line = ("\n" + r.out).substr(p + key.size(), e - p - key.size());
    CHECK(line.substr(line.rfind(' ') + 1) == unit);
    return std::stod(line);
  };
  CHECK(value("a", "mm") == Approx(7.162).margin(5e-4));
  CHECK(value("b", "mm") == Approx(5.387).margin(5e-4));
  CHECK(value("p0", "MPa") == Approx(1238).margin(0.5));
  CHECK(value("lambda", "-") == Approx(300.0 / 460.0));
  const double h0 = value("h0", "mm"), delta = value("approach", "mm");
  CHECK(delta > h0);
  CHECK(r.out.find("plastic") == std::string::npos);
  const CliRun q = run({"hertz", "--A", format_number(1.0 / 920), "--B", format_number(1.0 / 600), "--N", "100",
                        "--E", "210", "--nu", "0.3"});
  REQUIRE(q.code == 0);
  CHECK(q.out == r.out);
}

TEST_CASE("cli hertz: invalid values exit 2 naming the option and value", "[hertz][cli]") {
  struct Case { std::vector<std::string> args; std::string must_contain; };
  const std::vector<std::string> mat = {"--N", "100", "--E", "210", "--nu", "0.3"};
  const Case cases[] = {
      {{"--A", "0.001", "--B", "-0.5"}, "--B: value -0.5"},
      {{"--A", "-0.001", "--B", "0.5"}, "--A: value -0.001"},
      {{"--R-wyy", "460", "--R-rxx", "-300"}, "B = -0.00166"},
      {{"--R-wyy", "460", "--R-rxx", "300", "--R-wxx", "-300"}, "B = 0 1/mm"},
      {{"--R-wyy", "460"}, "--R-wxx/--R-rxx"},
      {{"--R-wyy", "-460", "--R-rxx", "300"}, "--R-wyy: value -460"},
      {{"--R-wyy", "460", "--R-rxx", "0"}, "--R-rxx: value 0"},
      {{"--R-rxx", "300"}, "--R-wyy"},
      {{}, "give the curvature sums"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"hertz"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.insert(args.end(), mat.begin(), mat.end());
    CAPTURE(args);
    const CliRun r = run(args);
    CHECK(r.code == 2);
    CHECK(r.err.find(c.must_contain) != std::string::npos);
    CHECK(r.out.empty());
  }
  const std::vector<std::string> geo = {"hertz", "--R-wyy", "460", "--R-rxx", "300"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = geo;
    a.insert(a.end(), extra.begin(), extra.end());
    return run(a);
  };
  CHECK(with({"--N", "-1", "--E", "210", "--nu", "0.3"}).err.find("--N: value -1") != std::string::npos);
  CHECK(with({"--N", "1", "--E", "0", "--nu", "0.3"}).err.find("--E: value 0") != std::string::npos);
  CHECK(with({"--N", "1", "--E", "210", "--nu", "0.5"}).err.find("--nu: value 0.5") != std::string::npos);
  CHECK(with({"--N", "1", "--E", "210", "--nu", "0.3", "--p-lim", "0"}).err.find("--p-lim: value 0") != std::string::npos);
  CHECK(with({"--N", "1", "--E", "210", "--nu", "0.3", "--p-lim", "0"}).code == 2);
  // Syntax errors are CLI11's (exit code >= 100): --A together with a radius, a missing --N.
  CHECK(run({"hertz", "--A", "0.001", "--B", "0.002", "--R-wyy", "460", "--N", "1", "--E", "210", "--nu", "0.3"}).code >= 100);
  CHECK(run({"hertz", "--A", "0.001", "--B", "0.002", "--E", "210", "--nu", "0.3"}).code >= 100);
}

TEST_CASE("cli hertz: zero load", "[hertz][cli]") {
  const CliRun r = run({"hertz", "--A", "0.001", "--B", "0.002", "--N", "0", "--E", "210", "--nu", "0.3", "--json"});
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j.at("a_mm").get<double>() == 0);
  CHECK(j.at("p0_MPa").get<double>() == 0);
  CHECK(j.at("m").get<double>() == Approx(1.2758).margin(5e-4));
}

TEST_CASE("cli hertz: README example with --A and --B", "[hertz][cli]") {
  // README: mhcontact hertz --A 0.001 --B 0.002 --N 10 --E 210 --nu 0.28 --json
  // λ = 0.5: m, n of method.md §2 (5e-4); a and b against closed-form Hertz
  // (tests/support/hertz_reference.hpp; 1e-9 relative: 10 printed digits and the fast path's
  // 5e-11); h0 = b² B (eq. 6).
  const CliRun r = run({"hertz", "--A", "0.001", "--B", "0.002", "--N", "10", "--E", "210", "--nu", "0.28", "--json"});
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j.at("lambda").get<double>() == 0.5);
  CHECK(j.at("m").get<double>() == Approx(1.2758).margin(5e-4));
  CHECK(j.at("n").get<double>() == Approx(0.8045).margin(5e-4));
  const testing::HertzReference h =
      testing::hertz_reference(1.0, 2.0, 10e3, testing::johnson_modulus(210e9, 0.28, 210e9, 0.28));  // A, B in 1/m
  CHECK(rel(j.at("a_mm").get<double>(), h.a * 1e3) <= 1e-9);
  CHECK(rel(j.at("b_mm").get<double>(), h.b * 1e3) <= 1e-9);
  CHECK(rel(j.at("h0_mm").get<double>(), std::pow(j.at("b_mm").get<double>(), 2) * 0.002) <= 1e-12);
  CHECK_FALSE(j.contains("plastic"));
}
