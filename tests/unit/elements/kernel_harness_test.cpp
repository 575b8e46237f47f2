// The kernel harness checks itself: a correct toy kernel (a two-node bar, small strain or NLGEOM,
// with history and an exact constraint row) passes every check, and each check fails, with one
// message naming what is wrong, for the defect it exists to find: a tangent entry off by 1e-6,
// a wrong row coefficient, a hidden cache that survives a revert, a grounded term, a force that
// does not turn with the body, a difference that crosses a status switch.
#include "kernel_harness.hpp"

#include <gtest/gtest-spi.h>

namespace gapfem::test {
namespace {

enum class Defect { None, TangentEntry, RowCoefficient, HiddenCache, Grounded, FixedAxis };

/// A bar between two nodes with stiffness k (NLGEOM: along the current axis, force k (l - L)),
/// history = the accumulated force, and optionally an exact row g = n0 . (u2 - u1) - gap that is
/// active only while g <= 0 (a gap closing along the bar).
class ToyBar final : public ElementKernel {
 public:
  ToyBar(Defect defect, bool with_row) : _defect(defect), _with_row(with_row) {}
  ElementType type() const override { return ElementType::SPRINGA; }
  std::span<const DofType> node_dofs(int) const override { return kDofs; }
  int n_state() const override { return 1; }
  int n_multipliers() const override { return _with_row ? 1 : 0; }
  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    Eigen::Vector3d X1(in.X[0][0], in.X[0][1], in.X[0][2]), X2(in.X[1][0], in.X[1][1], in.X[1][2]);
    const Eigen::Vector3d u1(in.u[0], in.u[1], in.u[2]), u2(in.u[3], in.u[4], in.u[5]);
    const double L = (X2 - X1).norm();
    const Eigen::Vector3d n0 = (X2 - X1) / L;
    const Eigen::Vector3d d = X2 + u2 - X1 - u1;
    const double l = d.norm();
    const bool nl = in.ctx->nlgeom;
    const Eigen::Vector3d e = nl ? Eigen::Vector3d(d / l) : n0;
    const double N = nl ? kK * (l - L) : kK * n0.dot(u2 - u1);
    const Eigen::Vector3d dir = _defect == Defect::FixedAxis ? n0 : e;
    // the block A: d(N dir) / d u2
    Eigen::Matrix3d A = kK * dir * e.transpose();
    if (nl && _defect != Defect::FixedAxis)
      A += N / l * (Eigen::Matrix3d::Identity() - e * e.transpose());
    for (int i = 0; i < 3; ++i) {
      out.residual[i] -= N * dir[i];
      out.residual[3 + i] += N * dir[i];
    }
    if (_defect == Defect::Grounded)
      for (int i = 0; i < 6; ++i) out.residual[i] += 0.1 * kK * in.u[i];
    if (_defect == Defect::HiddenCache) {
      out.residual[0] += 1e-3 * _cache;
      _cache = in.u[0];
    }
    in.state[0] = in.state_start[0] + N;
    if (out.want_tangent) {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          out.tangent[i * 6 + j] += A(i, j);
          out.tangent[(3 + i) * 6 + 3 + j] += A(i, j);
          out.tangent[i * 6 + 3 + j] -= A(i, j);
          out.tangent[(3 + i) * 6 + j] -= A(i, j);
        }
      if (_defect == Defect::Grounded)
        for (int i = 0; i < 6; ++i) out.tangent[i * 6 + i] += 0.1 * kK;
      if (_defect == Defect::TangentEntry) out.tangent[1 * 6 + 4] *= 1.0 + 1e-6;
      out.unsymmetric = _defect == Defect::FixedAxis;
    }
    if (_with_row) {
      const double g = n0.dot(u2 - u1) - kGap;
      if (g > 0.0) return;
      std::array<double, 6> c{};
      for (int i = 0; i < 3; ++i) {
        c[i] = -n0[i];
        c[3 + i] = n0[i] * (_defect == Defect::RowCoefficient ? 1.001 : 1.0);
      }
      for (int i = 0; i < 6; ++i) out.residual[i] += in.multipliers[0] * c[i];
      out.add_constraint(0, g, c);
    }
  }

  static constexpr double kK = 1000.0, kGap = 0.05;

 private:
  static constexpr DofType kDofs[3] = {DofType::U1, DofType::U2, DofType::U3};
  Defect _defect;
  bool _with_row;
  mutable double _cache = 0.0; // only the HiddenCache defect reads it
};

KernelProbe toy(Defect defect, bool nlgeom, bool with_row = false) {
  KernelProbe p(std::make_shared<ToyBar>(defect, with_row), {{0.1, 0.2, -0.1}, {1.0, 0.6, 0.3}});
  p.ctx.nlgeom = nlgeom;
  for (std::size_t j = 0; j < p.u.size(); ++j) p.u[j] = 0.02 * std::sin(1.0 + 2.0 * j);
  p.state0 = {5.0};
  p.state = p.state0;
  return p;
}

TEST(KernelHarness, ACorrectKernelPassesEveryCheck) {
  for (bool nl : {false, true}) {
    SCOPED_TRACE(nl ? "NLGEOM" : "small strain");
    KernelProbe p = toy(Defect::None, nl);
    const FdReport fd = expect_fd_tangent(p);
    EXPECT_EQ(fd.failures, 0);
    EXPECT_LT(fd.worst, 1.0);
    expect_revert_is_exact(p);
    expect_rigid_body_invariance(p);
    // a closed row: its coefficients and d r / d lambda by differences too
    KernelProbe q = toy(Defect::None, nl, true);
    q.u[3] -= 0.1; // g < 0: the row is active
    q.mult = {40.0};
    ASSERT_EQ(q.evaluate().n_constraints, 1);
    expect_fd_tangent(q);
    expect_revert_is_exact(q);
  }
}

TEST(KernelHarness, FiniteDifferencesFindATangentEntryOffByOnePartInAMillion) {
  for (bool nl : {false, true}) {
    KernelProbe p = toy(Defect::TangentEntry, nl);
    EXPECT_NONFATAL_FAILURE(expect_fd_tangent(p), "K(1,4)");
  }
}

TEST(KernelHarness, FiniteDifferencesFindAWrongRowCoefficient) {
  KernelProbe p = toy(Defect::RowCoefficient, true, true);
  p.u[3] -= 0.1;
  p.mult = {40.0};
  EXPECT_NONFATAL_FAILURE(expect_fd_tangent(p), "dg/du");
}

TEST(KernelHarness, FiniteDifferencesRefuseToCrossAStatusSwitch) {
  KernelProbe p = toy(Defect::None, false, true);
  // the row switches on where n0 . (u2 - u1) = gap: put the state right there
  const Eigen::Vector3d n0 = Eigen::Vector3d(0.9, 0.4, 0.4).normalized();
  for (int i = 0; i < 3; ++i) p.u[3 + i] = p.u[i] + n0[i] * ToyBar::kGap;
  EXPECT_NONFATAL_FAILURE(expect_fd_tangent(p), "changes the element's status");
}

TEST(KernelHarness, RevertFindsAHiddenCache) {
  KernelProbe p = toy(Defect::HiddenCache, false);
  EXPECT_NONFATAL_FAILURE(expect_revert_is_exact(p), "residual[0]");
}

TEST(KernelHarness, RigidBodyCheckFindsAGroundedTerm) {
  KernelProbe p = toy(Defect::Grounded, false);
  EXPECT_NONFATAL_FAILURE(expect_rigid_body_invariance(p), "after the translation");
}

TEST(KernelHarness, RigidBodyCheckFindsAForceThatDoesNotTurnWithTheBody) {
  KernelProbe p = toy(Defect::FixedAxis, true);
  expect_fd_tangent(p); // its tangent is consistent: only the rotation finds it
  EXPECT_NONFATAL_FAILURE(expect_rigid_body_invariance(p), "after the finite rotation");
}

} // namespace
} // namespace gapfem::test
