// The subsurface search of one contact for the RCF columns (rcf_columns.hpp).
#include "output/rcf_columns.hpp"

namespace mh {

SubsurfacePeaks subsurface_of(const RcfOptions& o, double N, double a_el, double b_el, const TangentialResult& t,
                              double f) {
  if (!(N > 0 && a_el > 0 && b_el > 0 && f >= 0)) return {};
  HertzLoad L;
  L.a = a_el, L.b = b_el, L.p0 = 1.5 * N / (units::pi * a_el * b_el), L.nu = o.nu;
  const double F = std::hypot(t.Fx, t.Fy);
  if (o.actual && F > 0) L.fx = f * t.Fx / F, L.fy = f * t.Fy / F;
  else L.fx = f;
  struct Memo { HertzLoad L; SubsurfacePeaks P; bool used = false; };
  static thread_local Memo memo[8];
  static thread_local int next = 0;
  for (const Memo& m : memo)
    if (m.used && m.L.a == L.a && m.L.b == L.b && m.L.p0 == L.p0 && m.L.fx == L.fx && m.L.fy == L.fy && m.L.nu == L.nu)
      return m.P;
  Memo& m = memo[next];
  next = (next + 1) % 8;
  m.L = L, m.P = subsurface_peaks(L), m.used = true;
  return m.P;
}
}  // namespace mh
