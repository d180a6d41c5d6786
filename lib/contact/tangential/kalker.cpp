// Kalker's creepage coefficients (kalker.hpp). The table values are those of Kalker 1990, Table E.3.
#include "contact/tangential/kalker.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace mh {
namespace {

// Kalker 1990, Table E.3. Rows g = 0.1, 0.2, …, 1.0 where g = a/b (kNarrow: a < b, the patch
// short along the rolling direction) or g = b/a (kLong: a > b). Per row: C11 at ν = 0, 0.25, 0.5,
// then C22, then C23, then C33 at the same ν. The row g = 1 is the circle in both halves.
// (A circulating copy has C23 = 1.15 at a/b = 0.8, ν = 0.25; the table has 1.25: the column steps
// by about 0.11 there. tests/unit/contact/test_kalker.cpp guards it.)
// C33 as a public copy of the table gives it (kalker.hpp: the source, its two-decimal rounding
// below 1, and CONTACT's check of the column).
struct Row { double c11[3], c22[3], c23[3], c33[3]; };
constexpr Row kNarrow[10] = {
    {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}},
    {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}},
    {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}},
    {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}},
    {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}},
    {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}},
    {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}},
    {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}},
    {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}},
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}},
};
constexpr Row kLong[10] = {
    {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.80, 0.53, 0.23}},
    {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.83, 0.60, 0.34}},
    {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.87, 0.67, 0.45}},
    {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.91, 0.75, 0.55}},
    {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.96, 0.82, 0.65}},
    {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.89, 0.75}},
    {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.97, 0.85}},
    {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.95}},
    {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}},
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}},
};

// The quadratic in ν through (0, 1/C0), (0.25, 1/C1), (0.5, 1/C2), inverted (Lagrange basis).
double interp_nu(const double c[3], double nu) {
  const double inv = (nu - 0.25) * (nu - 0.5) / (0.25 * 0.5) / c[0]
                   - nu * (nu - 0.5) / (0.25 * 0.25) / c[1]
                   + nu * (nu - 0.25) / (0.5 * 0.25) / c[2];
  return 1.0 / inv;
}

}  // namespace

KalkerCoefficients kalker_coefficients(double a_over_b, double nu) {
  assert(a_over_b > 0 && nu >= 0 && nu <= 0.5);
  constexpr double pi = M_PI;
  KalkerCoefficients k;
  const bool narrow = a_over_b <= 1.0;
  const double g = narrow ? a_over_b : 1.0 / a_over_b;
  if (g < kKalkerTableMin) {
    // Slender ellipses, Kalker 1990 Appendix E (the asymptotes as g → 0). C33 stays NaN (kalker.hpp).
    k.asymptote = true;
    if (narrow) {  // a ≪ b: the two-dimensional limit across the rolling direction
      k.C11 = pi * pi / (4.0 * (1.0 - nu));
      k.C22 = pi * pi / 4.0;
      k.C23 = pi * std::sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (std::log(16.0 / g) - 5.0));
    } else {       // a ≫ b
      const double L = std::log(16.0 / (g * g));
      const double k3 = 3.0 - std::log(4.0);
      k.C11 = 2.0 * pi / ((L - 2.0 * nu) * g) * (1.0 + k3 / (L - 2.0 * nu));
      const double d = (1.0 - nu) * L + 2.0 * nu;
      k.C22 = 2.0 * pi / g * (1.0 + (1.0 - nu) * k3 / d) / d;
      k.C23 = 2.0 * pi / (3.0 * std::pow(g, 1.5) * ((1.0 - nu) * L - 2.0 + 4.0 * nu));
    }
    return k;
  }
  // Linear in g between the rows g = 0.1 i (i = 1 … 10); row index of the lower neighbour.
  const Row* t = narrow ? kNarrow : kLong;
  int i = std::clamp(static_cast<int>(10.0 * g - 0.005), 1, 9);  // g ∈ [0.1 i, 0.1 (i + 1)]
  const double w = 10.0 * g - i;
  const Row& lo = t[i - 1];
  const Row& hi = t[i];
  double c11[3], c22[3], c23[3], c33[3];
  for (int j = 0; j < 3; ++j) {
    c11[j] = (1 - w) * lo.c11[j] + w * hi.c11[j];
    c22[j] = (1 - w) * lo.c22[j] + w * hi.c22[j];
    c23[j] = (1 - w) * lo.c23[j] + w * hi.c23[j];
    c33[j] = (1 - w) * lo.c33[j] + w * hi.c33[j];
  }
  k.C11 = interp_nu(c11, nu);
  k.C22 = interp_nu(c22, nu);
  k.C23 = interp_nu(c23, nu);
  k.C33 = interp_nu(c33, nu);
  return k;
}

TangentialResult kalker_linear(const Creepages& cr, double a, double b, double G, double nu) {
  const KalkerCoefficients k = kalker_coefficients(a / b, nu);
  const double c = std::sqrt(a * b);
  TangentialResult r;
  r.c = cr;
  r.Fx = -G * c * c * k.C11 * cr.xi;
  r.Fy = -G * c * c * k.C22 * cr.eta - G * c * c * c * k.C23 * cr.phi;
  // Mz = G c³ C23 η − G c⁴ C33 φ; without C33 (slender ellipses, kalker.hpp) the φ term is unknown.
  const double spin_term = cr.phi == 0 ? 0.0 : G * c * c * c * c * k.C33 * cr.phi;
  r.Mz = G * c * c * c * k.C23 * cr.eta - spin_term;
  r.Tgamma = -(r.Fx * cr.xi + r.Fy * cr.eta);
  r.Tgamma_spin = -r.Mz * cr.phi;
  r.solved = true;
  return r;
}

}  // namespace mh
