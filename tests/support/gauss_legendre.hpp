#pragma once
// N-point Gauss–Legendre nodes and weights on [−1, 1] for the tests' quadratures (Abramowitz &
// Stegun, Table 25.4), computed by Newton on P_N so that no test depends on a typed table:
// start z = cos(π (i + 3/4)/(N + 1/2)) (A&S 22.16), Bonnet's recursion (A&S 22.7.10), weights
// 2 / ((1 − z²) P_N'(z)²) (A&S 25.4.29).
#include <cmath>

template <int N>
struct GaussLegendre {
  static constexpr int n = N;
  double x[N], w[N];
  GaussLegendre() {
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < N; ++i) {
      double z = std::cos(pi * (i + 0.75) / (N + 0.5)), dp = 0;
      for (int k = 0; k < 100; ++k) {
        double p0 = 1, p1 = z;
        for (int j = 2; j <= N; ++j) {
          const double p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / j;
          p0 = p1;
          p1 = p2;
        }
        dp = N * (z * p1 - p0) / (z * z - 1);
        const double dz = p1 / dp;
        z -= dz;
        if (std::fabs(dz) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2 / ((1 - z * z) * dp * dp);
    }
  }
};
