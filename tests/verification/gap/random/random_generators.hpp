#pragma once
// Generators of the random gap models (random_models.hpp) for the differential test. Every model
// is a function of its seed, so a failure is reproduced by the seed printed with it.
#include "random_models.hpp"

#include <random>

namespace gapfem::test::random_contact {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : _g(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(_g); }
  double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(_g); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  Eigen::Vector3d direction(int dim) {
    Eigen::Vector3d v;
    do {
      v = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), dim == 3 ? uniform(-1, 1) : 0.0);
    } while (v.norm() < 0.2 || v.norm() > 1.0);
    return v.normalized();
  }

 private:
  std::mt19937_64 _g;
};

inline int add_node(ModelDef& m, Eigen::Vector3d X, bool free) {
  m.nodes.push_back({X, free});
  return static_cast<int>(m.nodes.size()) - 1;
}

/// Steps with zero loads and motions, sized for the model's nodes.
inline void add_steps(ModelDef& m, Rng& r, int n) {
  const double initial[] = {1.0, 0.5, 0.25, 0.1};
  for (int s = 0; s < n; ++s) {
    StepDef st;
    st.load.assign(m.nodes.size(), Eigen::Vector3d::Zero());
    st.motion = st.load;
    st.initial_increment = initial[r.integer(0, 3)];
    m.steps.push_back(st);
  }
}

/// Frictionless GAPUNI networks: 1-6 nodes on springs (and trusses), 1-12 gaps to supports or
/// between nodes, random directions (given or from the coordinates), DIRECT or PENALTY normal
/// behaviour, loads and support motions that close and open gaps.
inline ModelDef network_model(std::uint64_t seed, NormalMethod augmented_or_not) {
  Rng r(seed);
  ModelDef m;
  m.tag = fmt::format("network seed {}", seed);
  m.dim = r.chance(0.4) ? 2 : 3;
  const int nfree = r.integer(1, 6);
  for (int i = 0; i < nfree; ++i)
    add_node(m,
             Eigen::Vector3d(r.uniform(0, 4), r.uniform(0, 4), m.dim == 3 ? r.uniform(0, 4) : 0.0),
             true);
  for (int i = 0; i < nfree; ++i)
    for (int k = 0; k < m.dim; ++k) m.springs1.push_back({i, k, r.log_uniform(10, 1000)});
  for (int i = 1; i < nfree; ++i)
    if (r.chance(0.5))
      m.springs2.push_back(
          {r.integer(0, i - 1), i, r.integer(0, m.dim - 1), r.log_uniform(10, 1000)});
  const int ntruss = r.integer(m.dim == 2 ? 1 : 0, 3);
  for (int t = 0; t < ntruss; ++t) {
    const int a = r.integer(0, nfree - 1);
    int b;
    if (nfree > 1 && r.chance(0.5)) {
      do b = r.integer(0, nfree - 1);
      while (b == a);
    } else {
      b = add_node(m, m.nodes[a].X + r.uniform(0.5, 2.0) * r.direction(m.dim), false);
    }
    m.trusses.push_back({a, b, r.log_uniform(10, 1000) * (m.nodes[a].X - m.nodes[b].X).norm()});
  }
  // at most `dim` gaps at a node, so that the closed gaps' rows stay independent (more would make
  // the contact forces statically indeterminate: RandomContact.OverconstrainedNode covers that)
  const int ngaps = std::min(r.integer(1, 12), m.dim * nfree);
  std::vector<int> degree(static_cast<std::size_t>(nfree), 0);
  auto pick = [&](int avoid) {
    std::vector<int> open;
    for (int i = 0; i < nfree; ++i)
      if (i != avoid && degree[i] < m.dim) open.push_back(i);
    return open.empty() ? -1 : open[r.integer(0, static_cast<int>(open.size()) - 1)];
  };
  for (int g = 0; g < ngaps; ++g) {
    GapDef gd;
    gd.n1 = pick(-1);
    if (gd.n1 < 0) break;
    ++degree[gd.n1];
    gd.dir = r.direction(m.dim);
    gd.dir_given = r.chance(0.7);
    int partner = nfree > 1 && r.chance(0.4) ? pick(gd.n1) : -1;
    for (const GapDef& other : m.gaps) // one gap per pair of nodes (two would share their row)
      if ((other.n1 == gd.n1 && other.n2 == partner) || (other.n2 == gd.n1 && other.n1 == partner))
        partner = -1;
    if (partner >= 0) {
      gd.n2 = partner;
      ++degree[partner];
      gd.dir_given = gd.dir_given || (m.nodes[gd.n2].X - m.nodes[gd.n1].X).norm() < 0.1;
    } else {
      const Eigen::Vector3d at = gd.dir_given ? r.direction(m.dim) : gd.dir;
      gd.n2 = add_node(m, m.nodes[gd.n1].X + r.uniform(0.5, 1.5) * at, false);
    }
    gd.d = r.uniform(-0.05, 0.3);
    gd.normal = augmented_or_not;
    if (gd.normal == NormalMethod::Direct && r.chance(0.2)) {
      gd.normal = NormalMethod::Penalty;
      gd.penalty = r.log_uniform(1e3, 1e6);
    }
    m.gaps.push_back(gd);
  }
  m.fix_z = false;
  add_steps(m, r, r.integer(2, 4));
  const bool nlgeom = m.trusses.empty() && r.chance(0.5);
  for (StepDef& st : m.steps) {
    st.nlgeom = nlgeom;
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      if (m.nodes[i].free)
        st.load[i] = r.uniform(0, 200) * r.direction(m.dim);
      else if (r.chance(0.3))
        st.motion[i] = r.uniform(0, 0.3) * r.direction(m.dim);
    }
  }
  return m;
}

/// Friction with one tangential direction: gaps along y (closing down or up), slip along x, the
/// stiffness decoupled in x and y (SPRING1/SPRING2 per DOF, vertical trusses). Nodes pressed and
/// pulled in y, driven in x by loads and by springs to moving supports; elastic slip from 1e-9 to
/// 1e-1 (absolute, node spacing 2), SLIP TOLERANCE, or LAGRANGE.
inline ModelDef friction_model(std::uint64_t seed) {
  Rng r(seed);
  ModelDef m;
  m.tag = fmt::format("friction seed {}", seed);
  m.dim = r.chance(0.4) ? 2 : 3;
  m.fix_z = m.dim == 3;
  const int nfree = r.integer(1, 8);
  for (int i = 0; i < nfree; ++i) add_node(m, Eigen::Vector3d(2.0 * i, 0, 0), true);
  for (int i = 0; i < nfree; ++i) {
    m.springs1.push_back({i, 0, r.log_uniform(1, 1000)});
    m.springs1.push_back({i, 1, r.log_uniform(10, 1000)});
  }
  for (int i = 1; i < nfree; ++i) {
    if (r.chance(0.5)) m.springs2.push_back({i - 1, i, 0, r.log_uniform(10, 1000)});
    if (r.chance(0.3)) m.springs2.push_back({i - 1, i, 1, r.log_uniform(10, 1000)});
  }
  std::vector<int> drivers;
  for (int i = 0; i < nfree; ++i)
    if (r.chance(0.5)) {
      const int dnode = add_node(m, m.nodes[i].X + Eigen::Vector3d(1.0, 0.5, 0.0), false);
      m.springs2.push_back({i, dnode, 0, r.log_uniform(10, 1000)});
      drivers.push_back(dnode);
    }
  if (m.dim == 2 || r.chance(0.3)) {
    const int a = r.integer(0, nfree - 1);
    const int b = add_node(m, m.nodes[a].X + Eigen::Vector3d(0, -1.5, 0), false);
    m.trusses.push_back({a, b, r.log_uniform(10, 1000) * 1.5});
  }
  // one gap per node: two closed gaps along y at one node would make their forces indeterminate
  std::vector<int> order(static_cast<std::size_t>(nfree));
  for (int i = 0; i < nfree; ++i) order[i] = i;
  for (int i = nfree - 1; i > 0; --i) std::swap(order[i], order[r.integer(0, i)]);
  std::vector<int> moving;
  for (std::size_t next = 0; next < order.size();) {
    GapDef gd;
    const int a = order[next++];
    const double side = r.chance(0.7) ? -1.0 : 1.0; // support below (closes when a moves down)
    if (next < order.size() && r.chance(0.25)) {
      const int b = order[next++];
      gd.n1 = a;
      gd.n2 = b;
      gd.dir = Eigen::Vector3d(0, side, 0);
      gd.dir_given = true;
    } else {
      const int s = add_node(m, m.nodes[a].X + Eigen::Vector3d(0, side, 0), false);
      moving.push_back(s);
      gd.dir_given = r.chance(0.6);
      if (r.chance(0.5)) { // node 1 = the free node
        gd.n1 = a;
        gd.n2 = s;
        gd.dir = Eigen::Vector3d(0, side, 0);
      } else {
        gd.n1 = s;
        gd.n2 = a;
        gd.dir = Eigen::Vector3d(0, -side, 0);
      }
    }
    gd.d = r.uniform(-0.02, 0.1);
    if (r.chance(0.15)) {
      gd.normal = NormalMethod::Penalty;
      gd.penalty = r.log_uniform(1e3, 1e6);
    }
    gd.mu = r.uniform(0.05, 0.8);
    const double pick = r.uniform(0, 1);
    if (pick < 0.45) {
      gd.friction = FrictionKind::ElasticSlip; // 1e-9 to 1e-1 of the node spacing 2
      gd.elastic_slip = 2.0 * std::pow(10.0, r.uniform(-9, -1));
      if (gd.elastic_slip < 2e-6) m.residual_tolerance = 1e-5;
    } else if (pick < 0.65) {
      gd.friction = FrictionKind::SlipTolerance;
      gd.slip_tolerance = r.log_uniform(1e-4, 0.05);
    } else {
      gd.friction = FrictionKind::Lagrange;
    }
    m.gaps.push_back(gd);
  }
  add_steps(m, r, r.integer(2, 4));
  const bool nlgeom = m.trusses.empty() && r.chance(0.5);
  for (StepDef& st : m.steps) {
    st.nlgeom = nlgeom;
    for (int i = 0; i < nfree; ++i)
      st.load[i] = Eigen::Vector3d(r.uniform(-100, 100), r.uniform(-200, 200), 0);
    for (int dn : drivers)
      if (r.chance(0.7)) st.motion[dn] = Eigen::Vector3d(r.uniform(-0.5, 0.5), 0, 0);
    for (int s : moving)
      if (r.chance(0.5))
        st.motion[s] =
            Eigen::Vector3d(r.uniform(-0.3, 0.3), r.chance(0.3) ? r.uniform(-0.05, 0.05) : 0.0, 0);
  }
  return m;
}

/// GAPCYL/GAPSPHER units: node P on springs inside (d > 0, anisotropic springs) or outside (d < 0,
/// isotropic springs, loads kept on one side of the axis) of a cylinder or sphere about a
/// prescribed centre node C; friction optional (then only convergence and the Coulomb bound are
/// checked).
inline ModelDef radial_model(std::uint64_t seed, bool with_friction) {
  Rng r(seed);
  ModelDef m;
  m.tag = fmt::format("radial seed {}{}", seed, with_friction ? " with friction" : "");
  m.dim = 3;
  const int units = r.integer(1, 6);
  struct Unit {
    int P, C;
    Eigen::Vector3d k, side;
    double d;
    Eigen::Matrix3d Pr;
  };
  std::vector<Unit> us;
  for (int u = 0; u < units; ++u) {
    GapDef gd;
    gd.type = r.chance(0.5) ? ElementType::GAPCYL : ElementType::GAPSPHER;
    const Eigen::Vector3d a = r.direction(3);
    const Eigen::Matrix3d Pr =
        gd.type == ElementType::GAPCYL
            ? Eigen::Matrix3d(Eigen::Matrix3d::Identity() - a * a.transpose())
            : Eigen::Matrix3d::Identity();
    const int C = add_node(m, Eigen::Vector3d(3.0 * u, 0, 0), false);
    Unit un;
    un.C = C;
    un.Pr = Pr;
    if (r.chance(0.6)) {
      gd.d = r.uniform(0.05, 0.5);
      Eigen::Vector3d off = r.uniform(0, 0.8) * gd.d * r.direction(3);
      un.k = Eigen::Vector3d(r.log_uniform(100, 1e4), r.log_uniform(100, 1e4),
                             r.log_uniform(100, 1e4));
      un.P = add_node(m, m.nodes[C].X + off, true);
    } else {
      const double R = r.uniform(0.2, 1.0);
      gd.d = -R;
      Eigen::Vector3d e = Pr * r.direction(3);
      if (e.norm() < 0.3) e = Pr * Eigen::Vector3d(a.unitOrthogonal());
      e.normalize();
      un.side = e;
      const double kk = r.log_uniform(100, 1e4);
      un.k = Eigen::Vector3d(kk, kk, kk);
      un.P = add_node(
          m, m.nodes[C].X + (R + r.uniform(0.05, 0.5)) * e + r.uniform(-0.5, 0.5) * (a - Pr * a),
          true);
    }
    un.d = gd.d;
    gd.n1 = un.P;
    gd.n2 = C;
    gd.dir = a;
    if (with_friction) {
      gd.mu = r.uniform(0.05, 0.6);
      const double pick = r.uniform(0, 1);
      gd.friction = pick < 0.5   ? FrictionKind::ElasticSlip
                    : pick < 0.7 ? FrictionKind::SlipTolerance
                                 : FrictionKind::Lagrange;
      gd.elastic_slip = std::pow(10.0, r.uniform(-7, -2));
      gd.slip_tolerance = r.log_uniform(1e-3, 0.05);
    }
    m.gaps.push_back(gd);
    for (int k = 0; k < 3; ++k) m.springs1.push_back({un.P, k, un.k[k]});
    us.push_back(un);
  }
  add_steps(m, r, r.integer(2, 4));
  const bool nlgeom = r.chance(0.5);
  for (StepDef& st : m.steps) {
    st.nlgeom = nlgeom;
    for (const Unit& un : us) {
      if (r.chance(0.3)) st.motion[un.C] = r.uniform(0, 0.1) * std::abs(un.d) * r.direction(3);
      const Eigen::Vector3d xC = m.nodes[un.C].X + st.motion[un.C];
      const Eigen::Vector3d XP = m.nodes[un.P].X;
      Eigen::Vector3d target;
      if (un.d > 0) {
        target = xC + r.uniform(0, 2.0) * un.d * r.direction(3);
      } else {
        // free position on the same side of the axis: mostly inside the cylinder (contact)
        Eigen::Vector3d t = un.Pr * r.direction(3);
        t -= t.dot(un.side) * un.side;
        const double rho = r.uniform(0.2, 1.5) * (-un.d);
        target =
            xC + rho * un.side + 0.3 * rho * (t.norm() > 0 ? t.normalized() : t) +
            r.uniform(-0.3, 0.3) * (Eigen::Matrix3d::Identity() - un.Pr) * Eigen::Vector3d::Ones();
      }
      st.load[un.P] = un.k.cwiseProduct(target - XP);
    }
  }
  return m;
}

} // namespace gapfem::test::random_contact
