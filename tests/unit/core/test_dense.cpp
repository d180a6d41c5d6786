// DenseLU (lib/core/dense.hpp) against Eigen::PartialPivLU: the strips' collocation moved from the
// latter to the former to stop allocating per call, and claims the same bytes. Sizes below and
// above Eigen's unblocked bound (16) and one above its panel width, matrices that need row
// interchanges; the factorisation object reused across sizes, as the strips reuse it.
#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <cstring>
#include <random>

#include "core/dense.hpp"

namespace {

Eigen::MatrixXd random_matrix(int n, std::mt19937& g) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd A(n, n);
  for (int c = 0; c < n; ++c)
    for (int r = 0; r < n; ++r) A(r, c) = u(g);
  // A weak diagonal: partial pivoting must interchange rows.
  for (int k = 0; k < n; ++k) A(k, k) *= 1e-3;
  return A;
}

}  // namespace

TEST_CASE("DenseLU solves bit for bit as Eigen::PartialPivLU, reused across sizes", "[core][dense]") {
  std::mt19937 g(20261130);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  mh::DenseLU lu;  // one object for every size, as a strip collocation reuses it
  for (int n : {1, 2, 5, 16, 17, 40, 100, 7, 300, 40}) {
    const Eigen::MatrixXd A = random_matrix(n, g);
    Eigen::VectorXd b(n);
    for (int k = 0; k < n; ++k) b(k) = u(g);
    const Eigen::VectorXd ref = A.partialPivLu().solve(b);
    std::memcpy(lu.matrix(n), A.data(), sizeof(double) * static_cast<std::size_t>(n) * n);
    lu.factorise();
    Eigen::VectorXd x = b;
    lu.solve_in_place(x.data());
    INFO("n = " << n << ", max |x - ref| = " << (x - ref).cwiseAbs().maxCoeff());
    CHECK(std::memcmp(x.data(), ref.data(), sizeof(double) * static_cast<std::size_t>(n)) == 0);
    // And it solves: the residual at rounding level.
    CHECK((A * x - b).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + b.cwiseAbs().maxCoeff()) * n);
  }
}

TEST_CASE("DenseMatrix keeps its capacity and reads column-major", "[core][dense]") {
  mh::DenseMatrix M;
  M.zero(3, 2);
  M(2, 1) = 5.0;
  CHECK(M.map()(2, 1) == 5.0);
  CHECK(M.col(1)[2] == 5.0);
  const double* before = M.v.data();
  M.zero(2, 2);
  CHECK(M.v.data() == before);  // smaller: no new buffer
  CHECK(M(1, 1) == 0.0);
}
