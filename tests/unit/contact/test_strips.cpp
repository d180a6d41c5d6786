// Tests of the semi-Hertzian strip solver (lib/contact/strips/).
// Reference values: closed-form Hertz (Johnson, Contact Mechanics §3.6 / §4.2) from
// tests/support/hertz_reference.hpp, independent of the library.
#include "contact/strips/strip_patch.hpp"
#include "contact/strips/strip_extents.hpp"
#include "contact/strips/strip_influence.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "support/hertz_reference.hpp"

namespace {

using mh::testing::HertzReference;

constexpr double kPi = 3.14159265358979323846;

// Steel on steel: E = 210 GPa, nu = 0.28 (both bodies).
const double kE = 210e9, kNu = 0.28;
const double kH = 2.0 * (1.0 - kNu * kNu) / (kPi * kE);          // combined compliance [1/Pa], the solver's input
const double kEstar = mh::testing::johnson_modulus(kE, kNu, kE, kNu);  // Johnson's E*: the reference's

// Elliptic-paraboloid gap g = B s^2, A constant, odd number of strips centred on 0.
mh::StripGeometry ellipse_geometry(double A, double B, double ds, int n) {
  mh::StripGeometry geo;
  geo.ds = ds;
  for (int i = 0; i < n; ++i) {
    const double s = (i - (n - 1) / 2) * ds;
    geo.s.push_back(s);
    geo.g.push_back(B * s * s);
    geo.A.push_back(A);
    geo.xc.push_back(0.0);
  }
  return geo;
}

// Measured semi-axes: a from the centre strip, b from a least-squares fit of
// q_i^2 = p0^2 (1 - y^2/b^2) over strips with |y| < fit_frac * b_guess.
struct Measured {
  double p0, a, b;
};
Measured measure(const mh::StripResult& r, double b_guess) {
  Measured m{0.0, 0.0, 0.0};
  double Sx = 0, Sy = 0, Sxx = 0, Sxy = 0;
  int n = 0;
  const double fit_frac = 0.8;  // the tip strips carry the largest discretisation error
  for (const auto& st : r.strips) {
    if (std::fabs(st.s) < 1e-15) { m.p0 = st.q; m.a = st.a; }
    if (std::fabs(st.s) < fit_frac * b_guess) {
      const double x = st.s * st.s, y = st.q * st.q;
      Sx += x; Sy += y; Sxx += x * x; Sxy += x * y; ++n;
    }
  }
  const double slope = (n * Sxy - Sx * Sy) / (n * Sxx - Sx * Sx);
  const double icpt = (Sy - slope * Sx) / n;
  m.b = std::sqrt(-icpt / slope);
  return m;
}

// Brute-force influence: integral of f(t)/r over the strip
// x in [-a, a] (strip centre at 0), y in [y1, y2] (relative to the point),
// point at x = X0, f = min(sqrt(1 - (x/a)^2), rcap). Polar coordinates
// around the point remove the 1/r singularity (rho d rho d phi / rho); the
// midpoint rule is used in both directions.
double brute_polar(double X0, double a, double y1, double y2, double rcap, int nphi, int nrho) {
  const double xl = -a - X0, xr = a - X0;  // rectangle relative to the point (point inside)
  double sum = 0.0;
  for (int ip = 0; ip < nphi; ++ip) {
    const double phi = (ip + 0.5) * 2.0 * kPi / nphi;
    const double c = std::cos(phi), s = std::sin(phi);
    double rmax = 1e300;
    if (c > 0) rmax = std::min(rmax, xr / c);
    if (c < 0) rmax = std::min(rmax, xl / c);
    if (s > 0) rmax = std::min(rmax, y2 / s);
    if (s < 0) rmax = std::min(rmax, y1 / s);
    double acc = 0.0;
    for (int ir = 0; ir < nrho; ++ir) {
      const double rho = (ir + 0.5) * rmax / nrho;
      const double t = (X0 + rho * c) / a;
      acc += std::min(std::sqrt(std::max(0.0, 1.0 - t * t)), rcap);
    }
    sum += acc * rmax / nrho;
  }
  return sum * 2.0 * kPi / nphi;
}

// Brute force for a point off the strip: tensor midpoint rule in theta
// (x = a sin theta) and y.
double brute_tensor(double X0, double a, double y1, double y2, double rcap, int nx, int ny) {
  double sum = 0.0;
  for (int i = 0; i < nx; ++i) {
    const double th = -0.5 * kPi + (i + 0.5) * kPi / nx;
    const double t = std::sin(th);
    const double f = std::min(std::cos(th), rcap) * a * std::cos(th);
    const double X = a * t - X0;
    double acc = 0.0;
    for (int j = 0; j < ny; ++j) {
      const double y = y1 + (j + 0.5) * (y2 - y1) / ny;
      acc += 1.0 / std::sqrt(X * X + y * y);
    }
    sum += f * acc * (y2 - y1) / ny;
  }
  return sum * kPi / nx;
}

}  // namespace

TEST_CASE("strip influence matches brute-force 2-D quadrature", "[strips]") {
  using mh::strips_detail::strip_influence;
  struct Case {
    const char* what;
    double X0, a, y1, y2, rcap;
    bool inside;
  };
  const Case cases[] = {
      {"self, centre, a = 4 ds", 0.0, 4e-3, -0.5e-3, 0.5e-3, 1.0, true},
      {"self, centre, a = 40 ds", 0.0, 40e-3, -0.5e-3, 0.5e-3, 1.0, true},
      {"self, off-centre point x = 0.6 a", 2.4e-3, 4e-3, -0.5e-3, 0.5e-3, 1.0, true},
      {"self, capped r = 0.6", 0.0, 4e-3, -0.5e-3, 0.5e-3, 0.6, true},
      {"self, capped, point in flank", 3.5e-3, 4e-3, -0.5e-3, 0.5e-3, 0.6, true},
      {"neighbour strip, a = 20 ds", 0.0, 20e-3, 0.5e-3, 1.5e-3, 1.0, false},
      {"strip 5 widths away", 0.0, 4e-3, 4.5e-3, 5.5e-3, 1.0, false},
      {"centre line, beyond the strip end x = 1.3 a", 5.2e-3, 4e-3, -0.5e-3, 0.5e-3, 1.0, false},
  };
  for (const auto& c : cases) {
    const double lib = strip_influence(c.X0, c.a, c.y1, c.y2, c.rcap, 16);
    const double ref = c.inside ? brute_polar(c.X0, c.a, c.y1, c.y2, c.rcap, 4000, 2000)
                                : brute_tensor(c.X0, c.a, c.y1, c.y2, c.rcap, 4000, 4000);
    const double rel = std::fabs(lib / ref - 1.0);
    std::printf("  influence %-45s lib %.8e  brute %.8e  rel %.2e\n", c.what, lib, ref, rel);
    INFO(c.what << ": lib " << lib << " brute " << ref);
    CHECK(rel < 2e-4);
  }
}

namespace {
/// Load control, elastic, with the given end_gap_tol: 0.05 (the default: the estimated extents,
/// kept where their end gap closes within it) or 0 (the extents refined on every patch).
mh::StripResult solve_with_end_gap_tol(const mh::StripGeometry& geo, double N, double tol) {
  mh::StripOptions opt;
  opt.end_gap_tol = tol;
  return mh::solve_strips_load(geo, kH, N, INFINITY, opt);
}
}  // namespace

TEST_CASE("Hertz sphere: p0, semi-axes, approach (Johnson §4.2)", "[strips]") {
  const double R = 0.3, N = 50e3;
  const HertzReference h = mh::testing::hertz_reference(1.0 / (2.0 * R), 1.0 / (2.0 * R), N, kEstar);
  const int across = 40;  // strips across the contact diameter 2b (>= 30)
  // + 0.5: no strip centre exactly at the ellipse tip y = b, where the extent
  // is ~0 while delta - g > 0 (the thin-tail failure mode, see "outlier flag")
  const double ds = 2.0 * h.b / (across + 0.5);
  const int n = 2 * (int)(1.6 * h.b / ds) + 1;  // covers the interpenetration (sqrt(2) b) with margin
  const auto geo = ellipse_geometry(1.0 / (2.0 * R), 1.0 / (2.0 * R), ds, n);
  // The default (the estimate, kept: its end gap closes within end_gap_tol) and the extents
  // refined until the gap closes at every end (end_gap_tol = 0): Hertz is exact for both.
  for (const double tol : {0.05, 0.0}) {
    const auto r = solve_with_end_gap_tol(geo, N, tol);
    REQUIRE(r.status == mh::StripStatus::Ok);
    const Measured m = measure(r, h.b);
    std::printf("  sphere (end_gap_tol %g): p0 %.5g (ref %.5g, %+.3f%%)  a %.5g (ref %.5g, %+.3f%%)  b %.5g (%+.3f%%)  "
                "delta %.5g (ref %.5g, %+.3f%%)  area/(pi ab) %.4f  end-gap error %.4f  iters %d  strips %zu\n",
                tol, m.p0, h.p0, 100 * (m.p0 / h.p0 - 1), m.a, h.a, 100 * (m.a / h.a - 1), m.b, 100 * (m.b / h.b - 1),
                r.delta, h.delta, 100 * (r.delta / h.delta - 1), r.area / (kPi * h.a * h.b), r.end_gap_error,
                r.iterations, r.strips.size());
    INFO("end_gap_tol " << tol);
    CHECK(r.refined == (tol == 0.0));
    CHECK(r.end_gap_error < 0.05);  // the estimate is right for Hertz
    CHECK(std::fabs(r.N / N - 1.0) <= 1e-8);
    CHECK(std::fabs(m.p0 / h.p0 - 1.0) < 0.01);
    CHECK(std::fabs(m.a / h.a - 1.0) < 0.02);
    CHECK(std::fabs(m.b / h.b - 1.0) < 0.02);
    CHECK(std::fabs(r.delta / h.delta - 1.0) < 0.01);
    CHECK(r.n_outliers == 0);
    CHECK(r.n_bands == 1);
    if (tol > 0) CHECK(r.iterations <= 8);
  }
}

TEST_CASE("Hertz ellipses lambda = A/B in {0.1, 0.5, 2, 10} (Johnson §4.2)", "[strips]") {
  const double N = 50e3;
  const double Bs[] = {0.1, 0.5, 2.0, 10.0};
  for (double lambda : Bs) {
    const double B = 1.0 / (2.0 * 0.3);  // lateral curvature fixed, A varied
    const double A = lambda * B;
    const HertzReference h = mh::testing::hertz_reference(A, B, N, kEstar);
    const int across = 40;
    const double ds = 2.0 * h.b / (across + 0.5);
    const int n = 2 * (int)(2.0 * h.b / ds) + 1;
    const auto geo = ellipse_geometry(A, B, ds, n);
    for (const double tol : {0.05, 0.0}) {  // as for the sphere: estimate and refined extents
      const auto r = solve_with_end_gap_tol(geo, N, tol);
      REQUIRE(r.status == mh::StripStatus::Ok);
      const Measured m = measure(r, h.b);
      std::printf("  lambda %4.1f (end_gap_tol %g): p0 %+.3f%%  a %+.3f%%  b %+.3f%%  delta %+.3f%%  (a/b ref %.4f)  "
                  "end-gap error %.4f  iters %d\n",
                  lambda, tol, 100 * (m.p0 / h.p0 - 1), 100 * (m.a / h.a - 1), 100 * (m.b / h.b - 1),
                  100 * (r.delta / h.delta - 1), h.a / h.b, r.end_gap_error, r.iterations);
      INFO("lambda " << lambda << ", end_gap_tol " << tol);
      CHECK(std::fabs(m.p0 / h.p0 - 1.0) < 0.01);
      CHECK(std::fabs(m.a / h.a - 1.0) < 0.02);
      CHECK(std::fabs(m.b / h.b - 1.0) < 0.02);
      CHECK(r.n_outliers == 0);
    }
  }
}

TEST_CASE("library Hertz axes agree with the test's reference", "[strips]") {
  for (double lambda : {0.1, 0.5, 1.0, 2.0, 10.0}) {
    const double B = 1.0, A = lambda * B, N = 1e4;
    const HertzReference h = mh::testing::hertz_reference(A, B, N, kEstar);
    double a = 0, b = 0;
    REQUIRE(mh::strips_detail::hertz_axes(A, B, h.delta, &a, &b));
    CHECK(a == Approx(h.a).epsilon(1e-9));
    CHECK(b == Approx(h.b).epsilon(1e-9));
  }
}

TEST_CASE("plastic cap", "[strips]") {
  const double R = 0.3, N = 50e3;
  const HertzReference h = mh::testing::hertz_reference(1.0 / (2.0 * R), 1.0 / (2.0 * R), N, kEstar);
  const double ds = 2.0 * h.b / 40.5;
  const auto geo = ellipse_geometry(1.0 / (2.0 * R), 1.0 / (2.0 * R), ds, 2 * (int)(1.6 * h.b / ds) + 1);
  const auto el = mh::solve_strips_load(geo, kH, N, INFINITY);
  REQUIRE(el.status == mh::StripStatus::Ok);

  SECTION("p_lim above the elastic peak gives exactly the elastic answer") {
    const auto r = mh::solve_strips_load(geo, kH, N, 1.5 * el.pmax);
    REQUIRE(r.status == mh::StripStatus::Ok);
    CHECK(r.delta == el.delta);
    CHECK(r.N == el.N);
    CHECK(r.pmax == el.pmax);
    REQUIRE(r.strips.size() == el.strips.size());
    for (std::size_t k = 0; k < r.strips.size(); ++k) {
      CHECK(r.strips[k].q == el.strips[k].q);
      CHECK_FALSE(r.strips[k].plastic);
    }
  }
  SECTION("p_lim = 0.7 p0 in load control") {
    const double p_lim = 0.7 * h.p0;
    const auto r = mh::solve_strips_load(geo, kH, N, p_lim);
    REQUIRE(r.status == mh::StripStatus::Ok);
    CHECK(std::fabs(r.N - N) <= 1e-8 * N);
    CHECK(r.pmax == p_lim);
    int n_plastic = 0;
    double integrated = 0.0;  // independent integral of the capped pressure
    const int nq = 20000;     // midpoint points along x per strip
    for (const auto& st : r.strips) {
      n_plastic += st.plastic;
      double acc = 0.0, peak = 0.0;
      for (int k = 0; k < nq; ++k) {
        const double t = -1.0 + (k + 0.5) * 2.0 / nq;
        const double p = st.plastic ? std::min(st.q * std::sqrt(1 - t * t), p_lim) : st.q * std::sqrt(1 - t * t);
        acc += p;
        peak = std::max(peak, p);
      }
      integrated += acc * (2.0 * st.a / nq) * ds;
      CHECK(peak <= p_lim * (1 + 1e-12));
    }
    std::printf("  plastic 0.7 p0: %d of %zu strips capped, delta %.5g (elastic %.5g), area %.4g (elastic %.4g), "
                "integrated load / N - 1 = %.2e, iters %d\n",
                n_plastic, r.strips.size(), r.delta, el.delta, r.area, el.area, integrated / N - 1, r.iterations);
    CHECK(n_plastic > 0);
    CHECK(std::fabs(integrated / N - 1.0) < 1e-5);  // midpoint error of the sqrt edges
    // Lengthened strips (a' > a): larger area. (delta is not asserted: in
    // this model the capped strips keep their elastic load and their flatter,
    // longer pressure lowers the displacement at the neighbours' collocation
    // points, so delta at fixed load may go either way.)
    CHECK(r.area > el.area);
  }
  SECTION("p_lim = 0.2 p0: no capped strip reaches beyond its overlap") {
    // The displacements are compressive, so the surfaces touch only where they interpenetrate
    // rigidly: |x| <= sqrt((delta - g_i) / A_i) on strip i. Lengthening a strongly capped strip
    // to keep its elastic load (a' = a (pi/2) / Phi(r), 4 times at r = 0.2) broke that; it is
    // now held at its overlap and the approach rises to carry the load (docs/method.md §9 item 6).
    const double p_lim = 0.2 * h.p0;
    const auto r = mh::solve_strips_load(geo, kH, N, p_lim);
    REQUIRE(r.status == mh::StripStatus::Ok);
    CHECK(std::fabs(r.N - N) <= 1e-8 * N);
    int n_plastic = 0, n_held = 0;
    for (const auto& st : r.strips) {
      const double overlap = std::sqrt((r.delta - geo.g[st.index]) / geo.A[st.index]);
      CHECK(st.a <= overlap * (1 + 1e-12));
      n_plastic += st.plastic;
      n_held += st.plastic && st.a >= overlap * (1 - 1e-12);
    }
    std::printf("  plastic 0.2 p0: %d of %zu strips capped, %d held at their overlap; area / (N / p_lim) = %.4f, "
                "delta / elastic %.3f\n",
                n_plastic, r.strips.size(), n_held, r.area * p_lim / N, r.delta / el.delta);
    CHECK(n_held > 0);
    // p <= p_lim everywhere: the area carries at least N / p_lim.
    CHECK(r.area >= N / p_lim * (1 - 1e-9));
    CHECK(r.delta > el.delta);
  }
}

namespace {
// Two wells: a wide main well g1 = s^2/(2 R) and a narrow shallow well
// g2 = g2min + B2 (s - s2)^2; the gap is the lower of the two.
mh::StripGeometry two_wells(double s2, double g2min, double B2, double ds, double smin, double smax) {
  mh::StripGeometry geo;
  geo.ds = ds;
  const double R = 0.3;
  const int n = (int)std::lround((smax - smin) / ds) + 1;
  for (int i = 0; i < n; ++i) {
    const double s = smin + i * ds;
    geo.s.push_back(s);
    geo.g.push_back(std::min(s * s / (2 * R), g2min + B2 * (s - s2) * (s - s2)));
    geo.A.push_back(1.0 / (2 * R));
    geo.xc.push_back(0.0);
  }
  return geo;
}
}  // namespace

TEST_CASE("two bands: both carry load and coupling matters", "[strips]") {
  const double ds = 0.25e-3;
  SECTION("separate interpenetrated ranges") {
    const auto geo = two_wells(12e-3, 2e-5, 25.0, ds, -8e-3, 15e-3);
    const double delta = 6e-5;
    mh::StripOptions unc;
    unc.coupling = false;
    const auto r = mh::solve_strips_approach(geo, kH, delta, INFINITY);
    const auto u = mh::solve_strips_approach(geo, kH, delta, INFINITY, unc);
    REQUIRE(r.status == mh::StripStatus::Ok);
    REQUIRE(u.status == mh::StripStatus::Ok);
    CHECK(r.n_bands == 2);
    double N0 = 0, N1 = 0, q1c = 0, q1u = 0;
    for (const auto& st : r.strips) {
      (st.band == 0 ? N0 : N1) += st.load;
      if (st.band == 1) q1c = std::max(q1c, st.q);
    }
    for (const auto& st : u.strips)
      if (st.band == 1) q1u = std::max(q1u, st.q);
    std::printf("  two bands: N main %.4g N narrow %.4g; N coupled %.5g vs uncoupled %.5g; "
                "narrow peak coupled %.4g vs uncoupled %.4g\n",
                N0, N1, r.N, u.N, q1c, q1u);
    CHECK(N0 > 0);
    CHECK(N1 > 0);
    // Physics: every pressure adds a positive displacement everywhere (1/r > 0),
    // so with coupling each strip's interpenetration delta - g is partly
    // taken up by its neighbours' pressure and needs less of its own: at fixed
    // delta the coupled load and the narrow band's peak are LOWER.
    CHECK(r.N < 0.9 * u.N);
    CHECK(q1c < q1u);
  }
  SECTION("one interpenetrated range split at a saddle below delta") {
    const auto geo = two_wells(7e-3, 1e-5, 25.0, ds, -8e-3, 10e-3);
    const double delta = 7e-5;
    // the saddle is interpenetrated: all strips between the wells have g < delta
    double gsad = 0;
    for (std::size_t i = 0; i < geo.s.size(); ++i)
      if (geo.s[i] > 0 && geo.s[i] < 7e-3) gsad = std::max(gsad, geo.g[i]);
    REQUIRE(gsad < delta);
    const auto r = mh::solve_strips_approach(geo, kH, delta, INFINITY);
    REQUIRE(r.status == mh::StripStatus::Ok);
    CHECK(r.n_bands == 2);
    bool b0 = false, b1 = false;
    for (const auto& st : r.strips) (st.band == 0 ? b0 : b1) = true;
    CHECK(b0);
    CHECK(b1);
  }
}

TEST_CASE("active set: the answer does not depend on the starting set", "[strips]") {
  // The amplitudes solve a linear complementarity problem (q >= 0, no unloaded strip
  // penetrated), whose solution is unique: a warm start changes the cost, not the answer.
  // Reference: the cold start (every strip with a positive extent). A start from a single strip
  // fails this unless strips are added back, a start from every strip unless they are dropped.
  const double ds = 0.25e-3;
  const auto geo = two_wells(7e-3, 1e-5, 25.0, ds, -8e-3, 10e-3);
  const double delta = 7e-5;
  const int n = static_cast<int>(geo.s.size());
  for (const double p_lim : {static_cast<double>(INFINITY), 1.2e9}) {
    const auto cold = mh::solve_strips_approach(geo, kH, delta, p_lim);
    REQUIRE(cold.status == mh::StripStatus::Ok);
    std::vector<int> cold_set = mh::loaded_strips(cold);
    std::vector<int> every(n), one{n / 3}, band1;
    for (int i = 0; i < n; ++i) every[i] = i;
    for (int i : cold_set)
      if (geo.s[i] > 3.5e-3) band1.push_back(i);
    for (const std::vector<int>* warm : {&every, &one, &band1, &cold_set}) {
      const auto r = mh::solve_strips_approach(geo, kH, delta, p_lim, {}, warm);
      REQUIRE(r.status == mh::StripStatus::Ok);
      CHECK(mh::loaded_strips(r) == cold_set);
      CHECK(r.N == Approx(cold.N).epsilon(1e-9));
      CHECK(r.pmax == Approx(cold.pmax).epsilon(1e-9));
    }
    // Load control from a start far from the answer reaches the same load.
    const mh::StripSolver S(geo, kH, p_lim);
    mh::StripWarmStart w;
    w.loaded = one;
    const auto a = S.at_load(cold.N), b = S.at_load(cold.N, &w, 1.5 * delta);
    REQUIRE(a.status == mh::StripStatus::Ok);
    REQUIRE(b.status == mh::StripStatus::Ok);
    CHECK(b.delta == Approx(a.delta).epsilon(1e-7));
    // The patch's estimate misses the end gap and is refined, elastic or capped; refined extents
    // settle to 1e-3 of their sum with the load given, 1e-6 with the approach given: elastic, the
    // two approaches agree to about 1e-4 (3.4e-5 measured). Capped strips keep their extent before
    // lengthening through the refinement (docs/method.md §9 item 8), the extent of the estimate
    // at the approach where it was made: load control starts elsewhere and ends 8.2e-3 away.
    CHECK(a.refined);
    CHECK(b.delta == Approx(delta).epsilon(std::isinf(p_lim) ? 1e-4 : 1.5e-2));
  }
}

TEST_CASE("map_strips: a solution carried to the strips of a new plane", "[strips]") {
  // Three loaded strips in one band and two in another (old indices 2-4 and 7-8, ds = 1 mm).
  const double ds = 1e-3;
  std::vector<mh::StripState> old;
  for (int i : {2, 3, 4, 7, 8}) {
    mh::StripState st;
    st.index = i;
    st.s = i * ds;
    st.a = (1 + i) * 1e-3;
    st.q = (10 + i) * 1e6;
    old.push_back(st);
  }
  std::vector<double> s(12);
  for (int j = 0; j < 12; ++j) s[j] = j * ds;
  SECTION("the same strips: the same solution") {
    const auto m = mh::map_strips(old, ds, s, s);
    REQUIRE(m.size() == old.size());
    for (std::size_t k = 0; k < m.size(); ++k) {
      CHECK(m[k].index == old[k].index);
      CHECK(m[k].a == old[k].a);
      CHECK(m[k].q == old[k].q);
    }
  }
  SECTION("strips shifted by 0.4 ds: interpolated inside a band, tails kept, no bridge between bands") {
    // New strip j lies at old coordinate (j + 0.4) ds; its new coordinate is 5 mm further.
    std::vector<double> s_old(12), s_new(12);
    for (int j = 0; j < 12; ++j) {
      s_old[j] = (j + 0.4) * ds;
      s_new[j] = 5e-3 + j * ds;
    }
    const auto m = mh::map_strips(old, ds, s_old, s_new);
    std::vector<int> idx;
    for (const auto& st : m) idx.push_back(st.index);
    // j = 1 (old 1.4: 0.6 ds before the first loaded strip, kept as a tail), 2, 3 (between old 2-3,
    // 3-4), 4 (old 4.4: the first band's tail, inside the gap between the bands), not 5 (old 5.4:
    // 1.4 ds beyond it), 6 (old 6.4: the second band's tail), 7 (between 7 and 8), 8 (old 8.4:
    // tail); not 9 (old 9.4).
    CHECK(idx == std::vector<int>{1, 2, 3, 4, 6, 7, 8});
    REQUIRE(m.size() == 7);
    CHECK(m[0].a == old[0].a);  // tails: the end strip's values
    CHECK(m[3].a == old[2].a);
    CHECK(m[4].q == old[3].q);
    CHECK(m[6].a == old[4].a);
    CHECK(m[1].a == Approx(0.6 * old[0].a + 0.4 * old[1].a).epsilon(1e-14));
    CHECK(m[1].q == Approx(0.6 * old[0].q + 0.4 * old[1].q).epsilon(1e-14));
    CHECK(m[5].a == Approx(0.6 * old[3].a + 0.4 * old[4].a).epsilon(1e-14));
    CHECK(m[1].s == s_new[2]);
  }
}

TEST_CASE("a refinement started from a nearby plane's answer reaches the cold answer in half the passes", "[strips]") {
  // The patch of "active set: the answer does not depend on the starting set" (refined: its
  // estimate misses the end gap), sampled on two strip grids 0.4 ds apart, as a new placement of
  // a patch's plane samples it. The second grid's refinement from the first grid's answer mapped
  // by map_strips against its own cold solve (estimate, then refinement).
  const double ds = 0.25e-3, shift = 0.4 * ds;
  const auto A = two_wells(7e-3, 1e-5, 25.0, ds, -8e-3, 10e-3);
  const auto B = two_wells(7e-3, 1e-5, 25.0, ds, -8e-3 + shift, 10e-3 + shift);
  const mh::StripSolver SA(A, kH, INFINITY), SB(B, kH, INFINITY);
  const double N = mh::solve_strips_approach(A, kH, 7e-5, INFINITY).N;
  const auto ra = SA.at_load(N);
  const auto cold = SB.at_load(N);
  REQUIRE(ra.status == mh::StripStatus::Ok);
  REQUIRE(cold.status == mh::StripStatus::Ok);
  REQUIRE(ra.refined);
  REQUIRE(cold.refined);
  mh::StripWarmStart w;
  w.end_gap = 1;
  w.end_gap_error = ra.end_gap_error;
  w.previous.strips = mh::map_strips(ra.strips, ds, B.s, B.s);
  w.previous.delta = ra.delta;
  w.loaded = mh::loaded_strips(w.previous);
  const auto warm = SB.at_load(N, &w, ra.delta);
  REQUIRE(warm.status == mh::StripStatus::Ok);
  std::printf("  refinement on a shifted grid: cold %d passes, area %.5g mm², pmax %.5g MPa; from the mapped answer %d "
              "passes, area %+.3f %%, pmax %+.3f %%\n",
              cold.iterations, cold.area * 1e6, cold.pmax / 1e6, warm.iterations, 100 * (warm.area / cold.area - 1),
              100 * (warm.pmax / cold.pmax - 1));
  CHECK(warm.refined);
  CHECK(warm.N == Approx(N).epsilon(1e-6));
  CHECK(warm.area == Approx(cold.area).epsilon(0.01));
  CHECK(warm.pmax == Approx(cold.pmax).epsilon(0.005));
  CHECK(warm.delta == Approx(cold.delta).epsilon(1e-3));
  CHECK(2 * warm.iterations <= cold.iterations);  // measured 4 against 10 (6 with the strips one index off)
}

TEST_CASE("outlier flag", "[strips]") {
  const double R = 0.3, N = 50e3;
  const HertzReference h = mh::testing::hertz_reference(1.0 / (2.0 * R), 1.0 / (2.0 * R), N, kEstar);
  const double delta = h.delta;
  {
    // Degenerate tail: with ds = 2b/30 strip centres fall exactly on the tips y = +-b, where the
    // Hertz extent is ~0 (round-off) but delta - g > 0. Without widening (docs/method.md §9
    // item 7) the tip strips took that interpenetration with a vanishing length: amplitudes
    // far above their neighbours', flagged. Widened to the length of the interpenetration the
    // other strips leave there, they are not outliers and the Hertz answer holds (Johnson §4.2).
    const double ds = 2.0 * h.b / 30;
    const auto geo = ellipse_geometry(1.0 / (2.0 * R), 1.0 / (2.0 * R), ds, 2 * (int)(1.6 * h.b / ds) + 1);
    const auto r = mh::solve_strips_approach(geo, kH, delta, INFINITY);
    REQUIRE(r.status == mh::StripStatus::Ok);
    bool tip = false;
    for (const auto& st : r.strips) tip = tip || std::fabs(std::fabs(st.s) / h.b - 1.0) < 1e-9;
    std::printf("  strips on the tips: loaded %d, outliers %d, pmax/p0 = %.4f, N/N_Hertz = %.4f\n", tip ? 1 : 0,
                r.n_outliers, r.pmax / h.p0, r.N / N);
    CHECK(r.n_outliers == 0);
    CHECK(r.pmax == Approx(h.p0).epsilon(0.01));
    CHECK(r.N == Approx(N).epsilon(0.02));
  }
  const double ds = 2.0 * h.b / 30.5;
  auto geo = ellipse_geometry(1.0 / (2.0 * R), 1.0 / (2.0 * R), ds, 2 * (int)(1.6 * h.b / ds) + 1);
  auto base = mh::solve_strips_approach(geo, kH, delta, INFINITY);
  REQUIRE(base.status == mh::StripStatus::Ok);
  CHECK(base.n_outliers == 0);
  // Shorten the last loaded strip: a much stiffer row curvature along x gives
  // it a tiny extent, and collocation inflates its amplitude.
  const int tail = base.strips.back().index;
  const double stiffen = 1e8;  // A x 1e8 -> extent / 1e4
  geo.A[tail] *= stiffen;
  const auto r = mh::solve_strips_approach(geo, kH, delta, INFINITY);
  REQUIRE(r.status == mh::StripStatus::Ok);
  std::printf("  outlier: tail q %.4g vs neighbour %.4g, n_outliers %d\n", r.strips.back().q,
              r.strips[r.strips.size() - 2].q, r.n_outliers);
  CHECK(r.n_outliers >= 1);
  REQUIRE(r.worst_outlier >= 0);
  CHECK(r.strips[r.worst_outlier].index == tail);
  CHECK_FALSE(r.strips[r.worst_outlier].plastic);  // flagged, not capped
}

TEST_CASE("no contact and invalid input", "[strips]") {
  const auto geo = ellipse_geometry(1.0, 1.0, 1e-3, 11);
  CHECK(mh::solve_strips_approach(geo, kH, 0.0, INFINITY).status == mh::StripStatus::NoContact);
  CHECK(mh::solve_strips_approach(geo, kH, -1e-6, INFINITY).status == mh::StripStatus::NoContact);
  mh::StripOptions bad;
  bad.gauss_points = 7;
  std::string why;
  CHECK_FALSE(bad.valid(&why));
  CHECK(why.find("gauss_points") != std::string::npos);
  CHECK(mh::solve_strips_approach(geo, kH, 1e-6, INFINITY, bad).status == mh::StripStatus::InvalidInput);
  CHECK(mh::solve_strips_load(geo, kH, -5.0, INFINITY).status == mh::StripStatus::InvalidInput);
}

TEST_CASE("timing: ~50-strip patch", "[strips][timing]") {
  const double R = 0.3, N = 50e3;
  const HertzReference h = mh::testing::hertz_reference(1.0 / (2.0 * R), 0.5 / (2.0 * R), N, kEstar);
  const double ds = 2.0 * h.b / 50;
  const auto geo = ellipse_geometry(1.0 / (2.0 * R), 0.5 / (2.0 * R), ds, 2 * (int)(1.6 * h.b / ds) + 1);
  const int reps = 30;
  double ms = 1e300;  // best of reps: the machine is shared
  mh::StripResult r;
  for (int k = 0; k < reps; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    r = mh::solve_strips_load(geo, kH, N, INFINITY);
    const auto t1 = std::chrono::steady_clock::now();
    ms = std::min(ms, std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::printf("  timing: %zu loaded strips, %d delta iterations, %.3f ms per load-controlled solve\n",
              r.strips.size(), r.iterations, ms);
  CHECK(r.status == mh::StripStatus::Ok);
}
