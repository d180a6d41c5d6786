#include "contact/options.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/numfmt.hpp"

namespace mh {

const char* to_string(Method m) {
  switch (m) {
    case Method::MultiHertzian: return "multi-hertzian";
    case Method::HalfSpace: return "half-space";
    case Method::Strips: return "strips";
    case Method::Auto: return "auto";
  }
  return "?";
}

Method parse_method(const std::string& s) {
  if (s == "multi-hertzian") return Method::MultiHertzian;
  if (s == "half-space") return Method::HalfSpace;
  if (s == "strips") return Method::Strips;
  if (s == "auto") return Method::Auto;
  throw std::invalid_argument("unknown method '" + s + "' (expected multi-hertzian, half-space, strips or auto)");
}

bool Material::valid(std::string* why) const {
  auto fail = [&](const std::string& s) {
    if (why) *why = s;
    return false;
  };
  if (!(E > 0) || !std::isfinite(E))
    return fail("Material.E = " + format_number(E) + " Pa: Young's modulus must be > 0 and finite");
  if (!(nu > 0 && nu < 0.5))
    return fail("Material.nu = " + format_number(nu) + ": Poisson's ratio must be in (0, 0.5)");
  if (!std::isnan(E_rail) && (!(E_rail > 0) || !std::isfinite(E_rail)))
    return fail("Material.E_rail = " + format_number(E_rail) + " Pa: Young's modulus must be > 0 and finite");
  if (!std::isnan(nu_rail) && !(nu_rail > 0 && nu_rail < 0.5))
    return fail("Material.nu_rail = " + format_number(nu_rail) + ": Poisson's ratio must be in (0, 0.5)");
  if (!std::isnan(yield) && (!(yield > 0) || !std::isfinite(yield)))
    return fail("Material.yield = " + format_number(yield) + " Pa: the yield stress must be > 0 and finite (NaN: not given)");
  if (!std::isnan(yield_rail) && (!(yield_rail > 0) || !std::isfinite(yield_rail)))
    return fail("Material.yield_rail = " + format_number(yield_rail) +
                " Pa: the yield stress must be > 0 and finite (NaN: same as yield)");
  if (!(p_lim > 0))
    return fail("Material.p_lim = " + format_number(p_lim) +
                " Pa: the limit pressure must be > 0 (INFINITY for an elastic contact)");
  if (yield_law && std::isnan(yield_min()))
    return fail("Material.yield_law = true without a yield stress: set Material.yield (the yield law's first "
                "yield is 1.6 sigma_y) or clear yield_law for the law capped at p_lim");
  return true;
}

bool derive_plastic_law(Material& m) {
  if (!std::isfinite(m.p_lim) && !std::isnan(m.yield_min())) {
    m.p_lim = p_lim_from_yield(m.yield_min());
    m.yield_law = true;
  }
  return std::isfinite(m.p_lim);
}

bool HertzValidityOptions::valid(std::string* why) const {
  if (!(max_b_over_R > 0) || !std::isfinite(max_b_over_R)) {
    if (why) *why = "max_b_over_R must be > 0 and finite";
    return false;
  }
  if (!(max_gap_error > 0) || !std::isfinite(max_gap_error)) {
    if (why) *why = "max_gap_error must be > 0 and finite";
    return false;
  }
  if (!(max_gap_mean_error > 0) || !std::isfinite(max_gap_mean_error)) {
    if (why) *why = "max_gap_mean_error must be > 0 and finite";
    return false;
  }
  return true;
}

bool MultiHertzOptions::valid(std::string* why) const {
  if (!(rtol > 0 && rtol < 1e-3)) { if (why) *why = "rtol must be in (0, 1e-3)"; return false; }
  if (max_iterations < 1 || max_iterations > 10000) { if (why) *why = "max_iterations must be in [1, 10000]"; return false; }
  if (!(std::fabs(roll) <= 0.05)) { if (why) *why = "roll must be within [-0.05, 0.05] rad"; return false; }
  if (!validity.valid(why)) return false;
  return true;
}

bool NormalCGOptions::valid(std::string* why) const {
  auto fail = [&](const char* field, double value, const char* rule) {
    if (why) {
      std::ostringstream os;
      os.precision(17);
      os << "NormalCGOptions." << field << " = " << value << ": " << rule;
      *why = os.str();
    }
    return false;
  };
  if (!(tol > 0) || !std::isfinite(tol)) return fail("tol", tol, "must be > 0 and finite");
  if (max_iterations < 1) return fail("max_iterations", max_iterations, "must be >= 1");
  return true;
}

bool HalfSpaceOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& s) { if (why) *why = s; return false; };
  if (!(dx >= 0.01e-3 && dx <= 2e-3)) return fail("dx_mm = " + format_number(dx * 1e3) + ": must be in [0.01, 2] mm");
  if (!(ds >= 0.01e-3 && ds <= 2e-3)) return fail("ds_mm = " + format_number(ds * 1e3) + ": must be in [0.01, 2] mm");
  if (!(d_comb >= 0 && d_comb <= 100e-3)) return fail("d_comb_mm = " + format_number(d_comb * 1e3) + ": must be in [0, 100] mm");
  if (!(margin >= 1.0 && margin <= 4.0)) return fail("margin = " + format_number(margin) + ": must be in [1, 4]");
  if (!(force_rtol > 0 && force_rtol < 1e-2)) return fail("force_rtol = " + format_number(force_rtol) + ": must be in (0, 0.01)");
  if (max_outer < 1 || max_outer > 1000) return fail("max_outer = " + std::to_string(max_outer) + ": must be in [1, 1000]");
  if (max_rebuilds < 0 || max_rebuilds > 20) return fail("max_rebuilds = " + std::to_string(max_rebuilds) + ": must be in [0, 20]");
  if (max_refinements < 0 || max_refinements > 6) return fail("max_refinements = " + std::to_string(max_refinements) + ": must be in [0, 6]");
  if (!(std::fabs(roll) <= 0.05)) return fail("roll = " + format_number(roll) + " rad: must be within [-0.05, 0.05] rad");
  return cg.valid(why);
}

bool StripOptions::valid(std::string* why) const {
  std::ostringstream os;
  if (gauss_points < 2 || gauss_points % 2 != 0) {
    os << "gauss_points = " << gauss_points << ": must be even and >= 2";
  } else if (!(load_rtol > 0.0) || !std::isfinite(load_rtol)) {
    os << "load_rtol = " << load_rtol << ": must be positive and finite";
  } else if (max_iterations < 1) {
    os << "max_iterations = " << max_iterations << ": must be >= 1";
  } else if (max_active_set < 1) {
    os << "max_active_set = " << max_active_set << ": must be >= 1";
  } else if (!(outlier_factor > 1.0) || !std::isfinite(outlier_factor)) {
    os << "outlier_factor = " << outlier_factor << ": must be > 1 and finite";
  } else if (!(end_gap_tol >= 0.0) || !std::isfinite(end_gap_tol)) {
    os << "end_gap_tol = " << end_gap_tol << ": must be >= 0 and finite";
  } else {
    return true;
  }
  if (why) *why = os.str();
  return false;
}

bool StripMethodOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& s) { if (why) *why = s; return false; };
  if (!(ds >= 0.01e-3 && ds <= 2e-3)) return fail("ds_mm = " + format_number(ds * 1e3) + ": must be in [0.01, 2] mm");
  if (!(d_comb >= 0 && d_comb <= 100e-3)) return fail("d_comb_mm = " + format_number(d_comb * 1e3) + ": must be in [0, 100] mm");
  if (!(margin >= 1.0 && margin <= 4.0)) return fail("margin = " + format_number(margin) + ": must be in [1, 4]");
  if (!(force_rtol > 0 && force_rtol < 1e-2)) return fail("force_rtol = " + format_number(force_rtol) + ": must be in (0, 0.01)");
  if (max_outer < 1 || max_outer > 1000) return fail("max_outer must be in [1, 1000]");
  if (max_refinements < 0 || max_refinements > 6) return fail("max_refinements = " + std::to_string(max_refinements) + ": must be in [0, 6]");
  if (max_passes < 1 || max_passes > 21) return fail("max_passes must be in [1, 21]");
  if (!(x_curvature_step > 0)) return fail("x_curvature_step must be > 0");
  if (!(std::fabs(roll) <= 0.05)) return fail("roll = " + format_number(roll) + " rad: must be within [-0.05, 0.05] rad");
  return strips.valid(why);
}

}  // namespace mh
