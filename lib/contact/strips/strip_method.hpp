#pragma once
// The semi-Hertzian strip method with elastic coupling (docs/method.md §9) as a method of `run`:
// the patches, planes and vertical force balance of the grid methods (contact/grid/patch_driver.hpp),
// and in each patch lateral strips of width ds with a semi-elliptic pressure along x whose
// amplitudes are coupled through the half-space (contact/strips/strip_patch.hpp).
#include <memory>

#include "contact/options.hpp"
#include "contact/case_result.hpp"
#include "contact/ellipse/hertz.hpp"
#include "contact/strips/strip_patch.hpp"
#include "geometry/contact_geometry.hpp"

namespace mh {


/// Solve one case. `material.p_lim` finite caps the strips (plastic model, §9.6). Never throws for
/// a numerical reason. `elastic_mh`: the elastic multi-Hertzian solution of the same case, the
/// start (GridStart in contact/grid/patch_driver.hpp), when the caller has it; null: solved here.
CaseResult solve_strip_method(const ContactGeometry& G, const Material& material, double tY, double Q,
                              const StripMethodOptions& opt, const CaseResult* elastic_mh = nullptr);

/// One thread's memory for strip-method cases: the patch solvers with their strip geometries, the
/// driver's vectors and the physical checks' inputs. Made empty (no allocation); grows on first
/// use. Used by one thread at a time; it carries no data from case to case that the result
/// depends on (the same bytes as without it).
class StripWorkspace {
 public:
  StripWorkspace();
  ~StripWorkspace();
  StripWorkspace(StripWorkspace&&) noexcept;
  StripWorkspace& operator=(StripWorkspace&&) noexcept;
  StripWorkspace(const StripWorkspace&) = delete;
  StripWorkspace& operator=(const StripWorkspace&) = delete;
  struct Impl;  ///< strip_method.cpp
  Impl& impl();

 private:
  std::unique_ptr<Impl> impl_;
};

/// r's patches (results of this method) handed to `ws` for the capacity of their vectors, which
/// the next solve into any result reuses; r.patches is left empty.
void recycle_patches(StripWorkspace& ws, CaseResult& r);

/// The same into `out` (reset first, its vectors keeping their capacity) with the memory of `ws`.
/// The same bytes as the form above.
void solve_strip_method(const ContactGeometry& G, const Material& material, double tY, double Q,
                        const StripMethodOptions& opt, StripWorkspace& ws, CaseResult& out,
                        const CaseResult* elastic_mh = nullptr);

}  // namespace mh
