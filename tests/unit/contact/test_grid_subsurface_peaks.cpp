// The peak search below a grid patch (grid_subsurface_peaks, subsurface.cpp's field_peaks) against
// the largest stresses of the whole patch, on CONTACT's own load of the Manchester tread
// patch (tests/data/contact_subsurface_wheelrail/tread_yaw_pressure.csv: 1147 elements of 0.2 mm,
// 6.2 × 14 mm, its pressure and traction on the rail, ν = 0.28). Its largest von Mises stress lies
// 0.7 mm inside the edge of the loaded width, below a pressure lobe at the patch's side; the
// former search (9 rows over the middle 0.8 of the width) found 369.4 MPa there.
// References, both of the same load:
// - the brute-force maximum of mhcontact's own stresses (grid_stress): von Mises on every row's
//   element centres at 0.5 … 1 mm to locate it, then on a 0.025 mm grid of (x, y, z) about that
//   point; the orthogonal shear amplitude (half the range of σ_xz along x, 0 included) on every
//   row, x every 0.05 mm over the grid and beyond, depths every 0.025 mm (the hidden
//   "[.peaks_brute]" below prints them, about 30 s);
// - CONTACT module 1's per-depth maxima on its own points (every element along x, every second
//   row, depths 0.25 … 3 mm: tread_yaw_depths.csv): the largest over its depths.
// Tolerances at about 1.5 × the differences measured on 29 Nov 2026 (below).
// Broken once: the former coarse rows over the middle 0.8 of the loaded width, without the
// lateral refinement (see the report of the commit).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/rcf/grid_subsurface.hpp"
#include "support/contact_elements.hpp"
#include "support/data_csv.hpp"

using namespace mh;
using mh::test::csv_num;
using mh::test::read_data_csv;

namespace {

constexpr double kMPa = 1e6, kMm = 1e-3;
const std::string kDir = "contact_subsurface_wheelrail/";

// CONTACT's elements of the tread case as a GridLoad (its traction is on the rail, the body of the
// stresses).
GridLoad contact_tread_load() {
  const CsvTable e = read_data_csv(kDir + "tread_yaw_pressure.csv");
  REQUIRE(e.rows.size() == 1147);
  return mh::test::grid_load_from_elements(e, 0.2 * kMm, 0.2 * kMm, 0.28, "s_mm", "ps_MPa");
}

// CONTACT's largest von Mises stress and orthogonal shear amplitude over its depths [MPa].
std::pair<double, double> contact_maxima() {
  const CsvTable t = read_data_csv(kDir + "tread_yaw_depths.csv");
  double vm = 0, orth = 0;
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    vm = std::max(vm, csv_num(t, k, "vm_max_MPa")), orth = std::max(orth, csv_num(t, k, "orth_amp_MPa"));
  return {vm, orth};
}

}  // namespace

TEST_CASE("Grid subsurface peaks: the search finds the whole patch's maxima (CONTACT's A-2.2 tread load)",
          "[rcf][subsurface][grid][contact]") {
  const GridLoad G = contact_tread_load();
  const SubsurfacePeaks P = grid_subsurface_peaks(G);
  const auto [vm_contact, orth_contact] = contact_maxima();
  CAPTURE(P.vm_max / kMPa, P.vm_x / kMm, P.vm_y / kMm, P.vm_z / kMm, P.tau_orth_amp / kMPa, P.tau_orth_z / kMm);
  // Measured 29 Nov 2026: the search 409.09 MPa at (−0.294, −3.251, 0.695) mm, brute force 409.29 MPa
  // at (−0.300, −3.200, 0.700) mm on its 0.025 mm grid (−0.20 MPa; 0.006, 0.051, 0.005 mm); the
  // orthogonal shear amplitude 107.753 MPa against 107.759 MPa (−0.006 MPa; the brute force's own
  // resolution, 0.05 mm along x, is of that size: tolerance 0.02 MPa). CONTACT's largest over its
  // depths 0.25 mm apart: von Mises 405.77 MPa at 0.75 mm (+3.32 MPa: its depths straddle the
  // peak at 0.70 mm), orthogonal shear amplitude 107.56 MPa (+0.20 MPa).
  CHECK(std::fabs(P.vm_max / kMPa - 409.29) <= 0.3);
  CHECK(std::fabs(P.vm_x / kMm - -0.300) <= 0.02);
  CHECK(std::fabs(P.vm_y / kMm - -3.200) <= 0.08);
  CHECK(std::fabs(P.vm_z / kMm - 0.700) <= 0.02);
  CHECK(std::fabs(P.tau_orth_amp / kMPa - 107.759) <= 0.02);
  CHECK(std::fabs(P.vm_max / kMPa - vm_contact) <= 5);
  CHECK(std::fabs(P.tau_orth_amp / kMPa - orth_contact) <= 0.3);
}

TEST_CASE("Grid subsurface peaks: brute-force maxima of CONTACT's A-2.2 tread load", "[.peaks_brute]") {
  const GridLoad G = contact_tread_load();
  // Von Mises: every row (and one beyond), element centres (and three beyond), then a 0.025 mm grid.
  double gb = 0, gx = 0, gy = 0, gz = 0;
  for (double z : {0.5e-3, 0.6e-3, 0.7e-3, 0.8e-3, 1.0e-3})
    for (int j = -1; j <= G.ny; ++j)
      for (int i = -3; i < G.nx + 3; ++i) {
        const double x = G.x0 + i * G.dx, y = G.y0 + j * G.dy, v = von_mises(grid_stress(G, x, y, z));
        if (v > gb) gb = v, gx = x, gy = y, gz = z;
      }
  double b = 0, bx = 0, by = 0, bz = 0;
  for (int c = -6; c <= 6; ++c)
    for (int r = -12; r <= 12; ++r)
      for (int a = -12; a <= 12; ++a) {
        const double x = gx + a * 0.025e-3, y = gy + r * 0.025e-3, z = gz + c * 0.025e-3;
        const double v = von_mises(grid_stress(G, x, y, z));
        if (v > b) b = v, bx = x, by = y, bz = z;
      }
  // The orthogonal shear amplitude: every row, x every 0.05 mm, depths 0.5 … 1 mm every 0.025 mm.
  double ob = 0, oy = 0, oz = 0;
  for (int c = 0; c <= 20; ++c) {
    const double z = 0.5e-3 + c * 0.025e-3;
    for (int j = -1; j <= G.ny; ++j) {
      const double y = G.y0 + j * G.dy;
      double lo = 0, hi = 0;
      for (double x = G.x0 - 0.6e-3; x <= G.x0 + (G.nx - 1) * G.dx + 0.6e-3; x += 0.05e-3) {
        const double s = grid_stress(G, x, y, z).xz;
        lo = std::min(lo, s), hi = std::max(hi, s);
      }
      if (0.5 * (hi - lo) > ob) ob = 0.5 * (hi - lo), oy = y, oz = z;
    }
  }
  const SubsurfacePeaks P = grid_subsurface_peaks(G);
  WARN("brute force: von Mises " << b / kMPa << " MPa at (" << bx / kMm << ", " << by / kMm << ", " << bz / kMm
                                 << ") mm; orthogonal shear amplitude " << ob / kMPa << " MPa at y " << oy / kMm << ", z "
                                 << oz / kMm << " mm");
  WARN("search: von Mises " << P.vm_max / kMPa << " MPa at (" << P.vm_x / kMm << ", " << P.vm_y / kMm << ", "
                            << P.vm_z / kMm << ") mm; orthogonal shear amplitude " << P.tau_orth_amp / kMPa << " MPa at z "
                            << P.tau_orth_z / kMm << " mm; tau_max " << P.tau_max / kMPa << ", tau_eq,a "
                            << P.tau_eq_amp / kMPa);
}
