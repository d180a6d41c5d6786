#pragma once
// The exact elastic half-space method (docs/method.md §8): per case, the contact patches are the
// separate interpenetration regions of the undeformed profiles at the rigid vertical approach δz
// (regions closer than d_comb are one patch); each patch gets its own tangent plane at its
// reference point (CONTACT's planar contact approach), a grid of dx × ds elements of uniform
// pressure, the half-space influence of Love's rectangle (contact/half_space/influence.hpp) and the
// constrained conjugate-gradient solver (contact/half_space/normal_cg.hpp), with the pressure capped at
// p_lim in the plastic model. All patches share δz, and Σ_k N_k cos γ_k = Q (eq. 10) closes the
// problem. Frictionless; no conformal correction beyond the per-patch plane.
#include <memory>
#include <string>

#include "contact/options.hpp"
#include "contact/case_result.hpp"
#include "contact/ellipse/hertz.hpp"
#include "contact/half_space/normal_cg.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {


/// Solve one case. `material.p_lim` finite caps the pressure (plastic model). Never throws for a
/// numerical reason: the status says what happened (`not_converged` with a message).
/// `elastic_mh`: the elastic multi-Hertzian solution of the same case, the start (GridStart in
/// contact/grid/patch_driver.hpp), when the caller has it; null: solved here.
CaseResult solve_half_space(const ContactGeometry& G, const Material& material, double tY, double Q,
                            const HalfSpaceOptions& opt, const CaseResult* elastic_mh = nullptr);

/// One thread's memory for half-space cases: the patch solvers with their grids, the influence
/// operators with their FFT plans and buffers (InfluenceGrid, kept by nx, ny, dx, dy and
/// compliance; beyond kInfluenceGrids one of an earlier case is rebuilt in its own buffers for
/// the new grid), the conjugate-gradient vectors, the driver's vectors and the physical checks'
/// inputs. Made empty (no allocation);
/// grows on first use. Used by one thread at a time; it carries no data from case to case that
/// the result depends on (the same bytes as without it).
class HalfSpaceWorkspace {
 public:
  /// Influence operators kept (a case uses one per patch and placement, usually 1–4).
  static constexpr int kInfluenceGrids = 24;
  HalfSpaceWorkspace();
  ~HalfSpaceWorkspace();
  HalfSpaceWorkspace(HalfSpaceWorkspace&&) noexcept;
  HalfSpaceWorkspace& operator=(HalfSpaceWorkspace&&) noexcept;
  HalfSpaceWorkspace(const HalfSpaceWorkspace&) = delete;
  HalfSpaceWorkspace& operator=(const HalfSpaceWorkspace&) = delete;
  struct Impl;  ///< half_space_method.cpp
  Impl& impl();

 private:
  std::unique_ptr<Impl> impl_;
};

/// r's patches (results of this method) handed to `ws` for the capacity of their vectors, which
/// the next solve into any result reuses; r.patches is left empty.
void recycle_patches(HalfSpaceWorkspace& ws, CaseResult& r);

/// The same into `out` (reset first, its vectors keeping their capacity) with the memory of `ws`:
/// once `ws` and `out` have seen a case of the same pair with patches as large, a call allocates
/// nothing (a status message aside). The same bytes as the form above.
void solve_half_space(const ContactGeometry& G, const Material& material, double tY, double Q,
                      const HalfSpaceOptions& opt, HalfSpaceWorkspace& ws, CaseResult& out,
                      const CaseResult* elastic_mh = nullptr);

}  // namespace mh
