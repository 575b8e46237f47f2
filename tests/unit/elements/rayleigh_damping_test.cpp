// Material Rayleigh damping (*DAMPING in a *MATERIAL, issue 46): the decorator's damping block is
// C_e = alpha M_e + beta K_e of the kernel it wraps, at the trial state, also in a residual-only
// evaluation (no tangent, no mass asked for); the wrapped kernel's residual, tangent and mass are
// those of the kernel alone to the bit; has_damping says what the material gives; kernels of a
// material without *DAMPING are not wrapped.
#include "elements/rayleigh_damping.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <gtest/gtest.h>
#include <string>

namespace gapfem {
namespace {

using test::KernelProbe;

constexpr double kAlpha = 3.5, kBeta = 2.0e-4;

std::shared_ptr<const Model> model_of(const std::string& text) {
  return std::make_shared<const Model>(read_deck_string(text, "rayleigh.inp"));
}

std::string material(const std::string& damping, bool density = true) {
  std::string s = "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n";
  if (density) s += "*DENSITY\n7.8e-9\n";
  return s + damping;
}

std::string brick(const std::string& damping, bool density = true) {
  return "*NODE\n1, 0., 0., 0.\n2, 2., 0., 0.\n3, 2., 3., 0.\n4, 0., 3., 0.\n"
         "5, 0., 0., 1.\n6, 2., 0., 1.\n7, 2., 3., 1.\n8, 0., 3., 1.\n"
         "*ELEMENT, TYPE=C3D8, ELSET=E\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
         "*SOLID SECTION, ELSET=E, MATERIAL=M\n" +
         material(damping, density);
}

std::string beam(const std::string& damping) {
  return "*NODE\n1, 0., 0., 0.\n2, 3., 4., 0.\n*ELEMENT, TYPE=B31, ELSET=E\n1, 1, 2\n"
         "*BEAM SECTION, ELSET=E, MATERIAL=M, SECTION=RECT\n0.2, 0.3\n0., 0., 1.\n" +
         material(damping);
}

const std::string kDamping = "*DAMPING, ALPHA=3.5, BETA=2.0e-4\n";

/// Every block of one evaluation: residual, tangent, mass and damping as asked.
struct Blocks {
  std::vector<double> r, K, M, C;
};

Blocks evaluate(const ElementKernel& k, KernelProbe& p, bool tangent, bool mass, bool damping) {
  const auto n = static_cast<std::size_t>(p.n());
  Blocks b;
  b.r.assign(n, 0.0);
  b.K.assign(tangent ? n * n : 0, 0.0);
  b.M.assign(mass ? n * n : 0, 0.0);
  b.C.assign(damping ? n * n : 0, 0.0);
  ElementOutput out;
  out.residual = b.r;
  out.tangent = b.K;
  out.want_tangent = tangent;
  out.mass = b.M;
  out.want_mass = mass;
  out.damping = b.C;
  out.want_damping = damping;
  k.evaluate(p.input(), out);
  // the caller's request is left as it was
  EXPECT_EQ(out.want_tangent, tangent);
  EXPECT_EQ(out.want_mass, mass);
  EXPECT_EQ(out.want_damping, damping);
  EXPECT_EQ(out.tangent.data(), b.K.data());
  EXPECT_EQ(out.mass.data(), b.M.data());
  return b;
}

/// A deformed state (NLGEOM, so K depends on u) and the checks: C = alpha M + beta K to 1e-14 of
/// the largest entry (both sides are the same products of the same numbers: only the sum's
/// rounding differs), with and without the tangent and mass asked for; r, K and M of the wrapped
/// kernel equal the inner kernel's to the bit.
void expect_rayleigh(KernelProbe& p) {
  const auto* wrapped = dynamic_cast<const RayleighDampingKernel*>(p.kernel.get());
  ASSERT_NE(wrapped, nullptr);
  EXPECT_EQ(wrapped->alpha(), kAlpha);
  EXPECT_EQ(wrapped->beta(), kBeta);
  ASSERT_TRUE(p.kernel->has_damping());
  EXPECT_FALSE(p.kernel->damping_in_residual());
  p.ctx.nlgeom = true;
  const auto n = static_cast<std::size_t>(p.n());
  for (std::size_t i = 0; i < n; ++i) p.u[i] = 1e-3 * static_cast<double>((i * 7) % 5) - 2e-3;
  const ElementKernel& inner = wrapped->inner();
  const Blocks ref = evaluate(inner, p, true, true, false);
  const Blocks all = evaluate(*p.kernel, p, true, true, true);
  const Blocks residual_only = evaluate(*p.kernel, p, false, false, true);
  double scale = 0.0;
  for (std::size_t k = 0; k < n * n; ++k)
    scale = std::max(scale, std::abs(kAlpha * ref.M[k]) + std::abs(kBeta * ref.K[k]));
  ASSERT_GT(scale, 0.0);
  for (std::size_t k = 0; k < n * n; ++k) {
    const double expected = kAlpha * ref.M[k] + kBeta * ref.K[k];
    EXPECT_NEAR(all.C[k], expected, 1e-14 * scale) << "entry " << k;
    EXPECT_NEAR(residual_only.C[k], expected, 1e-14 * scale) << "residual-only, entry " << k;
    EXPECT_EQ(all.K[k], ref.K[k]);
    EXPECT_EQ(all.M[k], ref.M[k]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(all.r[i], ref.r[i]);
    EXPECT_EQ(residual_only.r[i], ref.r[i]);
  }
  // both Rayleigh parts are in C (neither factor silently dropped)
  double mass_part = 0.0, stiffness_part = 0.0;
  for (std::size_t k = 0; k < n * n; ++k) {
    mass_part = std::max(mass_part, std::abs(kAlpha * ref.M[k]));
    stiffness_part = std::max(stiffness_part, std::abs(kBeta * ref.K[k]));
  }
  EXPECT_GT(mass_part, 0.0);
  EXPECT_GT(stiffness_part, 0.0);
}

TEST(RayleighDamping, BrickDampingIsAlphaMPlusBetaK) {
  auto p = KernelProbe::of(model_of(brick(kDamping)));
  expect_rayleigh(p);
}

TEST(RayleighDamping, BeamDampingIsAlphaMPlusBetaK) {
  auto p = KernelProbe::of(model_of(beam(kDamping)));
  expect_rayleigh(p);
}

// The decorator changes neither residual nor tangent: the harness's central differences of the
// residual still give the wrapped kernel's tangent (C's beta part is beta times that tangent).
TEST(RayleighDamping, WrappedTangentPassesTheDifferenceCheck) {
  for (const std::string& deck : {brick(kDamping), beam(kDamping)}) {
    auto p = KernelProbe::of(model_of(deck));
    p.ctx.nlgeom = true;
    for (std::size_t i = 0; i < p.u.size(); ++i)
      p.u[i] = 1e-3 * static_cast<double>((i * 3) % 7) - 3e-3;
    test::expect_fd_tangent(p);
    test::expect_revert_is_exact(p);
  }
}

TEST(RayleighDamping, HasDampingReportsWhatTheMaterialGives) {
  // no *DAMPING, or both factors zero: not wrapped at all (results unchanged to the bit)
  for (const std::string& d : {std::string(), std::string("*DAMPING, ALPHA=0., BETA=0.\n"),
                               std::string("*DAMPING, STRUCTURAL=0.02\n")}) {
    auto p = KernelProbe::of(model_of(brick(d)));
    EXPECT_EQ(dynamic_cast<const RayleighDampingKernel*>(p.kernel.get()), nullptr) << d;
    EXPECT_FALSE(p.kernel->has_damping()) << d;
  }
  auto alpha = KernelProbe::of(model_of(brick("*DAMPING, ALPHA=2.\n")));
  EXPECT_TRUE(alpha.kernel->has_damping());
  auto beta = KernelProbe::of(model_of(brick("*DAMPING, BETA=1e-3\n")));
  EXPECT_TRUE(beta.kernel->has_damping());
  // alpha M of an element without density is zero: a zero damping block
  auto massless = KernelProbe::of(model_of(brick("*DAMPING, ALPHA=2.\n", false)));
  EXPECT_NE(dynamic_cast<const RayleighDampingKernel*>(massless.kernel.get()), nullptr);
  for (double c : evaluate(*massless.kernel, massless, false, false, true).C) EXPECT_EQ(c, 0.0);
  // two *DAMPING options giving one factor each combine
  auto split = KernelProbe::of(model_of(brick("*DAMPING, ALPHA=3.5\n*DAMPING, BETA=2.0e-4\n")));
  const auto* k = dynamic_cast<const RayleighDampingKernel*>(split.kernel.get());
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->alpha(), kAlpha);
  EXPECT_EQ(k->beta(), kBeta);
}

} // namespace
} // namespace gapfem
