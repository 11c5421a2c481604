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
#include <cstdint>
#include <vector>

namespace plant {

class SmallLu {
 public:
  explicit SmallLu(int n)
      : n_(static_cast<std::size_t>(n)),
        lu_(n_ * n_, 0.0),
        position_(n_, 0),
        order_(n_, 0),
        permuted_(n_, 0.0),
        positions_(n_),
        columns_(n_ * n_),
        row_start_(n_ + 1, 0),
        row_slots_(n_ * n_),
        adjacent_(n_ * n_, 0),
        eliminated_(n_, 0) {
    std::vector<char> diagonal(n_ * n_, 0);
    for (std::size_t i = 0; i < n_; ++i) diagonal[i * n_ + i] = 1;
    set_pattern(diagonal);
  }

  /// Where row r of W (in the solver's numbering) is stored: its diagonal entry at values()[diagonal],
  /// and the off-diagonal entries the factors use at values()[flat], for each {column, flat} in
  /// [first, last). Before factor(), all of them must be written; W's other entries are zero.
  struct Slot {
    std::uint32_t column, flat;
  };
  struct RowSlots {
    const Slot* first;
    const Slot* last;
    std::size_t diagonal;
  };
  RowSlots row(std::size_t r) const {
    return {&row_slots_[row_start_[r]], &row_slots_[row_start_[r + 1]], position_[r] * (n_ + 1)};
  }
  double* values() { return lu_.data(); }

  /// The entries of W that can be nonzero (row-major, n x n; nonzero = may be nonzero): chooses
  /// the elimination order and the factors' pattern, and lays out factor() and solve() as runs
  /// over it. Entries outside it must be zero in every W assembled afterwards. Does not allocate.
  template <typename Flag>
  void set_pattern(const std::vector<Flag>& pattern) {
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
    // adjacent_ is now the factors' (symmetric) pattern. For position k, the later positions m
    // coupled to it are both the rows below the pivot with an entry in column k (L) and the
    // columns right of it in row k (U); the earlier ones are the columns of L in row k.
    auto coupled = [&](std::size_t k, std::size_t m) { return adjacent_[order_[k] * n + order_[m]] != 0; };
    std::size_t next_column = 0;
    for (std::size_t k = 0; k < n; ++k) {
      Position& position = positions_[k];
      position.unknown = index(order_[k]);
      position.earlier_begin = index(next_column);
      for (std::size_t m = 0; m < k; ++m)
        if (coupled(k, m)) columns_[next_column++] = index(m);
      position.later_begin = index(next_column);
      for (std::size_t m = k + 1; m < n; ++m)
        if (coupled(k, m)) columns_[next_column++] = index(m);
      position.later_end = index(next_column);
    }
    std::size_t next = 0;
    for (std::size_t r = 0; r < n; ++r) {
      row_start_[r] = next;
      for (std::size_t c = 0; c < n; ++c)
        if (adjacent_[r * n + c]) row_slots_[next++] = {index(c), index(position_[r] * n + position_[c])};
    }
    row_start_[n] = next;
  }

  void factor() {
    const std::size_t n = n_;
    double* const lu = lu_.data();
    const std::uint32_t* const columns = columns_.data();
    for (std::size_t k = 0; k < n; ++k) {
      Position& position = positions_[k];
      const double inverse = 1.0 / lu[k * (n + 1)];
      position.inverse_pivot = inverse;
      // Rows below the pivot with an entry in column k are the columns right of it in row k
      // (the pattern is symmetric): each such row m gets l = W(m,k)/W(k,k) times row k.
      const std::uint32_t* const first = columns + position.later_begin;
      const std::uint32_t* const last = columns + position.later_end;
      const double* const pivot_row = lu + k * n;
      for (const std::uint32_t* m = first; m != last; ++m) {
        double* const row = lu + *m * n;
        double& entry = row[k];
        if (entry == 0.0) continue;  // e.g. a pinned row
        const double l = entry * inverse;
        entry = l;
        for (const std::uint32_t* j = first; j != last; ++j) row[*j] -= l * pivot_row[*j];
      }
    }
  }

  /// x = W^-1 b for the W of the last factor(), both in the solver's numbering.
  void solve(const double* b, double* x) {
    const std::size_t n = n_;
    double* const y = permuted_.data();  // the unknowns in elimination order
    const std::uint32_t* const columns = columns_.data();
    const Position* const first = positions_.data();
    const Position* const last = first + n;
    // Forward (L, unit diagonal), row by row: y[m] = b[m] - sum over k < m of L(m,k) y[k].
    const double* row = lu_.data();
    double* ym = y;
    for (const Position* p = first; p != last; ++p, row += n, ++ym) {
      double sum = b[p->unknown];
      for (const std::uint32_t* k = columns + p->earlier_begin; k != columns + p->later_begin; ++k) sum -= row[*k] * y[*k];
      *ym = sum;
    }
    // Backward (U): y[k] = (y[k] - sum over m > k of U(k,m) y[m]) / U(k,k).
    for (const Position* p = last; p != first;) {
      --p;
      row -= n;
      --ym;
      double sum = *ym;
      for (const std::uint32_t* m = columns + p->later_begin; m != columns + p->later_end; ++m) sum -= row[*m] * y[*m];
      sum *= p->inverse_pivot;
      *ym = sum;
      x[p->unknown] = sum;
    }
  }

 private:
  static std::uint32_t index(std::size_t i) { return static_cast<std::uint32_t>(i); }

  std::size_t n_;
  std::vector<double> lu_;             // row-major, elimination order: U on and above the diagonal, L below
  std::vector<std::size_t> position_;  // solver's unknown -> elimination position
  std::vector<std::size_t> order_;     // elimination position -> solver's unknown
  std::vector<double> permuted_;       // solve()'s scratch
  // Per elimination position k: its unknown, the positions coupled to it in the factors (those
  // before it: columns_[earlier_begin, later_begin), the columns of L in row k; those after it,
  // ascending: columns_[later_begin, later_end), the columns of U in row k and the rows of L in
  // column k), and 1/pivot from the last factor().
  struct Position {
    std::uint32_t unknown, earlier_begin, later_begin, later_end;
    double inverse_pivot;
  };
  std::vector<Position> positions_;
  std::vector<std::uint32_t> columns_;
  std::vector<std::size_t> row_start_;  // per unknown (solver's numbering): its range of row_slots_
  std::vector<Slot> row_slots_;
  std::vector<char> adjacent_, eliminated_;  // set_pattern()'s scratch
};

}  // namespace plant
