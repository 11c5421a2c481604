// The circuit solver's sparse LU (plant/small_lu.h): the solution of W x = b matches a dense
// elimination with partial pivoting for matrices shaped like the solver's W (a star of nodes with
// chambers and bodies, skew node-body couplings, pinned rows), whatever the elimination order the
// pattern gives, and a pattern that grows gets a new order.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "plant/small_lu.h"

namespace plant {
namespace {

using Matrix = std::vector<std::vector<double>>;

// Reference: dense Gaussian elimination with partial pivoting.
std::vector<double> dense_solve(Matrix a, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::abs(a[i][k]) > std::abs(a[pivot][k])) pivot = i;
    std::swap(a[k], a[pivot]);
    std::swap(b[k], b[pivot]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const double l = a[i][k] / a[k][k];
      for (std::size_t j = k; j < n; ++j) a[i][j] -= l * a[k][j];
      b[i] -= l * b[k];
    }
  }
  std::vector<double> x(n);
  for (std::size_t i = n; i-- > 0;) {
    double s = b[i];
    for (std::size_t j = i + 1; j < n; ++j) s -= a[i][j] * x[j];
    x[i] = s / a[i][i];
  }
  return x;
}

// W = I - gamma h J of a circuit: node 0 a supply feeding pairs of chambers (1, 2), (3, 4), ...,
// each pair moving one body (the last unknowns); flows give a Laplacian, bodies a skew coupling.
struct Circuit {
  Matrix w;
  std::vector<char> pattern;
};

Circuit make_circuit(int pairs, std::mt19937& rng, bool with_supply_edges = true) {
  std::uniform_real_distribution<double> conductance(1e-12, 1e-10), volume(1e-4, 2e-3), area(1e-4, 3e-3),
      mass(0.1, 300.0);
  const int nodes = 1 + 2 * pairs, n = nodes + pairs;
  const double gh = 0.29e-3, beta = 1.4e9;
  Matrix g(static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(n), 0.0));
  auto at = [&](int i, int j) -> double& { return g[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]; };
  auto edge = [&](int a, int b, double c) {
    at(a, a) -= c;
    at(b, b) -= c;
    at(a, b) += c;
    at(b, a) += c;
  };
  for (int p = 0; p < pairs; ++p) {
    const int a = 1 + 2 * p, b = a + 1, body = nodes + p;
    if (with_supply_edges) {
      edge(0, a, conductance(rng));
      edge(0, b, conductance(rng));
    }
    at(a, a) -= conductance(rng);  // to tank
    at(b, b) -= conductance(rng);
    const double aa = area(rng), ab = area(rng);
    at(a, body) -= aa;
    at(body, a) += aa;
    at(b, body) += ab;
    at(body, b) -= ab;
    at(body, body) -= 1500.0;  // viscous friction
  }
  at(0, 0) -= conductance(rng);  // relief
  Circuit c;
  c.w.assign(static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(n), 0.0));
  c.pattern.assign(static_cast<std::size_t>(n * n), 0);
  for (int i = 0; i < n; ++i) {
    const double scale = i < nodes ? beta / volume(rng) : 1.0 / mass(rng);
    for (int j = 0; j < n; ++j) {
      c.w[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = (i == j ? 1.0 : 0.0) - gh * scale * at(i, j);
      c.pattern[static_cast<std::size_t>(i * n + j)] = i == j || at(i, j) != 0.0;
    }
  }
  return c;
}

void assemble(SmallLu& lu, const Matrix& w) {
  double* values = lu.values();
  for (std::size_t r = 0; r < w.size(); ++r) {
    const SmallLu::RowSlots slots = lu.row(r);
    for (const SmallLu::Slot* e = slots.first; e != slots.last; ++e) values[e->flat] = w[r][e->column];
    values[slots.diagonal] = w[r][r];
  }
}

void expect_solves(SmallLu& lu, const Matrix& w, std::mt19937& rng) {
  std::uniform_real_distribution<double> rhs(-1e6, 1e6);
  const std::size_t n = w.size();
  std::vector<double> b(n), x(n);
  for (double& v : b) v = rhs(rng);
  assemble(lu, w);
  lu.factor();
  lu.solve(b.data(), x.data());
  const std::vector<double> expected = dense_solve(w, b);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(x[i], expected[i], 1e-9 * (1.0 + std::abs(expected[i]))) << "unknown " << i;
}

TEST(SmallLu, SolvesCircuitShapedSystemsLikeDenseEliminationWithPivoting) {
  std::mt19937 rng(14);
  for (int pairs = 1; pairs <= 5; ++pairs) {
    for (int trial = 0; trial < 20; ++trial) {
      const Circuit c = make_circuit(pairs, rng);
      SmallLu lu(static_cast<int>(c.w.size()));
      lu.set_pattern(c.pattern);
      expect_solves(lu, c.w, rng);
    }
  }
}

TEST(SmallLu, PinnedRowsKeepTheirValue) {
  std::mt19937 rng(408);
  Circuit c = make_circuit(2, rng);
  SmallLu lu(static_cast<int>(c.w.size()));
  lu.set_pattern(c.pattern);
  // A held body and a cavitating node: their rows of W become the identity's.
  for (std::size_t pinned : {std::size_t{1}, c.w.size() - 1}) {
    for (double& v : c.w[pinned]) v = 0.0;
    c.w[pinned][pinned] = 1.0;
  }
  expect_solves(lu, c.w, rng);
}

TEST(SmallLu, AGrownPatternIsFactoredCompletely) {
  std::mt19937 rng(406);
  // First only the chambers' couplings (valves closed, no leakage), then the supply edges too.
  const Circuit closed = make_circuit(3, rng, false);
  const Circuit open = make_circuit(3, rng, true);
  SmallLu lu(static_cast<int>(open.w.size()));
  lu.set_pattern(closed.pattern);
  expect_solves(lu, closed.w, rng);
  lu.set_pattern(open.pattern);
  expect_solves(lu, open.w, rng);
}

}  // namespace
}  // namespace plant
