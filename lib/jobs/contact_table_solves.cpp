// The direct solves of a contact table (contact_table_solves.hpp).
#include "jobs/contact_table_solves.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <string>

#include "contact/solve.hpp"
#include "contact/tangential/kalker.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "core/errors.hpp"
#include "core/units.hpp"

namespace mh {

NodeSolve extract(const CaseResult& r, double nu) {
  NodeSolve n;
  n.status = r.status;
  if (is_failure(r.status)) return n;
  n.pmax = r.pmax;
  n.area = r.area;
  n.Fy = r.Fy;
  auto kalker = [&](NodeContact& c) {
    const double a = c.v[kTabAEl], b = c.v[kTabBEl];
    const KalkerCoefficients k = a > 0 && b > 0 ? kalker_coefficients(a / b, nu) : KalkerCoefficients{};
    c.v[kTabC11] = k.C11;
    c.v[kTabC22] = k.C22;
    c.v[kTabC23] = k.C23;
  };
  for (const LoadedEllipse& L : r.loaded) {
    NodeContact c;
    c.v[kTabN] = L.s.N;
    c.v[kTabYRail] = L.g.y_r;
    c.v[kTabZRail] = L.z_r;
    c.v[kTabYWheel] = L.g.y_w;
    c.v[kTabGamma] = L.g.gamma;
    c.v[kTabRRoll] = L.g.r_roll;
    c.v[kTabPmax] = L.s.p_max;
    c.v[kTabArea] = units::pi * L.s.a * L.s.b;
    c.v[kTabA] = c.v[kTabAEl] = L.s.a;
    c.v[kTabB] = c.v[kTabBEl] = L.s.b;
    kalker(c);
    c.y_lo = L.g.y_r - L.s.b * L.cos_gamma;
    c.y_hi = L.g.y_r + L.s.b * L.cos_gamma;
    n.contacts.push_back(c);
  }
  for (const PatchResult& P : r.patches) {
    NodeContact c;
    const double cg = std::cos(P.gamma);
    c.v[kTabN] = P.N;
    c.v[kTabYRail] = P.y_r;
    c.v[kTabZRail] = P.z_r;
    c.v[kTabYWheel] = P.y_w;
    c.v[kTabGamma] = P.gamma;
    c.v[kTabRRoll] = P.r_roll;
    c.v[kTabPmax] = P.pmax;
    c.v[kTabArea] = P.area;
    c.v[kTabA] = 0.5 * P.length_x;
    c.v[kTabB] = 0.5 * P.width_s;
    // The equivalent ellipse: the elastic Hertz ellipse of N on the patch's curvatures where the
    // patch has one (PatchResult::a_el), else the patch's half extents.
    const bool el = std::isfinite(P.a_el) && std::isfinite(P.b_el) && P.a_el > 0 && P.b_el > 0;
    c.v[kTabAEl] = el ? P.a_el : c.v[kTabA];
    c.v[kTabBEl] = el ? P.b_el : c.v[kTabB];
    kalker(c);
    c.y_lo = P.y_r + std::min(P.s_lo, P.s_hi) * cg;
    c.y_hi = P.y_r + std::max(P.s_lo, P.s_hi) * cg;
    n.contacts.push_back(c);
  }
  std::sort(n.contacts.begin(), n.contacts.end(),
            [](const NodeContact& a, const NodeContact& b) { return a.v[kTabYRail] < b.v[kTabYRail]; });
  return n;
}

std::vector<NodeSolve> solve_points(const CaseFile& cf, const PairGeometry& pg, const std::vector<TablePoint>& pts,
                                    Pool& pool) {
  std::vector<NodeSolve> out(pts.size());
  double G = 0, nu = 0;
  combined_elastic(cf.material, G, nu);
  const MethodOptions base = cf.method_options();
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(pool.size());
  pool.run([&](unsigned t) {
    try {
      GridWorkspace ws;
      CaseResult r;
      MethodOptions mo = base;
      for (;;) {
        const std::size_t k = next.fetch_add(1);
        if (k >= pts.size()) break;
        mo.multi_hertzian.roll = pts[k].roll_mrad * 1e-3;
        solve_contact(pg.geo, cf.material, pts[k].tY_mm * units::mm, pts[k].Q_kN * 1e3, mo, r, &ws);
        out[k] = extract(r, nu);
      }
    } catch (...) {
      errors[t] = std::current_exception();
      next = pts.size();
    }
  });
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

namespace {

nlohmann::json num(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

double num_from(const nlohmann::json& j, const std::string& where) {
  if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!j.is_number()) throw InputError(where, j.dump(), "must be a number or null");
  return j.get<double>();
}

bool status_from(const std::string& s, CaseStatus& out) {
  for (CaseStatus c : {CaseStatus::Ok, CaseStatus::OutsideValidity, CaseStatus::NoContact, CaseStatus::OutOfRange,
                       CaseStatus::NotConverged, CaseStatus::Derailed})
    if (s == to_string(c)) return out = c, true;
  return false;
}

}  // namespace

nlohmann::json solve_to_json(const NodeSolve& s) {
  nlohmann::json j;
  j["status"] = to_string(s.status);
  j["pmax"] = num(s.pmax);
  j["area"] = num(s.area);
  j["Fy"] = num(s.Fy);
  nlohmann::json cs = nlohmann::json::array();
  for (const NodeContact& c : s.contacts) {
    nlohmann::json v = nlohmann::json::array();
    for (double x : c.v) v.push_back(num(x));
    cs.push_back({{"v", v}, {"y_lo", num(c.y_lo)}, {"y_hi", num(c.y_hi)}});
  }
  j["contacts"] = cs;
  return j;
}

NodeSolve solve_from_json(const nlohmann::json& j, const std::string& where) {
  NodeSolve s;
  if (!j.is_object() || !j.contains("status") || !j["status"].is_string() || !status_from(j["status"].get<std::string>(), s.status))
    throw InputError(where + "/status", j.is_object() && j.contains("status") ? j["status"].dump() : "",
                     "a solve has a status, one of the cases.csv words");
  s.pmax = num_from(j.value("pmax", nlohmann::json()), where + "/pmax");
  s.area = num_from(j.value("area", nlohmann::json()), where + "/area");
  s.Fy = num_from(j.value("Fy", nlohmann::json()), where + "/Fy");
  if (!j.contains("contacts") || !j["contacts"].is_array()) throw InputError(where + "/contacts", "", "must be an array");
  for (std::size_t k = 0; k < j["contacts"].size(); ++k) {
    const nlohmann::json& c = j["contacts"][k];
    const std::string at = where + "/contacts/" + std::to_string(k);
    if (!c.is_object() || !c.contains("v") || !c["v"].is_array() || c["v"].size() != kTableQuantities)
      throw InputError(at + "/v", "", "a contact has v, an array of " + std::to_string(kTableQuantities) + " numbers");
    NodeContact n;
    for (int q = 0; q < kTableQuantities; ++q) n.v[static_cast<std::size_t>(q)] = num_from(c["v"][static_cast<std::size_t>(q)], at + "/v");
    n.y_lo = num_from(c.value("y_lo", nlohmann::json()), at + "/y_lo");
    n.y_hi = num_from(c.value("y_hi", nlohmann::json()), at + "/y_hi");
    s.contacts.push_back(n);
  }
  return s;
}

}  // namespace mh
