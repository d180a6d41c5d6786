// Tangential solution of one half-space patch (tangential_patch.hpp).
#include "contact/half_space/tangential_patch.hpp"

#include <cmath>
#include <exception>
#include <string>

namespace mh {

HalfSpaceTangentialResult solve_tangential_patch(const PatchResult& patch, const Material& material,
                                                 const Creepages& c, double mu,
                                                 const HalfSpaceTangentialOptions& options,
                                                 PatchTraction* keep,
                                                 std::unique_ptr<HalfSpaceTangentialSolver>* kept) {
  if (keep) keep->clear();
  HalfSpaceTangentialResult res;
  res.forces.c = c;
  res.forces.mu = mu;
  const bool same_E = std::isnan(material.E_rail) || material.E_rail == material.E;
  const bool same_nu = std::isnan(material.nu_rail) || material.nu_rail == material.nu;
  if (!same_E || !same_nu) {
    res.message = "material: the exact tangential half-space solution needs wheel and rail of equal "
                  "elastic constants (E_rail, nu_rail unset or equal to E, nu); got E = " +
                  std::to_string(material.E) + " Pa, E_rail = " + std::to_string(material.E_rail) +
                  " Pa, nu = " + std::to_string(material.nu) + ", nu_rail = " +
                  std::to_string(material.nu_rail);
    return res;
  }
  const std::size_t n = static_cast<std::size_t>(patch.nx) * static_cast<std::size_t>(patch.ns);
  if (patch.nx < 1 || patch.ns < 1 || patch.p.size() != n) {
    res.message = "patch " + std::to_string(patch.patch) + ": no pressure grid (nx = " +
                  std::to_string(patch.nx) + ", ns = " + std::to_string(patch.ns) + ", " +
                  std::to_string(patch.p.size()) + " pressures)";
    return res;
  }
  double G = 0, nu = 0;
  combined_elastic(material, G, nu);  // equal bodies here: G = E / (2 (1 + ν)), ν
  try {
    std::unique_ptr<HalfSpaceTangentialSolver> local;
    std::unique_ptr<HalfSpaceTangentialSolver>& slot = kept ? *kept : local;
    if (slot) slot->reset(patch.nx, patch.ns, patch.dx, patch.ds, G, nu);
    else slot = std::make_unique<HalfSpaceTangentialSolver>(patch.nx, patch.ns, patch.dx, patch.ds, G, nu);
    HalfSpaceTangentialSolver& solver = *slot;
    HalfSpaceTangentialResult out = solver.solve(patch.p.data(), patch.x0, patch.s0, c, mu, options);
    if (keep && out.status == TangentialStatus::Ok) {
      keep->nx = patch.nx;
      keep->ns = patch.ns;
      keep->dx = patch.dx;
      keep->ds = patch.ds;
      keep->x0 = patch.x0;
      keep->s0 = patch.s0;
      keep->pn = patch.p;
      keep->px = solver.px();
      keep->py = solver.py();
      keep->slip.resize(n);
      for (std::size_t i = 0; i < n; ++i) keep->slip[i] = solver.state()[i] == ElementState::Slip;
    }
    return out;
  } catch (const std::exception& e) {  // invalid grid or material, or no memory
    res.message = std::string("patch ") + std::to_string(patch.patch) + ": " + e.what();
    return res;
  }
}

void solve_tangential_patches(CaseResult& r, const Material& material, double mu, bool keep_traction,
                              TangentialPatchWorkspace* ws) {
  if (r.method != Method::HalfSpace || !r.tangential.asked || !(mu > 0)) return;
  for (std::size_t k = 0; k < r.patches.size(); ++k) {
    PatchResult& P = r.patches[k];
    const Creepages c = P.t.c;
    const HalfSpaceTangentialResult t = solve_tangential_patch(P, material, c, mu, {}, keep_traction ? &P.traction : nullptr,
                                                               ws ? &ws->slot(k) : nullptr);
    if (t.status != TangentialStatus::Ok) continue;
    P.t = t.forces;
    P.t.c = c;
    P.t.mu = mu;
  }
  sum_tangential(r, mu);
}

}  // namespace mh
