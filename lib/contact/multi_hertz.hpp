#pragma once
// Multi-Hertzian normal contact (paper eqs. 10–11, method.md §4): at a lateral position t_Y and a
// vertical load Q, find the vertical virtual penetration δz with
//     Σ_i N_i cos γ_i = Q                                   (10)
//     h0_i = (δz − (z_wi − z_ri)) cos γ_i                    (11)
// N_i = 0 for h0_i ≤ 0, else N(h0_i) of ellipse i (eq. 8, or the plastic law of method.md §5).
// Every case returns a status; a failing case never throws.
#include <string>
#include <vector>

#include "geometry/contact_geometry.hpp"
#include "contact/ellipse_law.hpp"

namespace mh {

/// The outcome of one case's solve (a batch's `invalid_pair` is not a solver outcome: jobs/batch.hpp).
enum class CaseStatus { Ok, NoContact, OutOfRange, NotConverged };
const char* to_string(CaseStatus s);

struct SolverOptions {
  double rtol = 1e-12;     ///< converged when |Σ N_i cos γ_i − Q| ≤ rtol·Q (default 1e-12)
  int max_iterations = 60; ///< safeguarded Newton iterations before `not_converged` (default 60)
  bool exact_coefficients = false;  ///< Hertz m, n, ρ from GSL instead of the fast table (default: table)
  bool valid(std::string* why) const;
};

/// One loaded ellipse of a solved case.
struct LoadedEllipse {
  int ellipse = 0;          ///< 1-based index of the potential ellipse
  CandidateGeom g;          ///< its strip (interpolated at the case's t_Y)
  double A = 0, B = 0;      ///< [1/m] (eq. 1)
  HertzCoefficients c;
  double h_y = INFINITY;    ///< [m] yield penetration of its law (method.md §5); INFINITY when elastic
  EllipseState s;           ///< h0, N, a, b, p0, ... (hertz.hpp)
};

struct CaseResult {
  CaseStatus status = CaseStatus::Ok;
  std::string message;               ///< why, when not ok
  std::vector<std::string> warnings; ///< e.g. a non-Hertzian candidate that would have touched
  double dz = 0;          ///< [m] vertical virtual penetration δz, from the geometric contact position
  int iterations = 0;
  double residual = 0;    ///< (Σ N_i cos γ_i − Q) / Q at the end
  double Fz = 0, Fy = 0;  ///< [N] Σ N_i cos γ_i and Σ N_i sin γ_i (lateral, towards the field side)
  std::vector<LoadedEllipse> loaded;  ///< in increasing ellipse index
};

/// Solve one case. Candidates whose curvature sum B ≤ 0 (conformal: a concave wheel root on a rail
/// corner of nearly the same radius) have no Hertz ellipse: they are excluded, and when such a
/// candidate would have been loaded (h0 > 0 at the solution) the case carries a warning
/// "non_hertzian_excluded:ellipse=K". Q ≤ 0 or not finite gives `no_contact` with a message.
CaseResult solve_case(const ContactGeometry& G, const Material& mat, double tY, double Q,
                      const SolverOptions& opt = {});

}  // namespace mh
