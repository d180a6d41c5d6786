#pragma once
// Dense linear algebra in buffers that keep their capacity, for solvers called every time step
// that must not allocate once their memory has grown (docs/c-api.md, "What a call allocates"):
// an Eigen::MatrixXd, an Eigen::PartialPivLU or an Eigen::ColPivHouseholderQR reallocates at every
// change of size, and the strips' systems change size from one pass to the next.
//  - DenseMatrix: a column-major matrix over a std::vector, viewed by Eigen::Map.
//  - DenseLU: LU with partial pivoting by Eigen's own blocked kernel, the one PartialPivLU::compute
//    runs, and PartialPivLU's solve (row interchanges, then the unit-lower and upper triangular
//    solves): the same arithmetic, the same bytes (tests/unit/core/test_dense.cpp).
#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace mh {

/// A column-major rows × cols matrix; resize keeps the capacity (no allocation once grown).
struct DenseMatrix {
  std::vector<double> v;
  int rows = 0, cols = 0;
  void resize(int r, int c) {
    rows = r;
    cols = c;
    v.resize(static_cast<std::size_t>(r) * static_cast<std::size_t>(c));
  }
  /// resize, every entry zero.
  void zero(int r, int c) {
    resize(r, c);
    std::fill(v.begin(), v.end(), 0.0);
  }
  double& operator()(int r, int c) { return v[static_cast<std::size_t>(r) + static_cast<std::size_t>(c) * rows]; }
  double operator()(int r, int c) const { return v[static_cast<std::size_t>(r) + static_cast<std::size_t>(c) * rows]; }
  double* col(int c) { return v.data() + static_cast<std::size_t>(c) * rows; }
  const double* col(int c) const { return v.data() + static_cast<std::size_t>(c) * rows; }
  Eigen::Map<Eigen::MatrixXd> map() { return {v.data(), rows, cols}; }
  Eigen::Map<const Eigen::MatrixXd> map() const { return {v.data(), rows, cols}; }
};

/// LU factorisation with partial pivoting of an n × n matrix: fill matrix(n) (column-major),
/// factorise(), then solve_in_place any number of right-hand sides.
class DenseLU {
 public:
  /// The matrix to factorise, column-major (entry (r, c) at r + c n); its contents are replaced
  /// by the factors.
  double* matrix(int n) {
    n_ = n;
    lu_.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    return lu_.data();
  }
  void factorise() {
    transpositions_.resize(static_cast<std::size_t>(n_));
    int swaps = 0;
    if (n_ > 0)
      Eigen::internal::partial_lu_impl<double, Eigen::ColMajor, int>::blocked_lu(n_, n_, lu_.data(), n_,
                                                                                transpositions_.data(), swaps);
  }
  /// x ← A⁻¹ x, x of size n.
  void solve_in_place(double* x) const {
    // P x: the row interchanges in the order they were made (PartialPivLU's permutationP()).
    for (int k = 0; k < n_; ++k) std::swap(x[k], x[transpositions_[static_cast<std::size_t>(k)]]);
    const Eigen::Map<const Eigen::MatrixXd> LU(lu_.data(), n_, n_);
    Eigen::Map<Eigen::VectorXd> v(x, n_);
    LU.triangularView<Eigen::UnitLower>().solveInPlace(v);
    LU.triangularView<Eigen::Upper>().solveInPlace(v);
  }
  int size() const { return n_; }

 private:
  int n_ = 0;
  std::vector<double> lu_;
  std::vector<int> transpositions_;
};

}  // namespace mh
