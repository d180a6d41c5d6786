// The line contact's first-yield limit with traction (shakedown.hpp): the largest von Mises
// stress of McEwen's field (subsurface.hpp, mcewen_stress), searched below the surface and on it.
#include "contact/rcf/shakedown.hpp"

#include <array>
#include <cstdint>

#include "contact/rcf/subsurface.hpp"

namespace mh {

namespace {

// [p0] The largest von Mises stress of McEwen's field at traction f and Poisson's ratio ν: below
// the surface a grid (x −1.5 … 1.5 a, z 0.02 … 1.5 a, every 0.05 a) then a compass search from
// its best point down to steps of 1e-7 a; on the surface (z = 0) every 0.01 a over −1.5 … 1.5 a,
// then a golden section around the best. Both maxima are kept apart: traction moves the peak from
// below the surface (0.70 a at f = 0) to the surface (f ≈ 0.27 at ν = 0.3).
double line_vm_peak(double f, double nu) {
  auto vm = [&](double x, double z) { return von_mises(mcewen_stress(x, z, f, nu)); };
  double best = 0, xb = 0, zb = 0.5;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 29; ++j) {
      const double x = -1.5 + 0.05 * i, z = 0.02 + 0.05 * j, v = vm(x, z);
      if (v > best) best = v, xb = x, zb = z;
    }
  for (double h = 0.025; h > 1e-7; h *= 0.5) {
    bool moved = true;
    while (moved) {
      moved = false;
      for (const auto& d : std::array<std::array<double, 2>, 4>{{{h, 0}, {-h, 0}, {0, h}, {0, -h}}}) {
        const double x = xb + d[0], z = std::max(0.0, zb + d[1]), v = vm(x, z);
        if (v > best) best = v, xb = x, zb = z, moved = true;
      }
    }
  }
  double sb = 0, xs = 0;
  for (int i = 0; i <= 300; ++i) {
    const double x = -1.5 + 0.01 * i, v = vm(x, 0);
    if (v > sb) sb = v, xs = x;
  }
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double a = xs - 0.01, b = xs + 0.01, c = b - g * (b - a), d = a + g * (b - a), fc = vm(c, 0), fd = vm(d, 0);
  while (b - a > 1e-9) {
    if (fc >= fd) b = d, d = c, fd = fc, c = b - g * (b - a), fc = vm(c, 0);
    else a = c, c = d, fc = fd, d = a + g * (b - a), fd = vm(d, 0);
  }
  return std::max({best, sb, fc, fd});
}

constexpr double kDf = 0.0125;  // the table's step in f
constexpr int kNf = 81;         // f = 0 … 1

// √3 / line_vm_peak at f = 0, 0.0125, … 1 for one ν, made on first use per thread (about 8 ms).
struct FirstYieldTable {
  double nu = NAN;
  std::array<double, kNf> E{};
  void make(double nu_) {
    nu = nu_;
    for (int i = 0; i < kNf; ++i) E[static_cast<std::size_t>(i)] = std::sqrt(3.0) / line_vm_peak(kDf * i, nu);
  }
};

}  // namespace

double line_first_yield_limit(double f, double nu) {
  if (!(f >= 0) || !std::isfinite(nu)) return NAN;
  if (f > kDf * (kNf - 1)) return std::sqrt(3.0) / line_vm_peak(f, nu);
  // A few tables per thread, the least recently used replaced (a run has one ν or two).
  constexpr int kSlots = 4;
  thread_local FirstYieldTable t[kSlots];
  thread_local std::uint64_t used[kSlots] = {};
  thread_local std::uint64_t clock = 0;
  ++clock;
  int slot = -1, lru = 0;
  for (int i = 0; i < kSlots; ++i) {
    if (t[i].nu == nu) slot = i;
    if (used[i] < used[lru]) lru = i;
  }
  if (slot < 0) t[lru].make(nu), slot = lru;
  used[slot] = clock;
  const std::array<double, kNf>& E = t[slot].E;
  const double u = f / kDf;
  const int i = std::min(static_cast<int>(u), kNf - 2);
  return E[static_cast<std::size_t>(i)] + (E[static_cast<std::size_t>(i) + 1] - E[static_cast<std::size_t>(i)]) * (u - i);
}

}  // namespace mh
