// The elastic Hertz ellipse of each grid patch's load; see patch_elastic.hpp.
#include "contact/grid/patch_elastic.hpp"

#include <cmath>
#include <limits>

#include "contact/ellipse/hertz.hpp"

namespace mh {

void set_patch_elastic_hertz(const Material& mat, const CaseResult* mh, CaseResult& r) {
  for (PatchResult& P : r.patches) {
    P.a_el = P.b_el = std::numeric_limits<double>::quiet_NaN();
    if (!mh || !(P.N > 0)) continue;
    // The patch's lateral extent on the rail: its first and last strip, y_r + s cos γ.
    const double c = std::cos(P.gamma);
    const double lo = P.y_r + std::min(P.s_lo, P.s_hi) * c, hi = P.y_r + std::max(P.s_lo, P.s_hi) * c;
    const LoadedEllipse* best = nullptr;
    for (const LoadedEllipse& L : mh->loaded) {
      if (!(L.g.y_r >= lo && L.g.y_r <= hi && L.A > 0 && L.B > 0)) continue;
      if (!best || std::fabs(L.g.y_r - P.y_r) < std::fabs(best->g.y_r - P.y_r)) best = &L;
    }
    if (!best) continue;
    const double C = hertz_C(P.N, best->A, best->B, mat.E_star());  // (eqs. 2–3)
    P.a_el = best->c.m * C;
    P.b_el = best->c.n * C;
  }
}

}  // namespace mh
