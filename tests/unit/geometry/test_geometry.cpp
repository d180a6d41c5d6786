// Contact geometry (geometry.hpp): positioning, CAF, potential ellipses, eq. (9).
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <vector>

#include "geometry/contact_geometry.hpp"
#include "profile/read.hpp"

using namespace mh;

namespace {
const std::string kData = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/";

Profile read(const std::string& name, ProfileKind kind, bool check = true) {
  ProfileReadOptions o;
  o.kind = kind;
  o.check = check;
  return read_profile(kData + name, o);
}

// dγ/dt_Y by a central difference over ±half grid points (averages the fit's slope noise).
double dgamma(const ContactGeometry& G, std::size_t k, std::size_t half) {
  return (G.main_at(k + half).gamma - G.main_at(k - half).gamma) / (G.tY[k + half] - G.tY[k - half]);
}
}  // namespace

TEST_CASE("Manchester pair: the paper's 4 potential ellipses", "[geometry]") {
  // Source: Sebès et al. 2014 §2.3 and Fig. 2: S1002 on UIC60 1:40 (already canted), standard
  // track: 4 potential ellipses; at t_Y = 5 mm the main strip belongs to ellipse #2.
  const Profile W = read("MBench_S1002_v3.prw", ProfileKind::Wheel);
  const Profile R = read("MBench_UIC60_v3.prr", ProfileKind::Rail);
  GeometryOptions opt;  // default grid −10 … 12 mm, 0.01 mm
  const ContactGeometry G = build_geometry(W, R, TrackSetup{}, opt);
  REQUIRE(G.n_ellipses() == 4);
  const std::size_t k5 = static_cast<std::size_t>(std::lround((5e-3 - opt.tY_min) / opt.tY_step));
  REQUIRE(G.tY[k5] == Approx(5e-3));
  REQUIRE(G.main_ellipse[k5] + 1 == 2);
  // The CAF grows with t_Y through the jumps (method.md §1): the ellipses sit further towards
  // the gauge corner one after the other, with increasing contact angle.
  for (std::size_t e = 1; e < G.n_ellipses(); ++e) {
    REQUIRE(G.ellipses[e].y_r_max < G.ellipses[e - 1].y_r_min);
    REQUIRE(G.at(G.ellipses[e].k_first, e).gamma > G.at(G.ellipses[e - 1].k_last, e - 1).gamma);
  }
  // Regression of this implementation's jump positions (measured, 0.01 mm grid): 0.22, 5.03,
  // 6.62 mm. Tolerance: two grid steps.
  REQUIRE(G.ellipses[1].tY_min == Approx(0.22e-3).margin(0.02e-3));
  REQUIRE(G.ellipses[2].tY_min == Approx(5.03e-3).margin(0.02e-3));
  REQUIRE(G.ellipses[3].tY_min == Approx(6.62e-3).margin(0.02e-3));
  // Tread contact at t_Y = 0 on the R300 crown, flange contact on the R13 gauge corner.
  const std::size_t k0 = static_cast<std::size_t>(std::lround(-opt.tY_min / opt.tY_step));
  REQUIRE(1.0 / G.main_at(k0).k_rxx == Approx(0.300).epsilon(0.005));
  REQUIRE(1.0 / G.main_at(G.tY.size() - 1).k_rxx == Approx(0.013).epsilon(0.005));
}

TEST_CASE("eq. (9) on a pair of circular profiles", "[geometry]") {
  // Source: paper eq. (9), R_wxx + R_rxx = −1/(cos γ dγ/dt_Y), exact where radii are constant.
  // Wheel circ_r50.prw (convex, R_wxx = +50 mm), rail circ_r100.prr (R_rxx = +100 mm), both exact
  // to 5e−7 mm (tests/data/profiles/README.md). Tolerance 0.2 % (the derivative is a finite difference
  // over ±0.5 mm of the CAF).
  const Profile W = read("circ_r50.prw", ProfileKind::Wheel, false);
  const Profile R = read("circ_r100.prr", ProfileKind::Rail, false);
  const ContactGeometry G = build_geometry(W, R, TrackSetup{}, GeometryOptions{});
  REQUIRE(G.n_ellipses() == 1);
  for (std::size_t k = 50; k + 50 < G.tY.size(); k += 97) {
    const CandidateGeom& c = G.main_at(k);
    CAPTURE(G.tY[k]);
    REQUIRE(1.0 / c.k_wxx == Approx(0.050).epsilon(1e-4));
    REQUIRE(1.0 / c.k_rxx == Approx(0.100).epsilon(1e-4));
    REQUIRE(-1.0 / (std::cos(c.gamma) * dgamma(G, k, 50)) == Approx(0.150).epsilon(2e-3));
  }
}

TEST_CASE("eq. (9) on the Manchester pair where the radii are constant", "[geometry]") {
  // Flange contact t_Y 8.5 … 11.5 mm: S1002 flange arc R20 (section F) on the UIC60 R13 gauge
  // corner: R_wxx + R_rxx = 33 mm. Tolerance 1 %.
  const Profile W = read("MBench_S1002_v3.prw", ProfileKind::Wheel);
  const Profile R = read("MBench_UIC60_v3.prr", ProfileKind::Rail);
  const ContactGeometry G = build_geometry(W, R, TrackSetup{}, GeometryOptions{});
  for (double t = 8.5e-3; t <= 11.5e-3; t += 0.5e-3) {
    const std::size_t k = static_cast<std::size_t>(std::lround((t - G.tY.front()) / 1e-5));
    const CandidateGeom& c = G.main_at(k);
    CAPTURE(t);
    REQUIRE(1.0 / c.k_wxx + 1.0 / c.k_rxx == Approx(0.033).epsilon(0.01));
    REQUIRE(-1.0 / (std::cos(c.gamma) * dgamma(G, k, 50)) == Approx(0.033).epsilon(0.01));
  }
}

TEST_CASE("positioning at t_Y = 0 from the track data", "[geometry]") {
  // method.md §7: the taping line sits (flange-back distance/2 − flange-back position) −
  // gauge/2 = 750 − 717.5 = 32.5 mm to the field side of the rail's gauge point.
  const Profile W = read("MBench_S1002_v3.prw", ProfileKind::Wheel);
  const Profile R = read("MBench_UIC60_v3.prr", ProfileKind::Rail);
  GeometryOptions opt;
  opt.tY_min = -1e-3;
  opt.tY_max = 1e-3;
  const ContactGeometry G = build_geometry(W, R, TrackSetup{}, opt);
  REQUIRE(G.y_offset - G.rail_gauge_y == Approx(0.0325).margin(1e-12));
  TrackSetup wide;
  wide.gauge = 1.445;  // 10 mm wider gauge: the wheel sits 5 mm further to the gauge side
  const ContactGeometry H = build_geometry(W, R, wide, opt);
  REQUIRE(H.y_offset - G.y_offset == Approx(-0.005).margin(1e-12));
}

TEST_CASE("candidates interpolate between grid points and keep their gaps", "[geometry]") {
  const Profile W = read("MBench_S1002_v3.prw", ProfileKind::Wheel);
  const Profile R = read("MBench_UIC60_v3.prr", ProfileKind::Rail);
  const ContactGeometry G = build_geometry(W, R, TrackSetup{}, GeometryOptions{});
  std::vector<CandidateGeom> c(G.n_ellipses());
  int main = -1;
  G.candidates_at(3.005e-3, c.data(), &main);
  REQUIRE(main == 1);
  REQUIRE(c[1].gap == 0);            // the main ellipse touches
  for (int e : {0, 2, 3}) REQUIRE(c[static_cast<std::size_t>(e)].gap > 0);  // the others are apart
  REQUIRE_FALSE(G.covers(12.5e-3));
}

TEST_CASE("potential ellipses do not depend on the t_Y grid", "[geometry]") {
  // Manchester pair: 4 potential ellipses with the same jumps for every step 0.005 … 0.5 mm; the
  // jumps are bisected to 0.01 µm, so they agree far closer than one step (measured: identical
  // to 1e-5 mm). The ellipses' grid boundaries agree within one step.
  ProfileReadOptions o;
  o.kind = ProfileKind::Wheel;
  const Profile w = read_profile(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/MBench_S1002_v3.prw", o);
  o.kind = ProfileKind::Rail;
  const Profile r = read_profile(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/MBench_UIC60_v3.prr", o);
  GeometryOptions ref_opt;
  ref_opt.tY_step = 0.005e-3;
  const ContactGeometry ref = build_geometry(w, r, TrackSetup{}, ref_opt);
  REQUIRE(ref.n_ellipses() == 4);
  REQUIRE(ref.jumps.size() == 3);
  for (double step_mm : {0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5}) {
    GeometryOptions go;
    go.tY_step = step_mm * 1e-3;
    const ContactGeometry G = build_geometry(w, r, TrackSetup{}, go);
    CAPTURE(step_mm);
    REQUIRE(G.n_ellipses() == 4);
    for (std::size_t j = 0; j < 3; ++j) REQUIRE(G.jumps[j] == Approx(ref.jumps[j]).margin(1e-7));
    for (std::size_t e = 0; e < 4; ++e) {
      REQUIRE(G.ellipses[e].tY_min == Approx(ref.ellipses[e].tY_min).margin(go.tY_step + 1e-12));
      REQUIRE(G.ellipses[e].tY_max == Approx(ref.ellipses[e].tY_max).margin(go.tY_step + 1e-12));
    }
  }
}

TEST_CASE("a sliver between two jumps is merged into a neighbour", "[geometry]") {
  // With the minimum width raised above the 3rd Manchester ellipse's width (5.02 … 6.61 mm) but
  // below the 2nd's (0.21 … 5.02 mm), the 3rd alone is merged: one jump fewer; with 0 nothing is.
  ProfileReadOptions o;
  o.kind = ProfileKind::Wheel;
  const Profile w = read_profile(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/MBench_S1002_v3.prw", o);
  o.kind = ProfileKind::Rail;
  const Profile r = read_profile(std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/profiles/MBench_UIC60_v3.prr", o);
  GeometryOptions go;
  go.min_ellipse_width = 0;
  REQUIRE(build_geometry(w, r, TrackSetup{}, go).n_ellipses() == 4);
  go.min_ellipse_width = 3e-3;
  const ContactGeometry G = build_geometry(w, r, TrackSetup{}, go);
  REQUIRE(G.n_ellipses() == 3);
  for (std::size_t k = 0; k < G.tY.size(); ++k) REQUIRE(G.main_ellipse[k] < 3);
}

TEST_CASE("candidates next to a jump come from their own geometry, not a destroyed one at the same address", "[geometry]") {
  // In a grid interval that holds a jump the candidates are evaluated from the profiles and
  // cached per thread; a batch builds pair after pair, and a new geometry can occupy the address
  // of the one before. B is the Manchester pair on a gauge 2 µm wider: its jumps sit 1 µm later
  // in t_Y, so at t_Y = 6.615 mm (in the grid interval of the jump at 6.614 mm for both) its
  // candidates differ from A's by 1 µm in y_w.
  const Profile W = read("MBench_S1002_v3.prw", ProfileKind::Wheel);
  const Profile R = read("MBench_UIC60_v3.prr", ProfileKind::Rail);
  TrackSetup wide;
  wide.gauge += 2e-6;
  const double t = 6.615e-3;
  std::optional<ContactGeometry> slot;
  slot.emplace(build_geometry(W, R, TrackSetup{}, GeometryOptions{}));
  std::vector<CandidateGeom> a(slot->n_ellipses()), b(slot->n_ellipses()), ref(slot->n_ellipses());
  slot->candidates_at(t, a.data(), nullptr);
  slot.reset();
  slot.emplace(build_geometry(W, R, wide, GeometryOptions{}));  // same storage, hence same address
  slot->candidates_at(t, b.data(), nullptr);
  const ContactGeometry B2 = build_geometry(W, R, wide, GeometryOptions{});
  B2.candidates_at(t, ref.data(), nullptr);
  double diff = 0;  // A and B differ (the fixed candidates by the 1 µm shift): the test can fail
  for (std::size_t e = 0; e < a.size(); ++e) {
    CAPTURE(e);
    REQUIRE(b[e].y_w == ref[e].y_w);
    REQUIRE(b[e].sep == ref[e].sep);
    diff = std::max(diff, std::fabs(a[e].y_w - b[e].y_w));
  }
  REQUIRE(diff > 0.5e-6);
}
