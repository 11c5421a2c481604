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
        later_start_(n_ + 1, 0),
        later_(n_ * n_, 0),
        column_start_(n_ + 1, 0),
        below_(n_ * n_),
        right_(n_ * n_),
        updates_(n_ * n_ * n_ / 3 + n_),
        row_start_(n_ + 1, 0),
        row_slots_(n_ * n_),
        y_(n_, 0.0),
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
    // The same as flat indices into lu_, so that factor() and solve() are straight runs over them.
    std::size_t update = 0;
    for (std::size_t k = 0; k < n; ++k) {
      column_start_[k] = later_start_[k];
      for (std::size_t e = later_start_[k]; e < later_start_[k + 1]; ++e) {
        const std::size_t m = later_[e];
        below_[e] = {index(m), index(m * n + k), update, 0};
        right_[e] = {index(m), index(k * n + m), 0, 0};
        for (std::size_t f = later_start_[k]; f < later_start_[k + 1]; ++f)
          updates_[update++] = {index(m * n + later_[f]), index(k * n + later_[f])};
        below_[e].updates_end = update;
      }
    }
    column_start_[n] = later_start_[n];
    next = 0;
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
    const Entry* const below = below_.data();
    const Update* const updates = updates_.data();
    for (std::size_t k = 0; k < n; ++k) {
      const double d = lu[k * n + k];
      for (std::size_t e = column_start_[k]; e < column_start_[k + 1]; ++e) {
        double& entry = lu[below[e].flat];
        if (entry == 0.0) continue;  // e.g. a pinned row
        const double l = entry / d;
        entry = l;
        for (std::size_t u = below[e].updates_begin; u < below[e].updates_end; ++u)
          lu[updates[u].target] -= l * lu[updates[u].source];
      }
    }
  }

  /// x = W^-1 b for the W of the last factor(), both in the solver's numbering; x and b may not
  /// alias.
  void solve(const double* b, double* x) {
    const std::size_t n = n_;
    const double* const lu = lu_.data();
    double* const y = y_.data();  // in elimination order
    const Entry* const below = below_.data();
    const Entry* const right = right_.data();
    for (std::size_t k = 0; k < n; ++k) y[k] = b[order_[k]];
    for (std::size_t k = 0; k < n; ++k) {
      const double yk = y[k];
      for (std::size_t e = column_start_[k]; e < column_start_[k + 1]; ++e) y[below[e].unknown] -= lu[below[e].flat] * yk;
    }
    for (std::size_t k = n; k-- > 0;) {
      double s = y[k];
      for (std::size_t e = column_start_[k]; e < column_start_[k + 1]; ++e) s -= lu[right[e].flat] * y[right[e].unknown];
      y[k] = s / lu[k * n + k];
    }
    for (std::size_t k = 0; k < n; ++k) x[order_[k]] = y[k];
  }

 private:
  std::size_t n_;
  std::vector<double> lu_;             // row-major, elimination order: U on and above the diagonal, L below
  std::vector<std::size_t> position_;  // solver's unknown -> elimination position
  std::vector<std::size_t> order_;     // elimination position -> solver's unknown
  static std::uint32_t index(std::size_t i) { return static_cast<std::uint32_t>(i); }
  // An entry of the factors next to the diagonal: L's below position k (row `unknown`), or U's right
  // of it (column `unknown`); for L's, the range of updates_ its row takes in the elimination.
  struct Entry {
    std::uint32_t unknown, flat;
    std::size_t updates_begin, updates_end;
  };
  struct Update {
    std::uint32_t target, source;  // lu[target] -= l * lu[source]
  };

  std::vector<std::size_t> later_start_, later_;  // per position: the later positions coupled to it
  std::vector<std::size_t> column_start_;         // per position: its range of below_ and right_
  std::vector<Entry> below_, right_;
  std::vector<Update> updates_;
  std::vector<std::size_t> row_start_;  // per unknown (solver's numbering): its range of row_slots_
  std::vector<Slot> row_slots_;
  std::vector<double> y_;                         // the solve's scratch
  std::vector<char> adjacent_, eliminated_;       // set_pattern()'s scratch
};

}  // namespace plant
