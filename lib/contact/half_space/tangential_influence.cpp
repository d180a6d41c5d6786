// Tangential influence coefficients of the half-space (sources and closed forms in
// tangential_influence.hpp).
#include "contact/half_space/tangential_influence.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "core/units.hpp"

namespace mh {

namespace {

/// T(u, v) = ∫₀ᵘ∫₀ᵛ s²/(s²+t²)^{3/2} dt ds = v asinh(u/|v|); 0 where v = 0 (its limit).
double cerruti_corner(double u, double v) { return v != 0.0 ? v * std::asinh(u / std::fabs(v)) : 0.0; }

}  // namespace

void TangentialInfluence::check(int nx, int ny, double dx, double dy, double G, double nu) {
  if (nx < 1 || ny < 1 || !(dx > 0) || !(dy > 0) || !std::isfinite(dx) || !std::isfinite(dy))
    throw std::invalid_argument("TangentialInfluence: grid " + std::to_string(nx) + " × " +
                                std::to_string(ny) + " of " + std::to_string(dx) + " × " +
                                std::to_string(dy) + " m: needs ≥ 1 × 1 elements of size > 0");
  if (!(G > 0) || !std::isfinite(G))
    throw std::invalid_argument("TangentialInfluence: G = " + std::to_string(G) +
                                " Pa: the combined modulus of rigidity must be > 0 and finite");
  if (!(nu >= 0) || !(nu < 0.5))
    throw std::invalid_argument("TangentialInfluence: nu = " + std::to_string(nu) +
                                ": Poisson's ratio must be in [0, 0.5)");
}

double cerruti_rectangle_xx(double x, double y, double a, double b) {
  // Paired as love_rectangle: bitwise even in x and in y.
  return (cerruti_corner(a + x, b + y) + cerruti_corner(a - x, b + y)) +
         (cerruti_corner(a + x, b - y) + cerruti_corner(a - x, b - y));
}

double cerruti_rectangle_yy(double x, double y, double a, double b) {
  return cerruti_rectangle_xx(y, x, b, a);
}

double cerruti_rectangle_xy(double x, double y, double a, double b) {
  return (std::hypot(x - a, y + b) - std::hypot(x + a, y + b)) +
         (std::hypot(x + a, y - b) - std::hypot(x - a, y - b));
}

double TangentialKernel::xx(int i, int j) const {
  const double x = i * dx, y = j * dy, a = 0.5 * dx, b = 0.5 * dy;
  return ((1 - nu) * love_rectangle(x, y, a, b) + nu * cerruti_rectangle_xx(x, y, a, b)) / (units::pi * G);
}
double TangentialKernel::yy(int i, int j) const {
  const double x = i * dx, y = j * dy, a = 0.5 * dx, b = 0.5 * dy;
  return ((1 - nu) * love_rectangle(x, y, a, b) + nu * cerruti_rectangle_yy(x, y, a, b)) / (units::pi * G);
}
void TangentialKernel::xx_yy(int i, int j, double* axx, double* ayy) const {
  const double x = i * dx, y = j * dy, a = 0.5 * dx, b = 0.5 * dy;
  const double L = love_rectangle(x, y, a, b);
  *axx = ((1 - nu) * L + nu * cerruti_rectangle_xx(x, y, a, b)) / (units::pi * G);
  *ayy = ((1 - nu) * L + nu * cerruti_rectangle_yy(x, y, a, b)) / (units::pi * G);
}
double TangentialKernel::xy(int i, int j) const {
  return nu * cerruti_rectangle_xy(i * dx, j * dy, 0.5 * dx, 0.5 * dy) / (units::pi * G);
}

TangentialInfluence::TangentialInfluence(int nx, int ny, double dx, double dy, double G, double nu)
    : G_((check(nx, ny, dx, dy, G, nu), G)), nu_(nu),
      xx_(nx, ny, dx, dy, [k = TangentialKernel{dx, dy, G, nu}](int i, int j) { return k.xx(i, j); }),
      yy_(nx, ny, dx, dy, [k = TangentialKernel{dx, dy, G, nu}](int i, int j) { return k.yy(i, j); }),
      xy_(nx, ny, dx, dy, [k = TangentialKernel{dx, dy, G, nu}](int i, int j) { return k.xy(i, j); }),
      tmp_(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny)) {}

double TangentialInfluence::Axx(int dix, int diy) const { return xx_.coefficient(dix, diy); }
double TangentialInfluence::Ayy(int dix, int diy) const { return yy_.coefficient(dix, diy); }
double TangentialInfluence::Axy(int dix, int diy) const { return xy_.coefficient(dix, diy); }

void TangentialInfluence::apply(const double* px, const double* py, double* ux, double* uy) const {
  const std::size_t n = tmp_.size();
  xx_.apply(px, ux);
  if (nu_ == 0) {  // Aₓᵧ ≡ 0
    yy_.apply(py, uy);
    return;
  }
  xy_.apply(py, tmp_.data());
  for (std::size_t e = 0; e < n; ++e) ux[e] += tmp_[e];
  yy_.apply(py, uy);
  xy_.apply(px, tmp_.data());
  for (std::size_t e = 0; e < n; ++e) uy[e] += tmp_[e];
}

}  // namespace mh
