#pragma once
// Shared by the structural verification tests: run a deck of this directory through run_job and
// read nodal and element results of its frames.
#include "app/job.hpp"
#include "model/model.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace gapfem {

constexpr double kRel = 1e-8;

inline JobResult run_deck(const std::string& name) {
  JobOptions opt{.deck =
                     std::filesystem::path(GAPFEM_TEST_DIR) / "verification" / "structural" / name,
                 .write_files = false,
                 .quiet = true};
  return run_job(opt);
}

/// Runs a deck and checks it completed; the last frame of step 1 is then `end`.
struct DeckRun {
  JobResult res;
  const Frame* end = nullptr;
  explicit DeckRun(const std::string& deck) : res(run_deck(deck)) {
    EXPECT_EQ(res.exit_code, kExitOk) << res.error;
    if (res.exit_code == kExitOk && res.model) end = res.step_end(1);
  }
  bool ok() const { return end != nullptr; }
  const Model& model() const { return *res.model; }
  NodeId node(Label label) const { return JobResult::node(model(), label); }
  const Vec3& U(Label n) const { return end->nodes.U[node(n)]; }
  const Vec3& UR(Label n) const { return end->nodes.UR[node(n)]; }
  const Vec3& RF(Label n) const { return end->nodes.RF[node(n)]; }
  /// Component `comp` at point `point` of output `var` of element `label` in frame f.
  double el(const Frame& f, Label label, ElemVar var, int comp, int point = 0) const {
    const ElemId e = model().mesh.find_element(label);
    const ElementResult* r = f.element(e);
    if (r == nullptr) {
      ADD_FAILURE() << "no output for element " << label;
      return NAN;
    }
    const OutputBlock* b = r->data.find(var);
    if (b == nullptr) {
      ADD_FAILURE() << "element " << label << " has no " << elem_var_name(var);
      return NAN;
    }
    return b->values[static_cast<std::size_t>(point) * b->names.size() + comp];
  }
  double el(Label label, ElemVar var, int comp, int point = 0) const {
    return el(*end, label, var, comp, point);
  }
};

#define EXPECT_REL(actual, expected)                                                               \
  EXPECT_NEAR((actual), (expected), kRel* std::max(1.0, std::abs(expected)))
/// For small quantities: relative to a given scale.
#define EXPECT_SCALED(actual, expected, scale) EXPECT_NEAR((actual), (expected), kRel*(scale))

} // namespace gapfem
