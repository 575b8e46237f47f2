#pragma once
// Helpers shared by deck-level tests: write a deck to a temporary directory, run it, look up nodal
// and element results by deck label.
#include "app/job.hpp"
#include "model/model.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace gapfem::test {

/// A fresh directory under the test temp dir named after the running test.
inline std::filesystem::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "gapfem" /
                              (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole content of a file ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::filesystem::path write_deck(const std::string& text, const std::string& name = "job") {
  const auto path = test_dir() / (name + ".inp");
  std::ofstream(path) << text;
  return path;
}

/// Run a deck given as text. Files are written only when `files` is true.
inline JobResult run_deck(const std::string& text, bool files = false,
                          const std::string& name = "job") {
  JobOptions o;
  o.deck = write_deck(text, name);
  o.write_files = files;
  o.quiet = true;
  return run_job(o);
}

/// Run a deck with a fresh factor in every Newton iteration. For tests that compare two decks of
/// the same model to 1e-10: the default (Auto) factor reuse decides from measured solve and factor
/// times, so under load the two runs could take different (equally valid) Newton paths and
/// converge to within the tolerance rather than to the same digits.
inline JobResult run_deck_exact(const std::string& text, const std::string& name = "job",
                                bool files = false) {
  JobOptions o;
  o.deck = write_deck(text, name);
  o.write_files = files;
  o.quiet = true;
  o.factor_reuse = FactorReuse::Never;
  return run_job(o);
}

/// The model data of the smallest deck with a gap: node 10 on a spring to ground (k = 100 in y),
/// a GAPUNI of clearance 0.5 in -y to the fixed node 12. Loaded with 100 in -y it closes the gap
/// at u = -0.5 and the rest goes into the gap. Tests add their heading and steps.
inline constexpr const char* kSpringOnGapModel = R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SPR
1, 10
*SPRING, ELSET=SPR
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0.5, 0., -1., 0., 1.
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
)";

inline const Frame& last_frame(const JobResult& r, int step = -1) {
  const int s = step > 0 ? step : static_cast<int>(r.model->steps.size());
  const Frame* f = r.step_end(s);
  if (!f) throw std::runtime_error("no final frame for step " + std::to_string(s));
  return *f;
}

inline const Vec3& U(const JobResult& r, const Frame& f, Label node) {
  return f.nodes.U.at(r.model->mesh.find_node(node));
}
inline const Vec3& RF(const JobResult& r, const Frame& f, Label node) {
  return f.nodes.RF.at(r.model->mesh.find_node(node));
}
inline const GapRecord& gap(const JobResult& r, const Frame& f, Label elem) {
  const ElementResult* e = f.element(r.model->mesh.find_element(elem));
  if (!e || !e->data.gap)
    throw std::runtime_error("no gap record for element " + std::to_string(elem));
  return *e->data.gap;
}

} // namespace gapfem::test
