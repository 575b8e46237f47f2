// The toy solid law of the seam tests (counting_law.hpp).
#include "unit/elements/counting_law.hpp"

#include "elements/material/isotropic_elastic.hpp"

#include <algorithm>

namespace gapfem::test {

std::atomic<int> g_most_commits_seen{0};

namespace {

/// Linear elasticity (the built-in law's stress) with one history slot per point counting the
/// increments the point has been committed in; its tangent is given as a full Voigt matrix.
class CountingElasticLaw final : public SolidLaw {
 public:
  CountingElasticLaw(const Material& m, Kinematics k) : _elastic(m, k), _kin(k) {}

  int n_state() const override { return 1; }
  void initialize(std::span<double> state) const override { state[0] = 0.0; }
  bool temperature_dependent() const override { return _elastic.temperature_dependent(); }

  void update(const MaterialPointInput& in, MaterialPointOutput& out) const override {
    MaterialPointOutput elastic = out;
    elastic.tangent = {};
    elastic.state = {};
    _elastic.update(in, elastic);
    out.energy = elastic.energy;
    out.thickness_strain = elastic.thickness_strain;
    out.isotropic = false;
    if (!out.tangent.empty()) { // D = lambda 1 1^T + 2 mu I on the normals, mu on the shears
      const int n = voigt_size(_kin), nn = voigt_normals(_kin);
      const IsotropicModuli& m = elastic.moduli;
      std::fill(out.tangent.begin(), out.tangent.end(), 0.0);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          out.tangent[i * n + j] =
              i < nn && j < nn ? m.lambda + (i == j ? 2.0 * m.mu : 0.0) : (i == j ? m.mu : 0.0);
    }
    const int commits = static_cast<int>(in.state_start[0]);
    int seen = g_most_commits_seen.load();
    while (commits > seen && !g_most_commits_seen.compare_exchange_weak(seen, commits)) {
    }
    out.state[0] = in.state_start[0] + 1.0;
  }
  IsotropicModuli elastic_moduli(double T, IsotropicModuli* dT) const override {
    return _elastic.elastic_moduli(T, dT);
  }

 private:
  IsotropicElasticLaw _elastic;
  Kinematics _kin;
};

// The one registration: materials named COUNTING get the toy law.
const bool kRegistered = register_solid_law(
    "counting elastic (test)", [](const Material& m) { return m.name == "COUNTING"; },
    [](const Material& m, Kinematics k) { return std::make_unique<CountingElasticLaw>(m, k); });

} // namespace

bool counting_law_registered() {
  return kRegistered;
}

} // namespace gapfem::test
