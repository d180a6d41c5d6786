// Constrained conjugate-gradient normal contact solver (sources and problem in normal_cg.hpp).
#include "contact/half_space/normal_cg.hpp"

#include "core/roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <vector>

namespace mh {


namespace {

enum class Control { Approach, Load };

constexpr int kMaxLoadSteps = 60;  // capped load control: approach solves on δ (usually 4–8)
constexpr int kPolishSteps = 50;   // capped load control: final [PK] load-control steps (usually 0–2)

/// The least-squares scale α minimising Σ_S (α u_e − target_e)² over S = {e : shape_e > 0}, u = C
/// shape (the cold starts' fit of a shape to the grid's compliance); NaN where u vanishes on S.
template <class Target>
double fitted_scale(const double* shape, const double* u, std::size_t n, Target target) {
  double num = 0, den = 0;
  for (std::size_t e = 0; e < n; ++e)
    if (shape[e] > 0) {
      num += target(e) * u[e];
      den += u[e] * u[e];
    }
  return den > 0 ? num / den : std::numeric_limits<double>::quiet_NaN();
}

/// The Hertzian shape p = √(max(δ/2 − (g̃ − g_min), 0)) on the grid (δ/2 = half_delta [m]), g̃ the
/// gap with its level sets stretched to Hertz's aspect about the centroid of `support` (the
/// elements where support > 0, a level set of g): for a gap A x² + B y² the level sets have the
/// semi-axis ratio (B/A)^(1/2) and Hertz's ellipse about (B/A)^(2/3) (Johnson §4.2, the
/// approximation for moderately elliptical contacts), so g̃(x, y) = g(x_c + (x − x_c)/r,
/// y_c + (y − y_c) r), r = (B/A)^(1/12) (the area kept), bilinear between the elements, +∞ off
/// the grid; B/A = Mxx/Myy, the support's second moments about its centroid (those of an
/// elliptic level set). Returns Σ p.
double hertz_shape(const InfluenceGrid& C, const double* g, double g_min, double half_delta, const double* support,
                   double* p) {
  const int nx = C.nx(), ny = C.ny();
  double sw = 0, sx = 0, sy = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (support[static_cast<std::size_t>(i + nx * j)] > 0) sw += 1, sx += i, sy += j;
  const double xc = sx / sw, yc = sy / sw;
  double mxx = 0, myy = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (support[static_cast<std::size_t>(i + nx * j)] > 0) {
        mxx += (i - xc) * (i - xc) * C.dx() * C.dx();
        myy += (j - yc) * (j - yc) * C.dy() * C.dy();
      }
  const double r = mxx > 0 && myy > 0 ? std::pow(mxx / myy, 1.0 / 12.0) : 1.0;
  const int im = std::max(nx - 2, 0), jm = std::max(ny - 2, 0);
  auto G = [&](int i, int j) { return g[static_cast<std::size_t>(i + nx * j)]; };
  double sum_p = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double xs = xc + (i - xc) / r, ys = yc + (j - yc) * r;  // in element indices
      double gt = INFINITY;
      if (xs >= 0 && ys >= 0 && xs <= nx - 1 && ys <= ny - 1) {
        const int i0 = std::min(static_cast<int>(xs), im), j0 = std::min(static_cast<int>(ys), jm);
        const int i1 = std::min(i0 + 1, nx - 1), j1 = std::min(j0 + 1, ny - 1);
        const double fx = xs - i0, fy = ys - j0;
        gt = (1 - fy) * ((1 - fx) * G(i0, j0) + fx * G(i1, j0)) + fy * ((1 - fx) * G(i0, j1) + fx * G(i1, j1));
      }
      const std::size_t e = static_cast<std::size_t>(i + nx * j);
      p[e] = std::sqrt(std::max(half_delta - (gt - g_min), 0.0));
      sum_p += p[e];
    }
  return sum_p;
}

/// The cold start of load control: the pressure of a Hertzian contact of the load N on this gap.
/// For a round quadratic gap, p ∝ √(δ/2 − (g − g_min)) (the contact edge is where the gap equals
/// half the approach: a² = R δ against the interference's 2 R δ; Johnson, Contact Mechanics, §4.2;
/// for an elliptic one on the gap stretched to Hertz's aspect, hertz_shape) and N ∝ δ^(3/2)
/// (eq. 4.23). The scale of N(δ) comes from one probe: the rigid interference
/// q = max(δ₀ − g, 0) at δ₀ the median gap, fitted as in the approach control's cold start
/// (α minimising Σ_S (α (C q)_e − q_e)² over its support S), carries N₀ = α dx dy Σ q; then
/// δ = (δ₀ − g_min)(N/N₀)^(2/3). The caller restores the load exactly. Against [PK]'s uniform
/// start (every element loaded, so every element outside the contact must leave it): a third
/// fewer CG steps on round contacts, 15 % fewer at A/B = 2, as many at 10; 5 % fewer instructions
/// on the Manchester sweep (docs/performance.md). Falls back to the uniform start where the probe
/// carries nothing.
void hertz_shaped_guess(const InfluenceGrid& C, const double* g, double g_min, double N, double* p,
                        NormalCGWorkspace& ws, NormalCGResult& result) {
  const std::size_t n = static_cast<std::size_t>(C.nx()) * static_cast<std::size_t>(C.ny());
  const double area = C.dx() * C.dy();
  std::vector<double>& q = ws.h;
  std::vector<double>& u = ws.u;
  ws.sorted.assign(g, g + n);
  const auto mid = ws.sorted.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(ws.sorted.begin(), mid, ws.sorted.end());
  const double delta0 = *mid;
  double sum_q = 0;
  for (std::size_t e = 0; e < n; ++e) {
    q[e] = std::max(delta0 - g[e], 0.0);
    sum_q += q[e];
  }
  double N0 = 0;
  if (sum_q > 0) {
    C.apply(q.data(), u.data());
    ++result.convolutions;
    const double alpha = fitted_scale(q.data(), u.data(), n, [&](std::size_t e) { return q[e]; });
    if (std::isfinite(alpha)) N0 = alpha * area * sum_q;
  }
  if (!(N0 > 0) || !std::isfinite(N0)) {
    std::fill(p, p + n, N / (area * static_cast<double>(n)));  // [PK] §3
    return;
  }
  const double half_delta = 0.5 * (delta0 - g_min) * std::pow(N / N0, 2.0 / 3.0);
  const double sum_p = hertz_shape(C, g, g_min, half_delta, q.data(), p);
  if (!(sum_p > 0)) std::fill(p, p + n, N / (area * static_cast<double>(n)));
}

/// The shared CG loop ([PK]). target is δ [m] (Approach) or N [N] (Load); at most max_iterations
/// CG steps (0: only the initial guess is prepared and measured).
NormalCGResult solve(const InfluenceGrid& C, const double* g, double target, Control control,
                     double p_lim, double* p, const NormalCGOptions& options, int max_iterations,
                     NormalCGWorkspace& ws) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  NormalCGResult result;
  result.status = GridStatus::NotConverged;
  result.error = nan;
  const std::size_t n = static_cast<std::size_t>(C.nx()) * static_cast<std::size_t>(C.ny());
  const double area = C.dx() * C.dy();  // [m²] element area
  const bool load = control == Control::Load;

  // Invalid input: NotConverged, p untouched.
  if (!options.valid(nullptr) || !(p_lim > 0) || !std::isfinite(target)) return result;
  double g_min = inf;
  for (std::size_t e = 0; e < n; ++e) {
    if (!std::isfinite(g[e])) return result;
    g_min = std::min(g_min, g[e]);
  }

  auto finish = [&](GridStatus status) {
    double sum = 0;
    int n_contact = 0, n_plastic = 0;
    for (std::size_t e = 0; e < n; ++e) {
      sum += p[e];
      if (p[e] > 0) ++n_contact;
      if (p[e] == p_lim) ++n_plastic;
    }
    result.status = status;
    result.N = area * sum;
    result.n_contact = n_contact;
    result.n_plastic = n_plastic;
    return result;
  };

  // No contact.
  if ((!load && target <= g_min) || (load && target <= 0)) {
    std::fill(p, p + n, 0.0);
    result.delta = load ? g_min : target;
    result.error = 0;
    return finish(GridStatus::NoContact);
  }
  // Infeasible load: more than every element at the cap can carry.
  if (load && std::isfinite(p_lim) && target > p_lim * area * static_cast<double>(n)) {
    result.delta = nan;
    return finish(GridStatus::NotConverged);
  }

  // Work vectors, zeroed (as fresh vectors would be), in the caller's workspace.
  for (auto* v : {&ws.u, &ws.h, &ws.t, &ws.Ct}) v->assign(n, 0.0);
  ws.in_free.assign(n, 0);
  std::vector<double> &u = ws.u, &h = ws.h, &t = ws.t, &Ct = ws.Ct;
  std::vector<unsigned char>& in_free = ws.in_free;

  // Initial guess: clip to [0, p_lim] (non-finite entries → 0).
  double sum_p = 0;
  for (std::size_t e = 0; e < n; ++e) {
    const double pe = std::isfinite(p[e]) ? p[e] : (p[e] == inf ? p_lim : 0.0);
    p[e] = std::min(std::max(pe, 0.0), p_lim);
    sum_p += p[e];
  }

  // [PK] load restoration: scale the free pressures so that dx·dy·Σp = N; with a cap, elements
  // pushed to p_lim are fixed there and the scaling repeated (each pass caps ≥ 1 more element).
  // With no element at the cap this is exactly p *= N/P, the elastic path. Returns that factor
  // when every element was scaled by it (then C p scales by it too), else NaN.
  auto restore_load = [&]() -> double {
    constexpr double not_uniform = std::numeric_limits<double>::quiet_NaN();
    const double N = target;
    for (std::size_t pass = 0; pass <= n; ++pass) {
      double sum_free = 0;
      std::size_t n_cap = 0, n_zero = 0;
      for (std::size_t e = 0; e < n; ++e) {
        if (p[e] == p_lim)
          ++n_cap;
        else
          sum_free += p[e];
        if (p[e] == 0) ++n_zero;
      }
      const double P_cap = n_cap ? area * p_lim * static_cast<double>(n_cap) : 0.0;
      const double P_free = area * sum_free;
      if (N <= P_cap) {  // the capped elements alone carry N: scale everything down
        const double s = N / (P_cap + P_free);
        for (std::size_t e = 0; e < n; ++e) p[e] *= s;
        return pass == 0 ? s : not_uniform;
      }
      if (!(P_free > 0)) {  // nothing free to scale: spread the deficit over unloaded elements
        if (n_zero == 0) return not_uniform;
        const double q = std::min(p_lim, (N - P_cap) / (area * static_cast<double>(n_zero)));
        for (std::size_t e = 0; e < n; ++e)
          if (p[e] == 0) p[e] = q;
        continue;
      }
      const double s = (N - P_cap) / P_free;
      bool capped = false;
      for (std::size_t e = 0; e < n; ++e) {
        if (p[e] == p_lim) continue;
        p[e] *= s;
        if (p[e] >= p_lim) {
          p[e] = p_lim;
          capped = true;
        }
      }
      if (!capped) return pass == 0 && n_cap == 0 ? s : not_uniform;
    }
    return not_uniform;
  };

  if (load) {
    if (!(sum_p > 0)) hertz_shaped_guess(C, g, g_min, target, p, ws, result);
    restore_load();
  } else if (!(sum_p > 0)) {
    // Cold start in approach control: the Hertzian shape of this approach (hertz_shape, on the
    // rigid interference max(δ − g, 0) as its support), scaled by the least-squares α minimising
    // Σ_S (α (C q)_e − (δ − g_e))² over the shape's support S.
    for (std::size_t e = 0; e < n; ++e) h[e] = std::max(target - g[e], 0.0);
    hertz_shape(C, g, g_min, 0.5 * (target - g_min), h.data(), p);
    C.apply(p, u.data());
    ++result.convolutions;
    double alpha = fitted_scale(p, u.data(), n, [&](std::size_t e) { return target - g[e]; });
    if (!std::isfinite(alpha)) alpha = 1.0 / C.self_coefficient();
    for (std::size_t e = 0; e < n; ++e) p[e] = std::min(alpha * p[e], p_lim);
  }

  double delta = target;  // load control: re-estimated every iteration
  double G_old = 0;       // Σ_F h² of the previous step
  bool reset = true;      // conjugacy reset ([PK]: after the contact set gained elements)
  // u = C p is carried from step to step: a step that moved every free pressure by −τ t changes u
  // by −τ C t, already computed for τ, and the elastic load restoration scales p and u alike. The
  // elements the step moved otherwise (projected onto a bound, re-entering: d = their change
  // beyond −τ t) add C d, by direct sums while they are few (at most kSparse: cheaper than a
  // convolution, InfluenceGrid::add_sparse). So a step costs one convolution instead of two.
  // After a step that moved more, and before convergence is accepted (so that ε is always
  // measured on the exact u), u is convolved afresh.
  bool u_valid = false;   // u holds C p (convolved or carried)
  bool u_exact = false;   // ... convolved from this p
  // A third of the break-even count: m direct sums cost m·n against about 4 n log2(4n) · 6
  // instructions a convolution (measured: 0.58 M at 44 × 44 on a 90 × 90 padding).
  const std::size_t kSparse = static_cast<std::size_t>(
      8 * std::log2(static_cast<double>(C.padded_nx()) * static_cast<double>(C.padded_ny())));
  ws.moved.reserve(kSparse + 1);
  ws.moved_dp.reserve(kSparse + 1);
  for (int it = 0;;) {
    if (!u_valid) {
      C.apply(p, u.data());
      ++result.convolutions;
      u_valid = u_exact = true;
    }

    // Free set and, in load control, δ = mean of g + u over it ([PK]).
    std::size_t n_free = 0;
    double sum_gu = 0;
    for (std::size_t e = 0; e < n; ++e) {
      in_free[e] = p[e] > 0 && p[e] < p_lim;
      if (in_free[e]) {
        ++n_free;
        sum_gu += g[e] + u[e];
      }
    }
    if (load) {
      if (n_free > 0) {
        delta = sum_gu / static_cast<double>(n_free);
      } else {  // all loaded elements capped: δ where every element touches
        delta = -inf;
        for (std::size_t e = 0; e < n; ++e) delta = std::max(delta, g[e] + u[e]);
      }
    }

    // Gap, convergence measure ε (NormalCGOptions::tol).
    double G = 0, violation = 0;
    for (std::size_t e = 0; e < n; ++e) {
      h[e] = g[e] + u[e] - delta;
      if (in_free[e])
        G += h[e] * h[e];
      else if (p[e] == 0)
        violation = std::max(violation, -h[e]);
      else
        violation = std::max(violation, h[e]);
    }
    const double h_ref = delta - g_min;
    const double rms = n_free ? std::sqrt(G / static_cast<double>(n_free)) : 0.0;
    const double error = h_ref > 0 ? std::max(rms, violation) / h_ref : inf;
    result.error = error;
    result.iterations = it;
    result.delta = delta;
    if (!std::isfinite(G) || !std::isfinite(violation) || std::isnan(error))
      return finish(GridStatus::NotConverged);  // numerical trouble
    if (error <= options.tol) {
      if (u_exact) return finish(GridStatus::Ok);
      u_valid = false;  // measure ε again on u convolved from p
      continue;
    }
    if (it >= max_iterations) return finish(GridStatus::NotConverged);

    // Conjugate direction on F ([PK]): t = h + β t_old, β = G/G_old unless reset.
    const double beta = (reset || !(G_old > 0)) ? 0.0 : G / G_old;
    for (std::size_t e = 0; e < n; ++e) t[e] = in_free[e] ? h[e] + beta * t[e] : 0.0;
    G_old = G;

    // Step length τ = Σ_F h t / Σ_F (C t − mean_F C t) t ([PK]; no centring in approach control).
    double tau = 1.0 / C.self_coefficient();  // fallback with F empty: local (Jacobi) scale
    if (n_free > 0) {
      C.apply(t.data(), Ct.data());
      ++result.convolutions;
      double mean_Ct = 0;
      if (load) {
        for (std::size_t e = 0; e < n; ++e)
          if (in_free[e]) mean_Ct += Ct[e];
        mean_Ct /= static_cast<double>(n_free);
      }
      double num = 0, den = 0;
      for (std::size_t e = 0; e < n; ++e)
        if (in_free[e]) {
          num += h[e] * t[e];
          den += (Ct[e] - mean_Ct) * t[e];
        }
      if (num == 0 && den == 0) {
        // t = 0 on F: the free gaps are level (two free elements of equal gap, centred in load
        // control) while bound elements still violate; the Jacobi scale lets those re-enter.
      } else if (!(den > 0) || !std::isfinite(num) || !std::isfinite(den)) {
        return finish(GridStatus::NotConverged);  // C restricted to F must be positive definite
      } else {
        tau = num / den;
      }
    }

    // Step on F, projection onto [0, p_lim]; violators of a bound re-enter F ([PK], mirrored for
    // the cap), which resets the conjugacy.
    reset = false;
    ws.moved.clear();
    ws.moved_dp.clear();
    bool carry = true;  // u can be carried: the elements moved off −τ t are at most kSparse
    auto moved = [&](std::size_t e, double dp) {
      if (!carry) return;
      if (ws.moved.size() == kSparse) {
        carry = false;
        return;
      }
      ws.moved.push_back(static_cast<int>(e));
      ws.moved_dp.push_back(dp);
    };
    for (std::size_t e = 0; e < n; ++e) {
      if (in_free[e]) {
        const double q = p[e] - tau * t[e];
        p[e] = std::min(std::max(q, 0.0), p_lim);
        if (p[e] != q) moved(e, p[e] - q);
      } else if (p[e] == 0) {
        if (h[e] < 0) {
          p[e] = std::min(-tau * h[e], p_lim);
          moved(e, p[e]);
          reset = true;
        }
      } else if (h[e] > 0) {  // p[e] == p_lim
        p[e] = std::max(p_lim - tau * h[e], 0.0);
        moved(e, p[e] - p_lim);
        reset = true;
      }
    }
    if (carry) {
      if (n_free > 0)  // else t = 0: no step but the moved elements
        for (std::size_t e = 0; e < n; ++e) u[e] -= tau * Ct[e];
      C.add_sparse(ws.moved.data(), ws.moved_dp.data(), static_cast<int>(ws.moved.size()), u.data());
      u_exact = false;
    } else {
      u_valid = false;
    }
    if (load) {
      const double s = restore_load();
      if (!std::isfinite(s)) {
        u_valid = false;
      } else if (u_valid) {
        for (std::size_t e = 0; e < n; ++e) u[e] *= s;
      }
    }
    ++it;
  }
}

/// Load control with a finite cap (normal_cg.hpp, "Load control with a cap"): the elastic solution
/// when it stays below p_lim, else a root in δ of N(δ) = N over capped approach-control solves.
NormalCGResult solve_capped_load(const InfluenceGrid& C, const double* g, double N, double p_lim,
                                 double* p, const NormalCGOptions& options, NormalCGWorkspace& ws) {
  const std::size_t n = static_cast<std::size_t>(C.nx()) * static_cast<std::size_t>(C.ny());
  const double area = C.dx() * C.dy();
  // Invalid input, no load and an infeasible load are answered by the shared loop, untouched.
  if (!options.valid(nullptr) || !(p_lim > 0) || !std::isfinite(N) || !(N > 0) ||
      N > p_lim * area * static_cast<double>(n))
    return solve(C, g, N, Control::Load, p_lim, p, options, options.max_iterations, ws);
  for (std::size_t e = 0; e < n; ++e)
    if (!std::isfinite(g[e])) return solve(C, g, N, Control::Load, p_lim, p, options, options.max_iterations, ws);

  // 1. The elastic solution ([PK] load control, p_lim = ∞). If it stays below the cap it is the
  //    solution of the capped problem too (it satisfies every condition; the solution is unique).
  //    Skipped when the guess already holds capped elements (a previous capped solution): then δ
  //    starts from the guess's own approach, the mean of g + C p over its free elements.
  std::vector<double>& guess = ws.guess;
  guess.assign(p, p + n);
  bool capped_guess = false;
  for (std::size_t e = 0; e < n; ++e) capped_guess = capped_guess || p[e] >= p_lim;
  NormalCGResult el;
  el.status = GridStatus::NotConverged;
  double delta_guess = -INFINITY;
  int used = 0, conv = 0;  // CG steps and convolutions of the solves so far
  if (capped_guess) {
    for (std::size_t e = 0; e < n; ++e) p[e] = std::isfinite(p[e]) ? std::min(std::max(p[e], 0.0), p_lim) : 0.0;
    std::vector<double>& u = ws.u0;
    u.assign(n, 0.0);
    C.apply(p, u.data());
    ++conv;
    double sum = 0, top = -INFINITY;
    std::size_t n_free = 0;
    for (std::size_t e = 0; e < n; ++e) {
      if (p[e] > 0 && p[e] < p_lim) { sum += g[e] + u[e]; ++n_free; }
      if (p[e] > 0) top = std::max(top, g[e] + u[e]);
    }
    delta_guess = n_free ? sum / static_cast<double>(n_free) : top;
  } else {
    el = solve(C, g, N, Control::Load, INFINITY, p, options, options.max_iterations, ws);
    used = el.iterations;
    conv = el.convolutions;
    if (el.status != GridStatus::Ok) {
      std::copy(guess.begin(), guess.end(), p);  // the caller's guess, for the δ-loop below
    } else if (*std::max_element(p, p + n) <= p_lim) {
      el.n_plastic = 0;
      return el;
    }
  }

  // 2. δ ↦ N(δ) = dx·dy·Σp of the capped approach-control solution is continuous and
  //    non-decreasing; the capped δ* is at least
  //      δ_el (the elastic approach: capping only softens, N_cap(δ) ≤ N_el(δ)), and
  //      δ_rp (rigid–perfectly-plastic bound: contact needs g + u ≤ δ with u ≥ 0, so g < δ, and
  //            N(δ) ≤ p_lim·dx·dy·#{g < δ}; δ_rp is the k-th smallest g, k = ⌈N/(p_lim dx dy)⌉).
  std::vector<double>& sorted = ws.sorted;
  sorted.assign(g, g + n);
  const std::size_t k = std::min(n - 1, static_cast<std::size_t>(std::ceil(N / (p_lim * area))));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
  const double delta_rp = sorted[k];
  const double g_min = *std::min_element(g, g + n);
  double delta = delta_rp;
  if (el.status == GridStatus::Ok) delta = std::max(delta, el.delta);
  if (std::isfinite(delta_guess)) delta = std::max(delta, delta_guess);
  for (std::size_t e = 0; e < n; ++e) p[e] = std::min(std::max(p[e], 0.0), p_lim);  // warm start

  // F(δ) = N(δ) − N by capped approach-control solves, warm-started from the last; stop when
  // |F| ≤ tol·N (the force to the accuracy the gap has: ε ≤ tol of the interference), when a
  // solve fails or when the iteration budget is spent (`stop`: F is then reported as 0 so that
  // the root finder ends there). Bracket first, then TOMS 748 (core/roots.hpp).
  NormalCGOptions inner = options;
  NormalCGResult r;
  int evals = 0;
  bool stop = false;
  auto F = [&](double d) {
    if (stop) return 0.0;
    inner.max_iterations = std::max(1, options.max_iterations - used);
    r = solve(C, g, d, Control::Approach, p_lim, p, inner, inner.max_iterations, ws);
    used += r.iterations;
    conv += r.convolutions;
    ++evals;
    const double f = r.N - N;
    stop = (r.status != GridStatus::Ok && r.status != GridStatus::NoContact) || std::fabs(f) <= options.tol * N ||
           used >= options.max_iterations || evals >= kMaxLoadSteps;
    return stop ? 0.0 : f;
  };
  double lo = g_min, F_lo = -N, F_d = F(delta);
  while (!stop && F_d < 0) {
    // Not bracketed yet: the interference grown by N/N(δ) (exact for a fully capped contact
    // on a quadratic gap, whose area grows linearly with the interference), at most doubled.
    lo = delta;
    F_lo = F_d;
    const double grow = r.N > 0 ? std::min(2.0, N / r.N) : 2.0;
    delta = g_min + (delta - g_min) * std::max(grow, 1.05);
    F_d = F(delta);
  }
  if (!stop) {
    RootTolerance tol;
    tol.rel = 0;
    tol.max_iterations = kMaxLoadSteps;
    bracketed_root(F, lo, delta, F_lo, F_d, tol);
  }
  // 3. Exact load and the load-control measure: the shared loop from this solution ([PK] scaling
  //    of the free pressures, δ = mean of g + u over them), polishing if needed.
  NormalCGResult fin = solve(C, g, N, Control::Load, p_lim, p, options,
                             std::max(0, std::min(kPolishSteps, options.max_iterations - used)), ws);
  fin.iterations += used;
  fin.convolutions += conv;
  return fin;
}

}  // namespace

NormalCGResult solve_normal_approach(const InfluenceGrid& C, const double* g, double delta,
                                     double p_lim, double* p, const NormalCGOptions& options) {
  NormalCGWorkspace ws;
  return solve_normal_approach(C, g, delta, p_lim, p, options, ws);
}

NormalCGResult solve_normal_approach(const InfluenceGrid& C, const double* g, double delta, double p_lim, double* p,
                                     const NormalCGOptions& options, NormalCGWorkspace& ws) {
  return solve(C, g, delta, Control::Approach, p_lim, p, options, options.max_iterations, ws);
}

NormalCGResult solve_normal_load(const InfluenceGrid& C, const double* g, double N, double p_lim,
                                 double* p, const NormalCGOptions& options) {
  NormalCGWorkspace ws;
  return solve_normal_load(C, g, N, p_lim, p, options, ws);
}

NormalCGResult solve_normal_load(const InfluenceGrid& C, const double* g, double N, double p_lim, double* p,
                                 const NormalCGOptions& options, NormalCGWorkspace& ws) {
  if (std::isfinite(p_lim)) return solve_capped_load(C, g, N, p_lim, p, options, ws);
  return solve(C, g, N, Control::Load, p_lim, p, options, options.max_iterations, ws);
}

}  // namespace mh
