#pragma once
// Two runs of the same deck that must give the same converged answer (solver paths, backends).
#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace gapfem::test {

/// Every step's last U, RF and gap forces within tol of their scales (forces also within
/// k_max 1e-10 u_scale). Returns whether the iteration histories were identical.
inline bool expect_same(const JobResult& a, const JobResult& b, double tol, double k_max,
                        const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.exit_code, b.exit_code) << a.error << " | " << b.error;
  if (a.exit_code != 0 || b.exit_code != 0) return a.exit_code == b.exit_code;
  bool same_history = a.increments.size() == b.increments.size();
  for (std::size_t i = 0; same_history && i < a.increments.size(); ++i)
    same_history = a.increments[i].converged == b.increments[i].converged &&
                   a.increments[i].iterations == b.increments[i].iterations;
  EXPECT_EQ(a.steps.size(), b.steps.size());
  if (a.steps.size() != b.steps.size()) return false;
  for (std::size_t s = 0; s < a.steps.size(); ++s) {
    const Frame& fa = last_frame(a, static_cast<int>(s + 1));
    const Frame& fb = last_frame(b, static_cast<int>(s + 1));
    double su = 1e-30, sf = 1e-30, du = 0, df = 0;
    for (NodeId n = 0; n < static_cast<NodeId>(fa.nodes.U.size()); ++n)
      for (int k = 0; k < 3; ++k) {
        su = std::max(su, std::abs(fa.nodes.U[n][k]));
        du = std::max(du, std::abs(fa.nodes.U[n][k] - fb.nodes.U[n][k]));
        sf = std::max(sf, std::abs(fa.nodes.RF[n][k]));
        df = std::max(df, std::abs(fa.nodes.RF[n][k] - fb.nodes.RF[n][k]));
      }
    // rotations and temperatures where the model has them
    double sr = 1e-30, dr = 0, st = 1e-30, dt = 0;
    for (std::size_t n = 0; n < fa.nodes.UR.size() && n < fb.nodes.UR.size(); ++n)
      for (int k = 0; k < 3; ++k) {
        sr = std::max(sr, std::abs(fa.nodes.UR[n][k]));
        dr = std::max(dr, std::abs(fa.nodes.UR[n][k] - fb.nodes.UR[n][k]));
      }
    for (std::size_t n = 0; n < fa.nodes.NT.size() && n < fb.nodes.NT.size(); ++n) {
      st = std::max(st, std::abs(fa.nodes.NT[n]));
      dt = std::max(dt, std::abs(fa.nodes.NT[n] - fb.nodes.NT[n]));
    }
    EXPECT_LE(dr, tol * sr) << "step " << s + 1 << " (rotations)";
    EXPECT_LE(dt, tol * st) << "step " << s + 1 << " (temperatures)";
    double sg = 1e-30, dg = 0;
    for (ElemId e = 0; e < a.model->mesh.n_elements(); ++e) {
      const ElementResult* ea = fa.element(e);
      const ElementResult* eb = fb.element(e);
      if (!ea || !ea->data.gap) continue;
      if (!eb || !eb->data.gap) {
        ADD_FAILURE() << "element " << e << " has no gap result in the second run";
        return false;
      }
      sg = std::max(sg, std::abs(ea->data.gap->normal_force));
      dg = std::max(dg, std::abs(ea->data.gap->normal_force - eb->data.gap->normal_force));
      EXPECT_EQ(ea->data.gap->status, eb->data.gap->status) << "element " << e;
    }
    const double round_off = k_max * 1e-10 * su;
    EXPECT_LE(du, tol * su) << "step " << s + 1;
    EXPECT_LE(df, tol * sf + round_off) << "step " << s + 1;
    EXPECT_LE(dg, tol * sg + round_off) << "step " << s + 1;
  }
  return same_history;
}

} // namespace gapfem::test
