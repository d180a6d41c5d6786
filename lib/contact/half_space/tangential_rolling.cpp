// Exact half-space steady-rolling tangential solver (sources, problem and algorithm in
// tangential_rolling.hpp).
#include "contact/half_space/tangential_rolling.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mh {

namespace {

/// One element's problem with the others fixed ([V]): s = r + D∘p (D diagonal: the in-row
/// coefficients Aₓᵧ(0,0) − Aₓᵧ(1,0) vanish, Aₓᵧ being odd in y), |p| ≤ g.
/// Adhesion when p = −r/D satisfies the bound (s = 0); else slip, p = −g s/|s|: with σ = |s|,
///     s_k = r_k σ/(σ + g D_k),   Σ_k (r_k/(σ + g D_k))² = 1,
/// whose left side decreases convexly in σ ≥ 0, so Newton from σ₀ = max(0, |r| − g max D) (where
/// the left side is ≥ 1) rises monotonically to the root. Returns true for adhesion.
bool local_problem(double rx, double ry, double Dx, double Dy, double g, double* px, double* py) {
  const double ax = -rx / Dx, ay = -ry / Dy;
  if (ax * ax + ay * ay <= g * g) {
    *px = ax;
    *py = ay;
    return true;
  }
  const double gx = g * Dx, gy = g * Dy;
  double sigma = std::max(0.0, std::sqrt(rx * rx + ry * ry) - std::max(gx, gy));
  for (int it = 0; it < 60; ++it) {
    const double qx = rx / (sigma + gx), qy = ry / (sigma + gy);
    const double f = qx * qx + qy * qy - 1;
    const double df = -2 * (qx * qx / (sigma + gx) + qy * qy / (sigma + gy));
    const double step = -f / df;
    sigma = std::max(0.0, sigma + step);
    if (!(std::fabs(step) > 1e-15 * (sigma + std::min(gx, gy)))) break;
  }
  double tx = -g * rx / (sigma + gx), ty = -g * ry / (sigma + gy);
  const double t = std::sqrt(tx * tx + ty * ty);  // tractions [Pa]: no overflow, sqrt is cheaper
  if (t > 0) {  // on the bound to rounding
    tx *= g / t;
    ty *= g / t;
  }
  *px = tx;
  *py = ty;
  return false;
}

}  // namespace

HalfSpaceTangentialSolver::HalfSpaceTangentialSolver(int nx, int ny, double dx, double dy, double G,
                                                     double nu)
    : K_{dx, dy, G, nu}, fft_((TangentialInfluence::check(nx, ny, dx, dy, G, nu), nx + 1)) {
  setup(nx, ny, dx, dy, G, nu);
}

void HalfSpaceTangentialSolver::reset(int nx, int ny, double dx, double dy, double G, double nu) {
  TangentialInfluence::check(nx, ny, dx, dy, G, nu);
  fft_.reset(nx + 1);
  setup(nx, ny, dx, dy, G, nu);
}

void HalfSpaceTangentialSolver::setup(int nx, int ny, double dx, double dy, double G, double nu) {
  K_ = TangentialKernel{dx, dy, G, nu};
  nx_ = nx + 1;
  ny_ = ny;
  out_nx_ = nx;
  dx_ = dx;
  dy_ = dy;
  H_ = fft_.half();
  // Internally one more column, ix = 0, before the grid's first (trailing) column: the traction
  // difference there (0 − p of the first column) belongs to the slip of the grid's elements.
  nx = nx_;
  const std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  const std::size_t snx = static_cast<std::size_t>(nx), sh = static_cast<std::size_t>(H_);
  const std::size_t n_out = static_cast<std::size_t>(out_nx_) * static_cast<std::size_t>(ny);
  for (auto* v : {&out_px_, &out_py_, &out_sx_, &out_sy_}) v->assign(n_out, 0.0);
  out_state_.assign(n_out, ElementState::Exterior);
  pn_.assign(n, 0.0);
  for (auto* v : {&px_, &py_, &qx_, &qy_, &sx_, &sy_}) v->assign(n, 0.0);
  for (auto* v : {&rx_, &ry_, &vrx_, &vry_, &cx_, &cy_, &dqx_, &dqy_}) v->assign(snx, 0.0);
  for (int k = 0; k < nx; ++k) {
    rx_[static_cast<std::size_t>(k)] = K_.xx(k, 0);
    ry_[static_cast<std::size_t>(k)] = K_.yy(k, 0);
  }
  // Spectra of the wrapped row kernels for the row offsets d = 0 … ny−1 (Aₓₓ, A_yy even in d,
  // Aₓᵧ odd: the negative offsets follow).
  const int m = fft_.m();
  std::vector<double>& ka = build_a_;
  std::vector<double>& kb = build_b_;
  ka.assign(static_cast<std::size_t>(m), 0.0);
  kb.assign(static_cast<std::size_t>(m), 0.0);
  build_zero_.assign(sh, {0.0, 0.0});
  for (auto* v : {&kxx_, &kyy_, &kxy_}) v->assign(sh * static_cast<std::size_t>(ny), {0.0, 0.0});
  // Per row offset the kernels at the x offsets 0 … nx−1 only: Aₓₓ, A_yy bitwise even and Aₓᵧ
  // bitwise odd in the x offset (TangentialKernel), so the negative ones follow (the same bits).
  std::vector<double>& axx = build_xx_;
  std::vector<double>& ayy = build_yy_;
  std::vector<double>& axy = build_xy_;
  axx.assign(snx, 0.0);
  ayy.assign(snx, 0.0);
  axy.assign(snx, 0.0);
  for (int d = 0; d < ny; ++d) {
    for (int k = 0; k < nx; ++k) {
      K_.xx_yy(k, d, &axx[static_cast<std::size_t>(k)], &ayy[static_cast<std::size_t>(k)]);
      axy[static_cast<std::size_t>(k)] = K_.xy(k, d);
    }
    for (int i = 0; i < m; ++i) {
      int di = 0;
      const bool used = fft_.offset(i, &di);
      const std::size_t a = static_cast<std::size_t>(std::abs(di));
      ka[static_cast<std::size_t>(i)] = used ? axx[a] : 0.0;
      kb[static_cast<std::size_t>(i)] = used ? ayy[a] : 0.0;
    }
    fft_.forward(ka.data(), kb.data(), m, &kxx_[sh * d], &kyy_[sh * d]);
    for (int i = 0; i < m; ++i) {
      int di = 0;
      const bool used = fft_.offset(i, &di);
      ka[static_cast<std::size_t>(i)] = !used ? 0.0 : di >= 0 ? axy[static_cast<std::size_t>(di)] : -axy[static_cast<std::size_t>(-di)];
      kb[static_cast<std::size_t>(i)] = 0.0;
    }
    fft_.forward(ka.data(), kb.data(), m, &kxy_[sh * d], build_zero_.data());
  }
  // Keep the real parts of the even kernels' spectra and the imaginary part of the odd one's (the
  // other parts are rounding: offsets −(n−1)…(n−1) wrap symmetrically, RowFft::offset).
  for (auto* v : {&kxx_r_, &kyy_r_, &kxy_i_}) v->resize(sh * static_cast<std::size_t>(ny));
  for (std::size_t k = 0; k < sh * static_cast<std::size_t>(ny); ++k) {
    kxx_r_[k] = kxx_[k].real();
    kyy_r_[k] = kyy_[k].real();
    kxy_i_[k] = kxy_[k].imag();
  }
  vx_hat_.assign(sh * static_cast<std::size_t>(ny), {0.0, 0.0});
  vy_hat_.assign(sh * static_cast<std::size_t>(ny), {0.0, 0.0});
  qx_hat_.assign(sh, {0.0, 0.0});
  qy_hat_.assign(sh, {0.0, 0.0});
  contact_rows_.clear();
  contact_rows_.reserve(static_cast<std::size_t>(ny));
  state_.assign(n, ElementState::Exterior);
}

void HalfSpaceTangentialSolver::add_row_change(int iy) {
  const std::size_t sh = static_cast<std::size_t>(H_);
  fft_.forward(dqx_.data(), dqy_.data(), nx_, qx_hat_.data(), qy_hat_.data());
  for (int jy : contact_rows_) {
    const int d = std::abs(jy - iy);
    const double sgn = jy >= iy ? 1.0 : -1.0;  // Aₓᵧ odd in the row offset
    // The wrapped kernels are even (Aₓₓ, A_yy) or odd (Aₓᵧ) in the x offset, so their spectra are
    // real and imaginary: two real products per complex one.
    const double* a = &kxx_r_[sh * d];
    const double* b = &kyy_r_[sh * d];
    const double* g = &kxy_i_[sh * d];
    const double* qx = reinterpret_cast<const double*>(qx_hat_.data());
    const double* qy = reinterpret_cast<const double*>(qy_hat_.data());
    double* ox = reinterpret_cast<double*>(&vx_hat_[sh * jy]);
    double* oy = reinterpret_cast<double*>(&vy_hat_[sh * jy]);
    for (std::size_t k = 0; k < sh; ++k) {
      const double ak = a[k], bk = b[k], gk = sgn * g[k];
      const double xr = qx[2 * k], xi = qx[2 * k + 1], yr = qy[2 * k], yi = qy[2 * k + 1];
      ox[2 * k] += ak * xr - gk * yi;
      ox[2 * k + 1] += ak * xi + gk * yr;
      oy[2 * k] += bk * yr - gk * xi;
      oy[2 * k + 1] += bk * yi + gk * xr;
    }
  }
}

HalfSpaceTangentialResult HalfSpaceTangentialSolver::solve(const double* pn_in, double x0, double y0,
                                                           const Creepages& c, double mu,
                                                           const HalfSpaceTangentialOptions& options,
                                                           bool warm_start) {
  HalfSpaceTangentialResult res;
  res.forces.c = c;
  res.forces.mu = mu;
  const std::size_t n = px_.size();
  const std::size_t snx = static_cast<std::size_t>(nx_);
  std::string why;
  if (!options.valid(&why)) {
    res.message = "options: " + why;
    return res;
  }
  if (!(mu > 0) || !std::isfinite(mu) || !std::isfinite(c.xi) || !std::isfinite(c.eta) ||
      !std::isfinite(c.phi) || !std::isfinite(x0) || !std::isfinite(y0)) {
    res.message = "mu, the creepages and the grid origin must be finite, mu > 0";
    return res;
  }
  double pn_max = 0;
  const std::size_t n_out = out_px_.size();
  for (std::size_t e = 0; e < n_out; ++e) {
    if (std::isinf(pn_in[e])) {
      res.message = "pressure not finite at element " + std::to_string(e);
      return res;
    }
    if (pn_in[e] > 0) {
      pn_max = std::max(pn_max, pn_in[e]);
      ++res.n_contact;
    }
  }
  for (int iy = 0; iy < ny_; ++iy)
    for (int ix = 0; ix < nx_; ++ix) {
      const double v = ix == 0 ? 0.0 : pn_in[static_cast<std::size_t>(ix - 1) + static_cast<std::size_t>(out_nx_) * iy];
      pn_[static_cast<std::size_t>(ix) + snx * iy] = v > 0 ? v : 0.0;  // NaN: exterior
    }
  const double* pn = pn_.data();
  x0 -= dx_;  // the centre of the internal column 0
  const double xs = kSpinSlipOffset * dx_;  // where the spin's lateral rigid slip is taken (header)
  auto contact = [&](std::size_t e) { return pn[e] > 0; };
  contact_rows_.clear();
  for (int iy = 0; iy < ny_; ++iy)
    for (int ix = 0; ix < nx_; ++ix)
      if (contact(static_cast<std::size_t>(ix) + snx * iy)) {
        contact_rows_.push_back(iy);
        break;
      }
  // Start: zero tractions, or the last solve's where there is still contact; q from p; every
  // contact element in adhesion; the row spectra of v = A q.
  for (std::size_t e = 0; e < n; ++e) {
    if (!warm_start || !contact(e)) px_[e] = py_[e] = 0;
    sx_[e] = sy_[e] = 0;
    state_[e] = contact(e) ? ElementState::Adhesion : ElementState::Exterior;
  }
  std::fill(vx_hat_.begin(), vx_hat_.end(), std::complex<double>(0.0, 0.0));
  std::fill(vy_hat_.begin(), vy_hat_.end(), std::complex<double>(0.0, 0.0));
  for (int iy = 0; iy < ny_; ++iy) {
    bool any = false;
    for (int ix = 0; ix < nx_; ++ix) {
      const std::size_t e = static_cast<std::size_t>(ix) + snx * iy;
      const bool last = ix + 1 == nx_;
      qx_[e] = px_[e] - (last ? 0.0 : px_[e + 1]);
      qy_[e] = py_[e] - (last ? 0.0 : py_[e + 1]);
      dqx_[static_cast<std::size_t>(ix)] = qx_[e];
      dqy_[static_cast<std::size_t>(ix)] = qy_[e];
      any = any || qx_[e] != 0 || qy_[e] != 0;
    }
    if (any) add_row_change(iy);
  }
  if (res.n_contact == 0) {
    std::fill(out_px_.begin(), out_px_.end(), 0.0);
    std::fill(out_py_.begin(), out_py_.end(), 0.0);
    std::fill(out_sx_.begin(), out_sx_.end(), 0.0);
    std::fill(out_sy_.begin(), out_sy_.end(), 0.0);
    std::fill(out_state_.begin(), out_state_.end(), ElementState::Exterior);
    res.status = TangentialStatus::NoContact;
    res.forces.adhesion_fraction = NAN;
    return res;
  }

  const double Dx = rx_[0] / dx_, Dy = ry_[0] / dx_;  // [1/Pa] own coefficient of the slip in q
  const double scale = mu * pn_max;                   // [Pa] largest traction bound
  bool converged = false;
  for (int sweep = 1; sweep <= options.max_sweeps && !converged; ++sweep) {
    res.sweeps = sweep;
    double change = 0;
    for (int iy : contact_rows_) {
      const std::size_t r = snx * static_cast<std::size_t>(iy);
      fft_.backward(&vx_hat_[static_cast<std::size_t>(H_) * iy], &vy_hat_[static_cast<std::size_t>(H_) * iy],
                    vrx_.data(), vry_.data());
      std::fill(cx_.begin(), cx_.end(), 0.0);
      std::fill(cy_.begin(), cy_.end(), 0.0);
      std::fill(dqx_.begin(), dqx_.end(), 0.0);
      std::fill(dqy_.begin(), dqy_.end(), 0.0);
      bool row_changed = false;
      // q changes at element j of this row by (ax, ay): record it, correct v of the elements
      // still to be processed (k > i) exactly.
      auto change_q = [&](int j, int i, double ax, double ay) {
        const std::size_t e = r + static_cast<std::size_t>(j);
        qx_[e] += ax;
        qy_[e] += ay;
        dqx_[static_cast<std::size_t>(j)] += ax;
        dqy_[static_cast<std::size_t>(j)] += ay;
        for (int k = i + 1; k < nx_; ++k) {
          cx_[static_cast<std::size_t>(k)] += rx_[static_cast<std::size_t>(k - j)] * ax;
          cy_[static_cast<std::size_t>(k)] += ry_[static_cast<std::size_t>(k - j)] * ay;
        }
        row_changed = true;
      };
      const double y = y0 + iy * dy_;
      for (int ix = 0; ix < nx_; ++ix) {  // trailing → leading edge
        const std::size_t e = r + static_cast<std::size_t>(ix);
        if (!contact(e)) continue;
        const double x = x0 + ix * dx_;
        const double wx = c.xi - c.phi * y, wy = c.eta + c.phi * (x + xs);  // rigid slip (header)
        const double sx = wx + (vrx_[static_cast<std::size_t>(ix)] + cx_[static_cast<std::size_t>(ix)]) / dx_;
        const double sy = wy + (vry_[static_cast<std::size_t>(ix)] + cy_[static_cast<std::size_t>(ix)]) / dx_;
        double tx = 0, ty = 0;
        const bool adh = local_problem(sx - Dx * px_[e], sy - Dy * py_[e], Dx, Dy, mu * pn[e], &tx, &ty);
        state_[e] = adh ? ElementState::Adhesion : ElementState::Slip;
        double ax = tx - px_[e], ay = ty - py_[e];
        change = std::max(change, std::max(std::fabs(ax), std::fabs(ay)));
        if (ax == 0 && ay == 0) continue;
        px_[e] = tx;
        py_[e] = ty;
        change_q(ix, ix, ax, ay);
        // Downstream: adhesion elements keep their q (p moves with the change), the first slip or
        // exterior element keeps its p (its q takes the change); a moved p over its bound is put
        // back on the bound and the rest of the change goes on from there.
        for (int j = ix - 1; j >= 0 && (ax != 0 || ay != 0); --j) {
          const std::size_t f = r + static_cast<std::size_t>(j);
          if (state_[f] != ElementState::Adhesion) {
            change_q(j, ix, -ax, -ay);
            break;
          }
          double nxv = px_[f] + ax, nyv = py_[f] + ay;
          const double g = mu * pn[f], t = std::sqrt(nxv * nxv + nyv * nyv);
          if (t > g) {
            nxv *= g / t;
            nyv *= g / t;
            change_q(j, ix, nxv - (px_[f] + ax), nyv - (py_[f] + ay));
          }
          ax = nxv - px_[f];
          ay = nyv - py_[f];
          px_[f] = nxv;
          py_[f] = nyv;
        }
      }
      if (row_changed) add_row_change(iy);
    }
    // Relative to the largest traction magnitude (μ max p_n when that is larger: a saturated
    // solution's scale), so that a huge μ (no slip) does not stop the iteration early.
    double pt_max = 0;
    for (int iy : contact_rows_)
      for (int ix = 0; ix < nx_; ++ix) {
        const std::size_t e = static_cast<std::size_t>(ix) + snx * iy;
        pt_max = std::max(pt_max, px_[e] * px_[e] + py_[e] * py_[e]);
      }
    res.change = change == 0 ? 0.0 : change / std::min(scale, std::max(std::sqrt(pt_max), 1e-300));
    if (!std::isfinite(res.change)) {
      res.message = "non-finite traction in sweep " + std::to_string(sweep);
      break;
    }
    converged = res.change <= options.tol;
  }

  // Slip from the final tractions, forces and moment about the reference point.
  const double dA = dx_ * dy_;
  double Fx = 0, Fy = 0, Mz = 0;
  for (int iy : contact_rows_) {
    fft_.backward(&vx_hat_[static_cast<std::size_t>(H_) * iy], &vy_hat_[static_cast<std::size_t>(H_) * iy],
                  vrx_.data(), vry_.data());
    const double y = y0 + iy * dy_;
    for (int ix = 0; ix < nx_; ++ix) {
      const std::size_t e = static_cast<std::size_t>(ix) + snx * iy;
      if (!contact(e)) continue;
      const double x = x0 + ix * dx_;
      if (state_[e] == ElementState::Slip) {
        sx_[e] = c.xi - c.phi * y + vrx_[static_cast<std::size_t>(ix)] / dx_;
        sy_[e] = c.eta + c.phi * (x + xs) + vry_[static_cast<std::size_t>(ix)] / dx_;
      } else {
        ++res.n_adhesion;
      }
      Fx += px_[e] * dA;
      Fy += py_[e] * dA;
      Mz += (x * py_[e] - y * px_[e]) * dA;
    }
  }
  for (int iy = 0; iy < ny_; ++iy)
    for (int ix = 1; ix < nx_; ++ix) {
      const std::size_t e = static_cast<std::size_t>(ix) + snx * iy;
      const std::size_t o = static_cast<std::size_t>(ix - 1) + static_cast<std::size_t>(out_nx_) * iy;
      out_px_[o] = px_[e];
      out_py_[o] = py_[e];
      out_sx_[o] = sx_[e];
      out_sy_[o] = sy_[e];
      out_state_[o] = state_[e];
    }
  res.forces.Fx = Fx;
  res.forces.Fy = Fy;
  res.forces.Mz = Mz;
  res.forces.adhesion_fraction = static_cast<double>(res.n_adhesion) / res.n_contact;
  res.forces.Tgamma = -(Fx * c.xi + Fy * c.eta);  // forces on the rail (tangential_types.hpp)
  res.forces.Tgamma_spin = -Mz * c.phi;
  res.forces.iterations = res.sweeps;
  if (converged) {
    res.status = TangentialStatus::Ok;
    res.forces.solved = true;
  } else if (res.message.empty()) {
    res.message = "not converged after " + std::to_string(res.sweeps) + " sweeps: change " +
                  std::to_string(res.change) + " > tol " + std::to_string(options.tol);
  }
  return res;
}

}  // namespace mh
