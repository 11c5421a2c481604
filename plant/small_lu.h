// LU factorisation with partial pivoting for the circuit solver's small dense W (nodes + bodies,
// about ten unknowns). Eigen's PartialPivLU for dynamic sizes spends most of its time at this size
// in blocking and dispatch; this is the same algorithm (pivot: the largest magnitude in the
// column, rows swapped) in plain loops over storage allocated once. Like Eigen's, a zero pivot is
// not an error: the solve then yields inf/NaN, which the step's error control rejects.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace plant {

class SmallLu {
 public:
  explicit SmallLu(int n) : n_(static_cast<std::size_t>(n)), lu_(n_ * n_, 0.0), perm_(n_, 0) {}

  void compute(const Eigen::MatrixXd& a) {
    const std::size_t n = n_;
    for (std::size_t i = 0; i < n; ++i) {
      perm_[i] = i;
      for (std::size_t j = 0; j < n; ++j) lu_[i * n + j] = a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    }
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t pivot = k;
      double biggest = std::abs(lu_[k * n + k]);
      for (std::size_t i = k + 1; i < n; ++i) {
        const double v = std::abs(lu_[i * n + k]);
        if (v > biggest) {
          biggest = v;
          pivot = i;
        }
      }
      if (pivot != k) {
        for (std::size_t j = 0; j < n; ++j) std::swap(lu_[k * n + j], lu_[pivot * n + j]);
        std::swap(perm_[k], perm_[pivot]);
      }
      const double d = lu_[k * n + k];
      if (d == 0.0) continue;
      const double* row_k = &lu_[k * n];
      for (std::size_t i = k + 1; i < n; ++i) {
        double* row_i = &lu_[i * n];
        if (row_i[k] == 0.0) continue;  // W is sparse: most rows need no update
        const double l = row_i[k] / d;
        row_i[k] = l;
        for (std::size_t j = k + 1; j < n; ++j) row_i[j] -= l * row_k[j];
      }
    }
  }

  /// x = A^-1 b for the A of the last compute(); x and b may not alias.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
    const std::size_t n = n_;
    for (std::size_t i = 0; i < n; ++i) {
      double s = b[static_cast<Eigen::Index>(perm_[i])];
      const double* row = &lu_[i * n];
      for (std::size_t j = 0; j < i; ++j) s -= row[j] * x[static_cast<Eigen::Index>(j)];
      x[static_cast<Eigen::Index>(i)] = s;
    }
    for (std::size_t i = n; i-- > 0;) {
      double s = x[static_cast<Eigen::Index>(i)];
      const double* row = &lu_[i * n];
      for (std::size_t j = i + 1; j < n; ++j) s -= row[j] * x[static_cast<Eigen::Index>(j)];
      x[static_cast<Eigen::Index>(i)] = s / row[i];
    }
  }

 private:
  std::size_t n_;
  std::vector<double> lu_;  // row-major: U on and above the diagonal, L (unit diagonal) below
  std::vector<std::size_t> perm_;
};

}  // namespace plant
