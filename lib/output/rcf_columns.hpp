#pragma once
// The RCF, subsurface, tangential, damage and wear columns of the per-contact and per-case
// tables (docs/outputs.md "RCF columns", "Subsurface columns", "Damage and wear columns";
// docs/tangential.md), written by field to a sink (case_sinks.hpp). Internal to lib/output: the
// writers of lib/output/case_tables.cpp append them. They format what the case result carries and
// what contact/rcf computes from it (the subsurface stresses, contact_stresses.hpp).
#include <cmath>

#include "contact/case_result.hpp"
#include "contact/rcf/shakedown.hpp"
#include "contact/rcf/contact_stresses.hpp"
#include "contact/rcf/subsurface.hpp"
#include "core/units.hpp"

namespace mh {

// The subsurface columns of one contact (docs/outputs.md "Subsurface columns"): the stresses of
// contact_stresses (contact/rcf/contact_stresses.hpp: which load, its peaks, FI_sub), formatted.
// `patch`: the row's grid patch, or null (an ellipse row); `cells`: an ellipse row's FASTSIM cells.
template <class Sink>
void subsurface_fields(Sink& k, const RcfOptions& o, double N, double a_el, double b_el, const TangentialResult& t,
                       double f, const PatchResult* patch = nullptr, const EllipseCells& cells = {}) {
  const ContactStresses S = contact_stresses(o, N, a_el, b_el, t, f, patch, cells);
  const SubsurfacePeaks& P = S.peaks;
  k.text("sub_source", to_string(S.source));
  k.number("sub_vm_max_MPa", P.vm_max / units::MPa);
  k.number("sub_vm_depth_mm", P.vm_z * units::per_mm);
  k.number("sub_tau_max_MPa", P.tau_max / units::MPa);
  k.number("sub_tau_depth_mm", P.tau_z * units::per_mm);
  k.number("sub_tau_orth_amp_MPa", P.tau_orth_amp / units::MPa);
  k.number("sub_tau_orth_depth_mm", P.tau_orth_z * units::per_mm);
  k.number("sub_tau_eq_amp_MPa", P.tau_eq_amp / units::MPa);
  k.number("sub_sigma_h_MPa", P.sigma_h / units::MPa);
  k.number("FI_sub_MPa", S.fi_sub / units::MPa);
}
// The RCF columns (docs/outputs.md "RCF columns"), appended last to ellipses.csv and patches.csv
// and to their JSON records: by their definitions, from the elastic Hertz patch of the load N
// (semi-axes a_el, b_el; NaN: not known, the cells empty).
// The traction coefficient is the user's f, or with friction given the contact's own |F|/N
// (RcfOptions::traction; empty where its tangential problem is unsolved).
template <class Sink>
void rcf_fields(Sink& k, const RcfOptions& o, double N, double a_el, double b_el, const TangentialResult& t,
                const PatchResult* patch = nullptr, const EllipseCells& cells = {}) {
  const double f = o.traction(N, t.Fx, t.Fy, t.solved);
  const RcfPoint p = rcf_point(f, o.k, N, a_el, b_el, o.nu);
  k.number("traction_coefficient", f);
  k.number("k_MPa", o.k / units::MPa);
  k.number("p0_el_over_k", p.p0_el_over_k);
  k.number("elastic_limit_p0_over_k", p.elastic_limit);
  k.number("shakedown_limit_p0_over_k", p.shakedown_limit);
  k.text("shakedown_regime", std::isfinite(p.p0_el_over_k) ? to_string(p.regime) : nullptr);
  k.number("FI_surf_el", p.fi_surf_el);
  if (o.subsurface) subsurface_fields(k, o, N, a_el, b_el, t, f, patch, cells);
}
// The worst contact's RCF indicators in cases.csv and the case record (docs/outputs.md "RCF
// columns"), after the band columns: the contact (ellipse or patch number, by the row's method)
// whose elastic Hertz p0_el/k is the largest, its regime, and the largest FI_surf_el of the case's
// contacts (with one f for every contact, FI_surf = f − k/p0_el: the same contact; with each
// contact's own traction, possibly another). One place for a run that mixes methods (auto),
// whose per-contact RCF columns are split between ellipses.csv and patches.csv.
template <class Sink>
void rcf_case_fields(Sink& k, const RcfOptions& o, const CaseResult& r, bool failed) {
  RcfPoint worst;
  double which = NAN, fi_max = NAN;
  auto consider = [&](int contact, double N, double a_el, double b_el, const TangentialResult& t) {
    const RcfPoint p = rcf_point(o.traction(N, t.Fx, t.Fy, t.solved), o.k, N, a_el, b_el, o.nu);
    if (std::isfinite(p.p0_el_over_k) && !(p.p0_el_over_k <= worst.p0_el_over_k)) worst = p, which = contact;
    if (std::isfinite(p.fi_surf_el) && !(p.fi_surf_el <= fi_max)) fi_max = p.fi_surf_el;
  };
  if (!failed) {
    for (const LoadedEllipse& L : r.loaded) consider(L.ellipse, L.s.N, L.s.a_el, L.s.b_el, L.t);
    for (const PatchResult& P : r.patches) consider(P.patch, P.N, P.a_el, P.b_el, P.t);
  }
  const bool any = std::isfinite(which);
  k.optional("rcf_worst_contact", which);
  k.optional("rcf_worst_p0_el_over_k", worst.p0_el_over_k);
  k.text("rcf_worst_shakedown_regime", any ? to_string(worst.regime) : nullptr);
  k.optional("rcf_worst_FI_surf_el", fi_max);
}
// The tangential columns of one contact (docs/tangential.md), appended last to ellipses.csv and
// patches.csv and to their JSON records when friction is given: the creepages, then the creep
// forces and the spin moment ON THE RAIL in the contact frame (x rolling, s towards the field
// side, the moment about n = x × s), the adhesion fraction and Tγ (empty where not solved).
template <class Sink>
void tangential_fields(Sink& k, const TangentialResult& t) {
  k.optional("xi", t.c.xi);
  k.optional("eta", t.c.eta);
  k.optional("phi_per_mm", t.c.phi * units::mm);
  const double nan = NAN;
  k.optional("Fx_kN", t.solved ? -t.Fx / units::kN : nan);
  k.optional("Fy_kN", t.solved ? -t.Fy / units::kN : nan);
  k.optional("Mz_Nm", t.solved ? -t.Mz : nan);
  k.optional("adhesion_fraction", t.solved ? t.adhesion_fraction : nan);
  k.optional("Tgamma_N", t.solved ? t.Tgamma : nan);
  k.optional("Tgamma_spin_N", t.solved ? t.Tgamma_spin : nan);
}
// Damage and wear of one contact (ContactDamage, computed once per case by damage_step,
// contact/rcf/contact_damage.hpp; docs/outputs.md "Damage and wear columns"), after the tangential
// columns: the actual traction coefficient |F|/N, the Burstow damage per axle passage, the USFD
// wear rate over the contact's area A as solved (area_mm2 of the row: the plastic patch's under a
// plastic law) and the mass worn per metre.
constexpr double kUgPerMMm2 = 1e-3;  // [kg/m³] in 1 µg/(m·mm²)
constexpr double kUgPerM = 1e-9;     // [kg/m] in 1 µg/m
template <class Sink>
void damage_fields(Sink& k, const ContactDamage& d) {
  k.optional("traction_actual", d.traction);
  k.optional("D_burstow_per_axle", d.damage);
  k.optional("wear_rate_ug_per_m_mm2", d.wear_rate / kUgPerMMm2);
  k.optional("wear_ug_per_m", d.wear_per_metre / kUgPerM);
}
// The per-case sums (cases.csv, the case record), after every other column.
template <class Sink>
void tangential_case_fields(Sink& k, const CaseResult& r, bool failed) {
  const TangentialSums& t = r.tangential;
  const bool ok = !failed && t.solved;
  const double nan = NAN;
  k.optional("Fx_kN", ok ? t.Fx / units::kN : nan);
  k.optional("Fy_creep_kN", ok ? t.Fy_creep / units::kN : nan);
  k.optional("Mz_Nm", ok ? t.Mz : nan);
  k.optional("F_over_muN", ok ? t.F_over_muN : nan);
  k.optional("Y_kN", ok ? (r.Fy + t.Fy_creep) / units::kN : nan);
  k.optional("Fz_creep_kN", ok ? t.Fz_creep / units::kN : nan);
  // Σ over the case's contacts (one wheel's passage): CaseResult::damage (damage_step).
  k.optional("D_burstow_per_axle", ok ? r.damage.damage : nan);
  k.optional("wear_ug_per_m", ok ? r.damage.wear_per_metre / kUgPerM : nan);
}


}  // namespace mh
