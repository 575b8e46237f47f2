// Randomized differential test of the contact solve (issue 11): well over a thousand generated
// gap models — GAPUNI networks on springs and trusses (3-D and planar, DIRECT, PENALTY and
// AUGMENTED LAGRANGE), GAPCYL/GAPSPHER units, and friction with one tangential direction (elastic
// slip from 1e-9 to 1e-1, SLIP TOLERANCE, LAGRANGE) over 2-4 steps that close, slide, reverse and
// open — solved by gapfem and by the oracle of contact_oracle.hpp / radial_oracle.hpp. Every model
// must converge; displacements, gap forces, slips and friction forces must agree to 1e-6 of their
// scales at every converged increment. The distribution of Newton iterations per increment and of
// cut-backs per model is printed.
#include "contact_oracle.hpp"
#include "radial_oracle.hpp"
#include "random_generators.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>
#include <map>

using namespace gapfem;
using namespace gapfem::test;
using namespace gapfem::test::random_contact;

namespace {

/// Iterations per converged increment and cut-backs per model, over one test.
struct Statistics {
  std::map<int, long> iterations; ///< iterations -> increments
  std::map<int, long> cutbacks;   ///< cut-backs -> models
  long models = 0, increments = 0, skipped = 0;
  std::vector<std::string> with_cutbacks; ///< models that needed cut-backs (tag: count)
  void add(const JobResult& r, const std::string& tag) {
    ++models;
    int cut = 0;
    for (const IncrementInfo& i : r.increments) {
      if (i.converged) {
        ++iterations[i.iterations];
        ++increments;
      } else {
        ++cut;
      }
    }
    ++cutbacks[cut];
    if (cut > 0) with_cutbacks.push_back(fmt::format("{} ({})", tag, cut));
  }
  void print(const char* what) const {
    std::string it, cb;
    for (auto [k, v] : iterations) it += fmt::format(" {}:{}", k, v);
    for (auto [k, v] : cutbacks) cb += fmt::format(" {}:{}", k, v);
    std::printf("[ random ] %s: %ld models (%ld skipped as degenerate), %ld increments\n"
                "[ random ]   iterations per increment (iterations:increments)%s\n"
                "[ random ]   cut-backs per model (cut-backs:models)%s\n",
                what, models, skipped, increments, it.c_str(), cb.c_str());
    for (const auto& w : with_cutbacks) std::printf("[ random ]   cut back: %s\n", w.c_str());
  }
};

double max_load(const ModelDef& m) {
  double f = 1.0;
  for (const StepDef& s : m.steps)
    for (const auto& v : s.load) f = std::max(f, v.cwiseAbs().maxCoeff());
  return f;
}

JobResult run(const ModelDef& m) {
  return run_deck(write_deck(m));
}

/// Keeps the deck of a failing model next to the test's files (the path goes in the message).
std::string keep(const ModelDef& m) {
  std::string name = m.tag;
  for (char& c : name)
    if (c == ' ') c = '_';
  const auto path = write_deck(write_deck(m), name);
  return "deck: " + path.string();
}

/// Runs a linear-oracle model and compares every converged increment. Returns false when the
/// oracle found the model degenerate (not compared).
bool check_linear(const ModelDef& m, Statistics& stats, double loose = 0.0) {
  const JobResult r = run(m);
  EXPECT_EQ(r.exit_code, 0) << m.tag << ": " << r.error << "; " << keep(m);
  if (r.exit_code != 0) return true;
  stats.add(r, m.tag);
  if (r.increments.size() != r.frames.size()) keep(m); // cut back: keep the deck to look at
  LinearOracle oracle(m);
  const double F = max_load(m);
  std::vector<std::pair<const Frame*, OracleState>> compared;
  for (const Frame& f : r.frames) {
    if (!oracle.advance(f.step - 1, f.step_time)) {
      ++stats.skipped;
      return false;
    }
    compared.emplace_back(&f, oracle.state());
  }
  double uscale = 1e-3;
  for (const auto& [f, s] : compared) uscale = std::max(uscale, s.u.cwiseAbs().maxCoeff());
  double kmin = std::numeric_limits<double>::infinity();
  for (const auto& sp : m.springs1) kmin = std::min(kmin, sp.k);
  int failures = 0;
  for (const auto& [f, s] : compared) {
    // `loose`: the clearance tolerance of augmented Lagrange, carried to the answer exactly
    // + the round-off of a stiff elastic-slip stick (its force k_s e is known to ~ eps k_s |u|)
    const double roundoff = 10 * std::numeric_limits<double>::epsilon() * s.stiffest_stick * uscale;
    // + what the deck's own residual tolerance R_n (1e-6, or 1e-5 where round-off needs it)
    // allows: an increment that starts from the extrapolated guess may converge in one
    // iteration, at R_n times Newton's flux (the step's time-averaged element forces, up to a few
    // times the applied loads F in these spring networks: 2.8 F on friction seed 2160), rather
    // than at the round-off a second (quadratic) iteration would reach
    const double rn = 10.0 * std::max(1e-6, m.residual_tolerance);
    const double tol_u = rn * uscale + 1.01 * loose * s.clearance_to_u + roundoff / kmin;
    const double tol_f = rn * F + 1.01 * loose * s.clearance_to_force + roundoff;
    const std::string where = fmt::format("{}: step {} increment {} (time {})", m.tag, f->step,
                                          f->increment, f->step_time);
    for (std::size_t i = 0; i < m.nodes.size() && failures < 5; ++i) {
      if (!m.nodes[i].free) continue;
      const Vec3& u = U(r, *f, static_cast<Label>(i + 1));
      for (int k = 0; k < m.active_dofs(); ++k)
        if (std::abs(u[k] - s.u[3 * i + k]) > tol_u) {
          ADD_FAILURE() << where << ": node " << i + 1 << " u" << k + 1 << " = " << u[k]
                        << ", oracle " << s.u[3 * i + k] << "; " << keep(m);
          ++failures;
        }
    }
    for (std::size_t i = 0; i < m.gaps.size() && failures < 5; ++i) {
      const GapRecord& g = gap(r, *f, ModelDef::gap_label(i));
      const OracleGap& o = s.gaps[i];
      bool bad = std::abs(g.normal_force - o.normal_force) > tol_f;
      if (m.gaps[i].friction != FrictionKind::None) {
        bad |= std::abs(g.friction_force[0] - o.friction) > tol_f;
        bad |= std::abs(g.slip[0] - o.slip) > tol_u;
        if (!o.degenerate && o.closed) bad |= (g.status == ContactStatus::Slip) != (o.mode != 0);
      }
      const bool near_switch = std::abs(o.clearance) <= loose || o.normal_force <= tol_f;
      if (!o.degenerate && !(loose > 0 && near_switch))
        bad |= (g.status != ContactStatus::Open) != o.closed;
      if (loose > 0) bad |= g.status != ContactStatus::Open && -g.clearance > 1.01 * loose;
      if (bad) {
        ADD_FAILURE() << where << ": gap " << ModelDef::gap_label(i) << " status "
                      << contact_status_name(g.status) << " force " << g.normal_force
                      << " friction " << g.friction_force[0] << " slip " << g.slip[0] << "; oracle "
                      << (o.closed ? (o.mode ? "slip" : "closed/stick") : "open") << " force "
                      << o.normal_force << " friction " << o.friction << " slip " << o.slip
                      << " (tolerances: force " << tol_f << ", length " << tol_u << ")"
                      << "; " << keep(m);
        ++failures;
      }
    }
  }
  return true;
}

} // namespace

TEST(RandomContact, FrictionlessGapuniNetworksMatchTheExactContactSet) {
  Statistics stats;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    check_linear(network_model(seed, NormalMethod::Direct), stats);
    if (HasFailure()) break;
  }
  stats.print("frictionless GAPUNI networks (DIRECT, PENALTY)");
}

TEST(RandomContact, AugmentedLagrangeNetworksAgreeWithHardContactToTheirTolerance) {
  // AUGMENTED LAGRANGE stops augmenting once every closed gap is within 1e-3 of its
  // characteristic length: the answer is that of hard contact to that tolerance
  Statistics stats;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed) {
    const ModelDef m = network_model(seed, NormalMethod::Augmented);
    double lc = 0.0;
    LinearOracle o(m);
    for (std::size_t i = 0; i < m.gaps.size(); ++i) lc = std::max(lc, o.characteristic_length(i));
    check_linear(m, stats, 1e-3 * lc);
    if (HasFailure()) break;
  }
  stats.print("GAPUNI networks (AUGMENTED LAGRANGE)");
}

TEST(RandomContact, FrictionWithOneSlipDirectionMatchesTheExactStickSlipSolution) {
  Statistics stats;
  for (std::uint64_t seed = 2001; seed <= 2500; ++seed) {
    check_linear(friction_model(seed), stats);
    if (HasFailure()) break;
  }
  stats.print("friction, one slip direction");
}

namespace {

void check_radial(const ModelDef& m, Statistics& stats) {
  const JobResult r = run(m);
  EXPECT_EQ(r.exit_code, 0) << m.tag << ": " << r.error << "; " << keep(m);
  if (r.exit_code != 0) return;
  stats.add(r, m.tag);
  if (r.increments.size() != r.frames.size()) keep(m); // cut back: keep the deck to look at
  const bool friction = m.gaps.front().friction != FrictionKind::None;
  for (const Frame& f : r.frames) {
    const std::string where = fmt::format("{}: step {} increment {}", m.tag, f.step, f.increment);
    const StepDef& st = m.steps[f.step - 1];
    const StepDef* prev = f.step > 1 ? &m.steps[f.step - 2] : nullptr;
    for (std::size_t i = 0; i < m.gaps.size(); ++i) {
      const GapDef& g = m.gaps[i];
      const GapRecord& rec = gap(r, f, ModelDef::gap_label(i));
      if (friction) { // Coulomb bound and no penetration beyond round-off
        const double t = std::hypot(rec.friction_force[0], rec.friction_force[1]);
        EXPECT_LE(t, g.mu * rec.normal_force * (1 + 1e-6) + 1e-9) << where;
        EXPECT_GE(rec.clearance, -1e-8) << where;
        continue;
      }
      Eigen::Vector3d k;
      for (const auto& s : m.springs1)
        if (s.node == g.n1) k[s.dof] = s.k;
      const Eigen::Vector3d F0 = prev ? prev->load[g.n1] : Eigen::Vector3d::Zero();
      const Eigen::Vector3d M0 = prev ? prev->motion[g.n2] : Eigen::Vector3d::Zero();
      const Eigen::Vector3d F = F0 + f.step_time * (st.load[g.n1] - F0);
      const Eigen::Vector3d xC = m.nodes[g.n2].X + M0 + f.step_time * (st.motion[g.n2] - M0);
      const Eigen::Vector3d a = g.dir.normalized();
      const Eigen::Matrix3d P =
          g.type == ElementType::GAPCYL
              ? Eigen::Matrix3d(Eigen::Matrix3d::Identity() - a * a.transpose())
              : Eigen::Matrix3d::Identity();
      const RadialAnswer o = solve_radial(k, m.nodes[g.n1].X, F, xC, g.d, P);
      const Vec3& u = U(r, f, g.n1 + 1);
      const Eigen::Vector3d x = m.nodes[g.n1].X + Eigen::Vector3d(u[0], u[1], u[2]);
      const double scale = std::abs(g.d);
      EXPECT_LE((x - o.x).norm(), 1e-6 * scale)
          << where << ": gap " << ModelDef::gap_label(i) << "; " << keep(m);
      EXPECT_NEAR(rec.normal_force, o.force, 1e-6 * std::max(1.0, F.norm())) << where;
      if (::testing::Test::HasFailure()) return;
    }
  }
}

} // namespace

TEST(RandomContact, RadialGapsMatchTheConstrainedMinimum) {
  Statistics stats;
  for (std::uint64_t seed = 3001; seed <= 3250; ++seed) {
    check_radial(radial_model(seed, false), stats);
    if (HasFailure()) break;
  }
  stats.print("GAPCYL/GAPSPHER, frictionless");
}

TEST(RandomContact, RadialGapsWithFrictionConvergeWithinTheCoulombCone) {
  Statistics stats;
  for (std::uint64_t seed = 4001; seed <= 4150; ++seed) {
    check_radial(radial_model(seed, true), stats);
    if (HasFailure()) break;
  }
  stats.print("GAPCYL/GAPSPHER with friction");
}
