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
