// Sparse LU factorisation of the circuit solver's W = I - gamma h J (nodes + bodies, about ten
// unknowns), on dense row-major storage allocated once: the solver assembles W straight into
// row(), factor() overwrites it with the factors, solve() uses them.
//
// W is sparse - a node meets only its neighbours, a body its chambers - so the elimination visits
// only the entries of W's pattern and their fill-in, in minimum-degree order (set_pattern(): the
// unknown with the fewest neighbours first, its neighbours then joined). For a tree of valves and
// actuators like the reference circuit the factors have almost no fill-in, where eliminating the
// supply node (which meets every valve) first would fill them in completely.
//
// No pivoting: scaled by rows (V/beta for a node, the mass for a body), W is the identity's
// scaling plus gamma h times flow conductances (symmetric, positive semidefinite: a Laplacian),
// damping (a nonnegative diagonal) and the chamber-body couplings (skew-symmetric: area on one
// side, -area on the other). Its symmetric part is positive definite, so every pivot is positive
// in any elimination order and the growth of the entries stays bounded; the skew couplings are
// small against the diagonal at the steps used (their ratio is about (gamma omega h)^2 for a mass
// on oil springs of natural frequency omega). Rows pinned to the identity (held bodies, cavitating
// nodes) drop out of the elimination. Should a pivot nevertheless be zero, the solve yields
// inf/NaN, which the step's error control rejects.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace plant {

class SmallLu {
 public:
  explicit SmallLu(int n)
      : n_(static_cast<std::size_t>(n)),
        lu_(n_ * n_, 0.0),
        position_(n_, 0),
        order_(n_, 0),
        later_start_(n_ + 1, 0),
        later_(n_ * n_, 0),
        y_(n_, 0.0),
        adjacent_(n_ * n_, 0),
        eliminated_(n_, 0) {
    std::vector<char> diagonal(n_ * n_, 0);
    for (std::size_t i = 0; i < n_; ++i) diagonal[i * n_ + i] = 1;
    set_pattern(diagonal);
  }

  /// Row `r` of W (in the solver's numbering) for assembly: its entry for column c is
  /// row(r)[column(c)]. Every entry of the row must be written before factor().
  double* row(std::size_t r) { return &lu_[position_[r] * n_]; }
  std::size_t column(std::size_t c) const { return position_[c]; }

  /// The entries of W that can be nonzero (row-major, n x n; nonzero = may be nonzero): chooses
  /// the elimination order and the factors' pattern. Entries outside it must be zero in every W
  /// assembled afterwards. Does not allocate.
  void set_pattern(const std::vector<char>& pattern) {
    const std::size_t n = n_;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        adjacent_[i * n + j] = i != j && (pattern[i * n + j] != 0 || pattern[j * n + i] != 0);
    std::fill(eliminated_.begin(), eliminated_.end(), 0);
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t best = n, best_degree = n + 1;
      for (std::size_t v = 0; v < n; ++v) {
        if (eliminated_[v]) continue;
        std::size_t degree = 0;
        for (std::size_t u = 0; u < n; ++u) degree += !eliminated_[u] && adjacent_[v * n + u];
        if (degree < best_degree) {
          best = v;
          best_degree = degree;
        }
      }
      eliminated_[best] = 1;
      order_[k] = best;
      position_[best] = k;
      // Eliminating `best` couples all its remaining neighbours: the fill-in.
      for (std::size_t a = 0; a < n; ++a) {
        if (eliminated_[a] || !adjacent_[best * n + a]) continue;
        for (std::size_t b = 0; b < n; ++b)
          if (b != a && !eliminated_[b] && adjacent_[best * n + b]) adjacent_[a * n + b] = 1;
      }
    }
    // Per elimination position k: the later positions coupled to it (filled pattern), which are
    // both the rows below the pivot with an entry in column k and the columns right of it in row k.
    std::size_t next = 0;
    for (std::size_t k = 0; k < n; ++k) {
      later_start_[k] = next;
      for (std::size_t m = k + 1; m < n; ++m)
        if (adjacent_[order_[k] * n + order_[m]]) later_[next++] = m;
    }
    later_start_[n] = next;
  }

  void factor() {
    const std::size_t n = n_;
    double* const lu = lu_.data();
    for (std::size_t k = 0; k < n; ++k) {
      const double d = lu[k * n + k];
      const std::size_t* const first = &later_[later_start_[k]];
      const std::size_t* const last = &later_[later_start_[k + 1]];
      const double* row_k = &lu[k * n];
      for (const std::size_t* i = first; i != last; ++i) {
        double* row_i = &lu[*i * n];
        if (row_i[k] == 0.0) continue;  // e.g. a pinned row
        const double l = row_i[k] / d;
        row_i[k] = l;
        for (const std::size_t* j = first; j != last; ++j) row_i[*j] -= l * row_k[*j];
      }
    }
  }

  /// x = W^-1 b for the W of the last factor(), both in the solver's numbering; x and b may not
  /// alias.
  void solve(const double* b, double* x) {
    const std::size_t n = n_;
    const double* const lu = lu_.data();
    double* const y = y_.data();  // in elimination order
    for (std::size_t k = 0; k < n; ++k) y[k] = b[order_[k]];
    for (std::size_t k = 0; k < n; ++k) {
      const double yk = y[k];
      for (std::size_t e = later_start_[k]; e < later_start_[k + 1]; ++e) y[later_[e]] -= lu[later_[e] * n + k] * yk;
    }
    for (std::size_t k = n; k-- > 0;) {
      double s = y[k];
      const double* row = &lu[k * n];
      for (std::size_t e = later_start_[k]; e < later_start_[k + 1]; ++e) s -= row[later_[e]] * y[later_[e]];
      y[k] = s / row[k];
    }
    for (std::size_t k = 0; k < n; ++k) x[order_[k]] = y[k];
  }

 private:
  std::size_t n_;
  std::vector<double> lu_;             // row-major, elimination order: U on and above the diagonal, L below
  std::vector<std::size_t> position_;  // solver's unknown -> elimination position
  std::vector<std::size_t> order_;     // elimination position -> solver's unknown
  std::vector<std::size_t> later_start_, later_;  // per position: the later positions coupled to it
  std::vector<double> y_;                         // the solve's scratch
  std::vector<char> adjacent_, eliminated_;       // set_pattern()'s scratch
};

}  // namespace plant
