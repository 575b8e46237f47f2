// The registry of solid laws (solid_law.hpp).
#include "elements/material/solid_law.hpp"

#include "elements/material/isotropic_elastic.hpp"

#include <fmt/format.h>
#include <mutex>
#include <vector>

namespace gapfem {
namespace {

struct Registration {
  std::string name;
  SolidLawPredicate applies;
  SolidLawFactory make;
};

struct Registry {
  std::mutex mutex;
  std::vector<Registration> laws; ///< oldest first; asked newest first
};

Registry& registry() {
  static Registry r;
  static const bool built_in = [] {
    // The built-in laws, most general first (a later one is asked before it).
    r.laws.push_back({"isotropic elastic", [](const Material& m) { return m.has_elastic(); },
                      [](const Material& m, Kinematics k) -> std::unique_ptr<SolidLaw> {
                        return std::make_unique<IsotropicElasticLaw>(m, k);
                      }});
    return true;
  }();
  (void)built_in;
  return r;
}

} // namespace

bool register_solid_law(std::string name, SolidLawPredicate applies, SolidLawFactory make) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.laws.push_back({std::move(name), std::move(applies), std::move(make)});
  return true;
}

std::shared_ptr<const SolidLaw> make_solid_law(const Material& material, Kinematics kinematics) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  for (auto it = r.laws.rbegin(); it != r.laws.rend(); ++it)
    if (it->applies(material)) return it->make(material, kinematics);
  throw InputError(
      material.loc, material.name,
      fmt::format("material {} has no data a solid element can use (no *ELASTIC)", material.name));
}

} // namespace gapfem
