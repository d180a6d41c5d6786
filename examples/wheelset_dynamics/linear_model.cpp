#include "linear_model.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "contact/tangential/kalker.hpp"
#include "contact/tangential/tangential_solve.hpp"
#include "geometry/conicity.hpp"
#include "geometry/wheelset.hpp"

namespace wsdyn {

std::vector<double> LinearWheelset::matrix(double V) const {
  const double m = body.m, I = body.I_z;
  std::vector<double> A(16, 0.0);
  auto a = [&](int i, int j) -> double& { return A[static_cast<std::size_t>(4 * i + j)]; };
  a(0, 1) = 1;
  a(1, 0) = -(k_s + body.k_y) / m;
  a(1, 1) = -2 * f22 / (m * V);
  a(1, 2) = 2 * f22 / m;
  a(1, 3) = -2 * f23 / (m * V);
  a(2, 3) = 1;
  a(3, 0) = -2 * f11 * l0 * lambda / (r0 * I);
  a(3, 2) = -body.k_psi / I;
  a(3, 3) = -2 * f11 * l0 * l0 / (V * I);
  return A;
}

std::vector<std::complex<double>> LinearWheelset::eigenvalues(double V) const {
  const std::vector<double> A = matrix(V);
  Eigen::Matrix4d M;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) M(i, j) = A[static_cast<std::size_t>(4 * i + j)];
  Eigen::EigenSolver<Eigen::Matrix4d> es(M, false);
  std::vector<std::complex<double>> ev;
  for (int i = 0; i < 4; ++i) ev.push_back(es.eigenvalues()(i));
  return ev;
}

double LinearWheelset::max_real_part(double V) const {
  double mx = -INFINITY;
  for (const auto& e : eigenvalues(V)) mx = std::max(mx, e.real());
  return mx;
}

double LinearWheelset::critical_speed(double V_lo, double V_hi, int n, double tol) const {
  double prev = V_lo;
  if (max_real_part(prev) > 0) return V_lo;
  for (int i = 1; i <= n; ++i) {
    const double V = V_lo + (V_hi - V_lo) * i / n;
    if (max_real_part(V) > 0) {
      double lo = prev, hi = V;
      while (hi - lo > tol) {
        const double mid = 0.5 * (lo + hi);
        (max_real_part(mid) > 0 ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    }
    prev = V;
  }
  return NAN;
}

double LinearWheelset::wavelength(double V) const {
  double best = -INFINITY, w = NAN;
  for (const auto& e : eigenvalues(V))
    if (e.imag() > 0 && e.real() > best) {
      best = e.real();
      w = e.imag();
    }
  return 2 * M_PI * V / w;
}

struct GeometryReference::Impl {
  mh::Wheelset W;
  mh::EquivalentConicity C;
  Impl(mh::Wheelset w, mh::EquivalentConicity c) : W(std::move(w)), C(std::move(c)) {}
};

namespace {
mh::Wheelset make_wheelset(const WheelsetSetup& s) {
  mh::WheelsetPlacement P;
  P.gauge = s.track.gauge;
  P.gauge_height = s.track.gauge_height;
  P.flange_back_distance = s.track.flange_back_distance;
  P.flange_back_position = s.track.flange_back_position;
  P.nominal_radius_left = P.nominal_radius_right = s.track.nominal_radius;
  return mh::Wheelset(s.wheel, s.wheel, s.rail, s.rail, P);
}
mh::EquivalentConicity make_conicity(const mh::Wheelset& W) {
  std::vector<double> ys, dr;
  for (int i = -800; i <= 800; ++i) ys.push_back(i * 1e-5);
  for (const mh::WheelsetState& st : W.sweep(ys)) dr.push_back(st.delta_r());
  return mh::EquivalentConicity(ys, dr);
}
}  // namespace

GeometryReference::GeometryReference(const WheelsetSetup& s) {
  mh::Wheelset W = make_wheelset(s);
  mh::EquivalentConicity C = make_conicity(W);
  p_ = new Impl(std::move(W), std::move(C));
  const mh::WheelsetState c0 = p_->W.at(0);
  r0 = c0.right.r;
  l0 = p_->W.taping_line(+1) + c0.right.y_w;
}

GeometryReference::~GeometryReference() { delete p_; }

double GeometryReference::conicity(double A) const {
  const mh::ConicityResult cr = p_->C.at(A);
  if (cr.status != "ok") throw std::runtime_error("conicity at " + std::to_string(A * 1e3) + " mm: " + cr.status);
  return cr.tan_gamma_e;
}

void GeometryReference::describing_functions(double A, double* d_tan, double* d_sincos) const {
  const int n = 400;
  double sg = 0, ss = 0;
  for (int i = 0; i < n; ++i) {
    const double th = M_PI * (i + 0.5) / n;
    const mh::WheelsetState st = p_->W.at(A * std::sin(th));
    const double gR = st.right.gamma, gL = st.left.gamma;
    sg += st.delta_tan_gamma() * std::sin(th);
    ss += (std::sin(gR) * std::cos(gR) - std::sin(gL) * std::cos(gL)) * std::sin(th);
  }
  const double df = 2 / (M_PI * A) * M_PI / n;  // (2 / (π A)) dθ
  *d_tan = sg * df;
  *d_sincos = ss * df;
}

LinearInputs linear_inputs(ContactAdapter& contact, const GeometryReference& g, double A) {
  const WheelsetSetup& s = contact.setup();
  LinearInputs in;
  in.amplitude = A;
  // The Hertz ellipse of the centred wheelset at the nominal load: the contact solve.
  WheelsetMotion m;
  m.V = 1;
  m.Omega = 1 / s.track.nominal_radius;
  const WheelsetForces f = contact.evaluate(m);
  if (!f.right.ok) throw std::runtime_error("linear_inputs: no contact answer for the centred wheelset");
  in.n_contacts = f.right.n_contacts;
  in.a = f.right.a;
  in.b = f.right.b;
  mh::combined_elastic(s.material, in.G, in.nu);
  const mh::KalkerCoefficients C = mh::kalker_coefficients(in.a / in.b, in.nu);
  in.C11 = C.C11;
  in.C22 = C.C22;
  in.C23 = C.C23;
  in.r0 = g.r0;
  in.l0 = g.l0;
  in.lambda = g.conicity(A);
  double d_tan = 0, d_sincos = 0;
  g.describing_functions(A, &d_tan, &d_sincos);
  const double c = std::sqrt(in.a * in.b);
  const double f23 = in.G * c * c * c * in.C23;
  in.k_grav = s.Q * d_tan;
  in.k_spin = f23 / in.r0 * d_sincos;
  return in;
}

LinearWheelset linear_model(const LinearInputs& in, const WheelsetBody& body) {
  LinearWheelset L;
  L.body = body;
  const double c2 = in.a * in.b, c = std::sqrt(c2);
  L.f11 = in.G * c2 * in.C11;
  L.f22 = in.G * c2 * in.C22;
  L.f23 = in.G * c2 * c * in.C23;
  L.lambda = in.lambda;
  L.k_s = in.k_grav - in.k_spin;
  L.l0 = in.l0;
  L.r0 = in.r0;
  return L;
}

}  // namespace wsdyn
