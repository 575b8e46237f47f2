#pragma once
// Small random gap models for the differential test against an independent oracle
// (random_contact_test.cpp): nodes on springs and trusses, GAPUNI/GAPCYL/GAPSPHER gaps with
// random clearances, directions, normal methods and friction, 2-4 steps of loads and support
// motions. This file describes a model and writes it as an Abaqus deck; contact_oracle.hpp solves
// the same description without gapfem.
#include "model/element_types.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>
#include <string>
#include <vector>

namespace gapfem::test::random_contact {

enum class NormalMethod { Direct, Penalty, Augmented };
enum class FrictionKind { None, ElasticSlip, SlipTolerance, Lagrange };

struct NodeDef {
  Eigen::Vector3d X = Eigen::Vector3d::Zero();
  bool free = true; ///< false: a support whose displacement is prescribed (0 or a motion)
};
struct Spring1Def {
  int node = 0, dof = 0; ///< 0-based node index and DOF (0 = x)
  double k = 0.0;
};
struct Spring2Def {
  int a = 0, b = 0, dof = 0; ///< the same DOF at both nodes
  double k = 0.0;
};
struct TrussDef {
  int a = 0, b = 0;
  double EA = 0.0; ///< axial stiffness EA (area 1, modulus EA), small-displacement
};
struct GapDef {
  ElementType type = ElementType::GAPUNI;
  int n1 = 0, n2 = 0;
  double d = 0.0;
  Eigen::Vector3d dir = Eigen::Vector3d::Zero(); ///< GAPUNI normal or GAPCYL axis
  bool dir_given = true;                         ///< GAPUNI: false = computed from coordinates
  NormalMethod normal = NormalMethod::Direct;
  double penalty = 0.0; ///< PENALTY stiffness
  FrictionKind friction = FrictionKind::None;
  double mu = 0.0;
  double elastic_slip = 0.0;   ///< ELASTIC SLIP= (absolute)
  double slip_tolerance = 0.0; ///< SLIP TOLERANCE= (fraction of the characteristic length)
};
struct StepDef {
  std::vector<Eigen::Vector3d> load;   ///< per node: CLOAD at the end of the step (free nodes)
  std::vector<Eigen::Vector3d> motion; ///< per node: displacement at the end of the step (supports)
  bool nlgeom = false;
  double initial_increment = 1.0;
};
struct ModelDef {
  int dim = 3;        ///< 2: planar model (needs a truss, written as T2D2)
  bool fix_z = false; ///< 3-D model whose free nodes have z fixed
  std::vector<NodeDef> nodes;
  std::vector<Spring1Def> springs1;
  std::vector<Spring2Def> springs2;
  std::vector<TrussDef> trusses;
  std::vector<GapDef> gaps;
  std::vector<StepDef> steps;
  bool tight_controls =
      true; ///< *CONTROLS, PARAMETERS=FIELD with R_n, C_n = 1e-6 (comparison to 1e-6)
  /// R_n of the tight controls: 1e-6, or 1e-5 where an elastic slip below 1e-6 of the node spacing
  /// makes a stick stiffness whose force round-off (eps k_s |u|) is about 1e-6 of the loads
  double residual_tolerance = 1e-6;
  std::string tag; ///< class and seed, for messages

  int active_dofs() const { return dim == 2 || fix_z ? 2 : 3; }
  /// Label of gap i in the deck.
  static int gap_label(std::size_t i) { return 1001 + static_cast<int>(i); }
};

inline std::string gap_type_name(ElementType t) {
  return t == ElementType::GAPCYL ? "GAPCYL" : t == ElementType::GAPSPHER ? "GAPSPHER" : "GAPUNI";
}

/// The Abaqus deck of a model (labels: node i+1, springs 1.., trusses 501.., gaps 1001..).
inline std::string write_deck(const ModelDef& m) {
  std::string d = fmt::format("*HEADING\nrandom gap model {}\n*NODE\n", m.tag);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const auto& X = m.nodes[i].X;
    d += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", i + 1, X[0], X[1], X[2]);
  }
  int label = 1;
  for (std::size_t i = 0; i < m.springs1.size(); ++i, ++label) {
    const Spring1Def& s = m.springs1[i];
    d += fmt::format("*ELEMENT, TYPE=SPRING1, ELSET=SA{0}\n{1}, {2}\n*SPRING, ELSET=SA{0}\n{3}\n"
                     "{4:.17g}\n",
                     i, label, s.node + 1, s.dof + 1, s.k);
  }
  for (std::size_t i = 0; i < m.springs2.size(); ++i, ++label) {
    const Spring2Def& s = m.springs2[i];
    d += fmt::format("*ELEMENT, TYPE=SPRING2, ELSET=SB{0}\n{1}, {2}, {3}\n*SPRING, ELSET=SB{0}\n"
                     "{4}, {4}\n{5:.17g}\n",
                     i, label, s.a + 1, s.b + 1, s.dof + 1, s.k);
  }
  for (std::size_t i = 0; i < m.trusses.size(); ++i) {
    const TrussDef& t = m.trusses[i];
    d += fmt::format("*ELEMENT, TYPE={0}, ELSET=T{1}\n{2}, {3}, {4}\n*SOLID SECTION, ELSET=T{1}, "
                     "MATERIAL=MT{1}\n1.\n*MATERIAL, NAME=MT{1}\n*ELASTIC\n{5:.17g}, 0.3\n",
                     m.dim == 2 ? "T2D2" : "T3D2", i, 501 + i, t.a + 1, t.b + 1, t.EA);
  }
  for (std::size_t i = 0; i < m.gaps.size(); ++i) {
    const GapDef& g = m.gaps[i];
    d += fmt::format("*ELEMENT, TYPE={}, ELSET=G{}\n{}, {}, {}\n*GAP, ELSET=G{}\n",
                     gap_type_name(g.type), i, ModelDef::gap_label(i), g.n1 + 1, g.n2 + 1, i);
    if (g.type == ElementType::GAPSPHER || !g.dir_given)
      d += fmt::format("{:.17g}, , , , 1.\n", g.d);
    else
      d += fmt::format("{:.17g}, {:.17g}, {:.17g}, {:.17g}, 1.\n", g.d, g.dir[0], g.dir[1],
                       g.dir[2]);
    if (g.normal == NormalMethod::Penalty)
      d += fmt::format("*SURFACE BEHAVIOR, PENALTY\n{:.17g}\n", g.penalty);
    else if (g.normal == NormalMethod::Augmented)
      d += "*SURFACE BEHAVIOR, AUGMENTED LAGRANGE\n";
    switch (g.friction) {
    case FrictionKind::None:
      break;
    case FrictionKind::ElasticSlip:
      d += fmt::format("*FRICTION, ELASTIC SLIP={:.17g}\n{:.17g}\n", g.elastic_slip, g.mu);
      break;
    case FrictionKind::SlipTolerance:
      d += fmt::format("*FRICTION, SLIP TOLERANCE={:.17g}\n{:.17g}\n", g.slip_tolerance, g.mu);
      break;
    case FrictionKind::Lagrange:
      d += fmt::format("*FRICTION, LAGRANGE\n{:.17g}\n", g.mu);
      break;
    }
  }
  d += "*ELSET, ELSET=GAPS\n";
  for (std::size_t i = 0; i < m.gaps.size(); ++i) d += fmt::format("G{}\n", i);
  const int nd = m.dim == 2 ? 2 : 3;
  d += "*BOUNDARY\n";
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (!m.nodes[i].free)
      d += fmt::format("{}, 1, {}\n", i + 1, nd);
    else if (m.fix_z)
      d += fmt::format("{}, 3, 3\n", i + 1);
  }
  const int na = m.active_dofs();
  for (const StepDef& st : m.steps) {
    d += fmt::format("*STEP{}, INC=1000\n*STATIC\n{:.17g}, 1.\n", st.nlgeom ? ", NLGEOM" : "",
                     st.initial_increment);
    if (m.tight_controls)
      d += fmt::format("*CONTROLS, PARAMETERS=FIELD\n{}, 1e-6, , , , , , 1e-9\n",
                       m.residual_tolerance);
    d += "*CLOAD\n";
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (m.nodes[i].free)
        for (int k = 0; k < na; ++k)
          d += fmt::format("{}, {}, {:.17g}\n", i + 1, k + 1, st.load[i][k]);
    // every support's displacement at the end of every step (a support left out would keep the
    // value of the previous step)
    d += "*BOUNDARY\n";
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (!m.nodes[i].free)
        for (int k = 0; k < nd; ++k)
          d += fmt::format("{0}, {1}, {1}, {2:.17g}\n", i + 1, k + 1, st.motion[i][k]);
    d += "*NODE PRINT, FREQUENCY=1\nU\n*EL PRINT, ELSET=GAPS, FREQUENCY=1\nS, E\n*END STEP\n";
  }
  return d;
}

} // namespace gapfem::test::random_contact
