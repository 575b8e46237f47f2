// Randomized differential test of *EQUATION (issue 12): 400 generated spring networks — grounded
// SPRING1 and coupling SPRING2 springs on random DOFs 1-6 of a few nodes, 1-6 random equations
// (2-4 terms, random coefficients, chains where a dependent DOF is another equation's term),
// boundary conditions with zero and non-zero values on independent DOFs, concentrated forces
// and moments — solved by gapfem and by an independent oracle: the dense bordered system
// [K A^T; A 0] with the equations and the boundary conditions as rows A, by full-pivoting LU.
// Displacements, rotations and the reactions at the prescribed DOFs must agree to 1e-9.
#include "test_util.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <random>
#include <set>

using namespace gapfem;
using namespace gapfem::test;

namespace {

struct Spring {
  int a, da, b, db; ///< b < 0: SPRING1 (grounded)
  double k;
};
struct Term {
  int node, dof;
  double c;
};
struct RandomModel {
  int n_nodes = 0;
  std::vector<Spring> springs;
  std::vector<std::vector<Term>> equations;
  std::vector<std::pair<std::pair<int, int>, double>> bcs, loads; ///< ((node, dof), value)
};

int index_of(int node, int dof) {
  return 6 * node + (dof - 1);
}

RandomModel generate(unsigned seed) {
  std::mt19937 rng(seed);
  auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  RandomModel m;
  m.n_nodes = 2 + pick(6);
  // every node carries a random non-empty set of DOFs, each grounded by a SPRING1
  std::vector<std::pair<int, int>> dofs;
  for (int n = 0; n < m.n_nodes; ++n) {
    int added = 0;
    for (int d = 1; d <= 6; ++d)
      if (pick(3) != 0 || (d == 6 && added == 0)) {
        dofs.emplace_back(n, d);
        m.springs.push_back({n, d, -1, 0, std::pow(10.0, uni(-1.0, 1.0))});
        ++added;
      }
  }
  const int nd = static_cast<int>(dofs.size());
  for (int s = 0, ns = nd + pick(nd); s < ns; ++s) {
    const auto [a, da] = dofs[pick(nd)];
    const auto [b, db] = dofs[pick(nd)];
    if (a == b) continue;
    m.springs.push_back({a, da, b, db, std::pow(10.0, uni(-1.0, 1.0))});
  }
  // equations: distinct dependent DOFs; other terms anywhere (chains through dependents)
  std::set<int> dependent;
  const int ne = 1 + pick(std::min(6, nd / 2));
  for (int e = 0; e < ne; ++e) {
    std::vector<Term> eq;
    std::set<int> used;
    const int nt = 2 + pick(3);
    for (int t = 0; t < 40 && static_cast<int>(eq.size()) < nt; ++t) {
      const auto [n, d] = dofs[pick(nd)];
      const int id = index_of(n, d);
      if (used.count(id) || (eq.empty() && dependent.count(id))) continue;
      used.insert(id);
      const double c = (pick(2) ? 1.0 : -1.0) * uni(0.3, 2.0);
      eq.push_back({n, d, c});
    }
    if (eq.size() < 2) continue;
    dependent.insert(index_of(eq[0].node, eq[0].dof));
    m.equations.push_back(eq);
  }
  // boundary conditions on independent DOFs, loads anywhere else
  std::set<int> fixed;
  for (int b = 0, nb = pick(3); b < nb; ++b) {
    const auto [n, d] = dofs[pick(nd)];
    const int id = index_of(n, d);
    if (dependent.count(id) || fixed.count(id)) continue;
    fixed.insert(id);
    m.bcs.push_back({{n, d}, pick(2) ? 0.0 : uni(-0.5, 0.5)});
  }
  for (int l = 0, nl = 1 + pick(4); l < nl; ++l) {
    const auto [n, d] = dofs[pick(nd)];
    if (fixed.count(index_of(n, d))) continue;
    fixed.insert(index_of(n, d)); // one load per DOF
    m.loads.push_back({{n, d}, uni(-3.0, 3.0)});
  }
  return m;
}

std::string deck(const RandomModel& m) {
  std::string d = "*HEADING\nrandom equations\n*NODE\n";
  for (int n = 0; n < m.n_nodes; ++n) d += fmt::format("{}, {}, {}, 0.\n", n + 1, n, n % 2);
  for (std::size_t s = 0; s < m.springs.size(); ++s) {
    const Spring& sp = m.springs[s];
    if (sp.b < 0)
      d += fmt::format("*ELEMENT, TYPE=SPRING1, ELSET=S{0}\n{0}, {1}\n*SPRING, ELSET=S{0}\n{2}\n"
                       "{3:.17g}\n",
                       s + 1, sp.a + 1, sp.da, sp.k);
    else
      d += fmt::format("*ELEMENT, TYPE=SPRING2, ELSET=S{0}\n{0}, {1}, {2}\n*SPRING, ELSET=S{0}\n"
                       "{3}, {4}\n{5:.17g}\n",
                       s + 1, sp.a + 1, sp.b + 1, sp.da, sp.db, sp.k);
  }
  d += "*EQUATION\n";
  for (const auto& eq : m.equations) {
    d += fmt::format("{}\n", eq.size());
    for (std::size_t t = 0; t < eq.size(); ++t)
      d += fmt::format("{}, {}, {:.17g}{}", eq[t].node + 1, eq[t].dof, eq[t].c,
                       (t % 4 == 3 || t + 1 == eq.size()) ? "\n" : ", ");
  }
  d += "*STEP\n*STATIC\n";
  if (!m.bcs.empty()) d += "*BOUNDARY\n";
  for (const auto& [nd, v] : m.bcs)
    d += fmt::format("{}, {}, {}, {:.17g}\n", nd.first + 1, nd.second, nd.second, v);
  if (!m.loads.empty()) d += "*CLOAD\n";
  for (const auto& [nd, v] : m.loads)
    d += fmt::format("{}, {}, {:.17g}\n", nd.first + 1, nd.second, v);
  return d + "*END STEP\n";
}

struct OracleSolution {
  Eigen::VectorXd u, reaction; ///< 6 per node
};

/// [K A^T; A 0] [u; lambda] = [f; b] with the equations and the boundary conditions as rows of A.
OracleSolution oracle(const RandomModel& m) {
  const int n = 6 * m.n_nodes;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  std::vector<bool> active(n, false);
  for (const Spring& s : m.springs) {
    const int i = index_of(s.a, s.da);
    active[i] = true;
    K(i, i) += s.k;
    if (s.b < 0) continue;
    const int j = index_of(s.b, s.db);
    active[j] = true;
    K(j, j) += s.k;
    K(i, j) -= s.k;
    K(j, i) -= s.k;
  }
  for (int i = 0; i < n; ++i)
    if (!active[i]) K(i, i) = 1.0; // DOFs no spring uses: decoupled, zero
  const int ne = static_cast<int>(m.equations.size());
  const int nr = ne + static_cast<int>(m.bcs.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n + nr, n + nr);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + nr);
  S.topLeftCorner(n, n) = K;
  for (int e = 0; e < ne; ++e)
    for (const Term& t : m.equations[e]) {
      S(n + e, index_of(t.node, t.dof)) = t.c;
      S(index_of(t.node, t.dof), n + e) = t.c;
    }
  for (std::size_t b = 0; b < m.bcs.size(); ++b) {
    const int i = index_of(m.bcs[b].first.first, m.bcs[b].first.second);
    S(n + ne + b, i) = S(i, n + ne + b) = 1.0;
    rhs(n + ne + b) = m.bcs[b].second;
  }
  for (const auto& [nd, v] : m.loads) rhs(index_of(nd.first, nd.second)) += v;
  const Eigen::VectorXd x = S.fullPivLu().solve(rhs);
  OracleSolution o;
  o.u = x.head(n);
  o.reaction = Eigen::VectorXd::Zero(n);
  // K u + A_eq^T lambda_eq + lambda_bc = f: the support's reaction (gapfem's RF = f_int - f_ext,
  // f_int holding the constraint forces) is -lambda_bc
  for (std::size_t b = 0; b < m.bcs.size(); ++b)
    o.reaction(index_of(m.bcs[b].first.first, m.bcs[b].first.second)) = -x(n + ne + b);
  return o;
}

} // namespace

TEST(RandomEquation, SpringNetworksMatchTheBorderedOracle) {
  int checked = 0;
  for (unsigned seed = 1; seed <= 400; ++seed) {
    const RandomModel m = generate(seed);
    if (m.equations.empty()) continue;
    const OracleSolution o = oracle(m);
    const JobResult r = run_deck(deck(m));
    ASSERT_EQ(r.exit_code, 0) << "seed " << seed << ": " << r.error << "\n" << deck(m);
    const Frame& f = last_frame(r);
    double scale = 1e-12;
    for (int i = 0; i < o.u.size(); ++i) scale = std::max(scale, std::abs(o.u(i)));
    double fscale = 1.0;
    for (int i = 0; i < o.reaction.size(); ++i) fscale = std::max(fscale, std::abs(o.reaction(i)));
    for (int n = 0; n < m.n_nodes; ++n) {
      const NodeId id = r.model->mesh.find_node(n + 1);
      for (int c = 0; c < 3; ++c) {
        if (f.nodes.dof_mask[id] & dof_bit(static_cast<DofType>(c)))
          EXPECT_NEAR(f.nodes.U[id][c], o.u(6 * n + c), 1e-9 * scale)
              << "seed " << seed << " node " << n + 1 << " U" << c + 1;
        if (f.nodes.dof_mask[id] & dof_bit(static_cast<DofType>(c + 3)))
          EXPECT_NEAR(f.nodes.UR[id][c], o.u(6 * n + 3 + c), 1e-9 * scale)
              << "seed " << seed << " node " << n + 1 << " UR" << c + 1;
      }
    }
    for (const auto& [nd, v] : m.bcs) {
      const NodeId id = r.model->mesh.find_node(nd.first + 1);
      const int c = nd.second;
      const double got = c <= 3 ? f.nodes.RF[id][c - 1] : f.nodes.RM[id][c - 4];
      EXPECT_NEAR(got, o.reaction(index_of(nd.first, c)), 1e-9 * fscale)
          << "seed " << seed << " node " << nd.first + 1 << " reaction " << c;
    }
    ++checked;
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << deck(m);
      break;
    }
  }
  std::printf("[ random ] %d spring networks with equations checked\n", checked);
  EXPECT_GT(checked, 300);
}
