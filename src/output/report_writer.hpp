#pragma once
/// @file report_writer.hpp
/// job.report.html: one self-contained page per run (docs/results.md, "The run report") with
/// plots drawn by Chart.js, which the build embeds from Debian's libjs-chart.js, so the page needs
/// no network: gap force, clearance and status against time for the gaps the user names
/// (`--report-gaps`) or else the most loaded ones, the contact-set size per increment, the Newton
/// residual history with the cut-back attempts marked, the step self-checks and the time split.
/// Written at the end of the run, also of one that stops early.
#include "results/results.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace gapfem {

class ReportWriter : public ResultWriter {
 public:
  /// `gaps`: element labels or element set names (empty: the most loaded gaps).
  ReportWriter(std::filesystem::path path, std::string job, std::vector<std::string> gaps);

  bool wants_gap_samples() const override { return true; }
  void begin(const Model& model) override;
  void increment(const IncrementInfo& info) override;
  void end_step(const Model& model, int step_index, const StepSummary& summary) override;
  void modes(const Model& model, int step_index, const EigenSummary& modes) override;
  void end(const Model& model, const RunSummary& summary) override;
  std::string_view restart_key() const override { return "report"; }
  void save_state(ArchiveWriter& out) override;
  void resume(const Model& model, int step_index, ArchiveReader& state,
              const ResumeFiles& from) override;

  /// How many gaps the page plots when the user names none.
  static constexpr int kMostLoaded = 6;
  /// Samples (gaps x increments) kept for every gap; beyond, only the named gaps and the
  /// kKeptWhenPruned most loaded so far keep their histories.
  static constexpr std::size_t kMaxSamples = std::size_t{8} << 20;
  static constexpr int kKeptWhenPruned = 32;

 private:
  struct Attempt {
    int step = 0, increment = 0, attempt = 0;
    double total_time = 0.0;
    bool converged = false;
    std::vector<double> residuals;
  };
  struct History { ///< one gap's samples at the converged increments it was kept for
    std::vector<float> time, force, clearance;
    std::vector<std::uint8_t> status;
    float peak = 0.0f;
  };
  void prune();
  std::vector<ElemId> plotted() const;
  std::string data_json(const Model& model, const RunSummary& run) const;

  std::filesystem::path _path;
  std::string _job;
  std::vector<std::string> _gap_names;
  std::vector<ElemId> _named; ///< resolved at begin()
  std::vector<Attempt> _attempts;
  std::vector<std::pair<double, int>> _contact_set; ///< (total time, closed gaps)
  /// dynamic steps: (total time, ALLKE, ALLSE, ALLIE, ALLVD, ALLFD, ALLKL, ALLWK, ETOTAL) per
  /// increment
  std::vector<std::array<double, 9>> _energies;
  /// *OUTPUT, HISTORY: the columns (of the first step that has any) and (total time, values…)
  std::vector<std::string> _history_columns;
  std::vector<std::vector<double>> _history;
  std::vector<StepSummary> _steps;
  /// *FREQUENCY steps' modes (step number, table); not part of the restart state: a resumed
  /// run's report lists the modes of the steps it ran itself
  std::vector<std::pair<int, EigenSummary>> _modes;
  std::vector<ElemId> _gap_ids;    ///< gaps in the order of IncrementInfo::gaps
  std::vector<History> _histories; ///< per _gap_ids entry
  std::vector<char> _kept;         ///< per _gap_ids entry: history still recorded
  std::size_t _samples = 0;
  bool _pruned = false;
};

} // namespace gapfem
