#pragma once
/// @file report_page.hpp
/// The HTML of job.report.html (report_writer.hpp): the page with Chart.js inlined, the run data as
/// one JSON object, the step self-check table and the warnings. The page's script draws the plots
/// on load (no animation) and records on <body> how many charts it drew and how many canvases
/// hold paint (data-charts, data-painted), which the browser test reads.
#include "results/results.hpp"

#include <fmt/format.h>
#include <string>
#include <vector>

namespace gapfem::output {

struct ReportContent {
  std::string job;
  std::string data_json; ///< gaps, contact_set, energies, attempts, time_split, wall_seconds
  const RunSummary* run = nullptr;
  const std::vector<StepSummary>* steps = nullptr;
  /// *FREQUENCY steps: (step number, modes), each a table on the page
  const std::vector<std::pair<int, EigenSummary>>* modes = nullptr;
  bool has_gaps = false;
  bool has_energies = false; ///< dynamic steps: the energies chart
  bool has_history = false;  ///< *OUTPUT, HISTORY: the values' chart
  bool named_gaps = false;
};

void write_report_page(fmt::memory_buffer& out, const ReportContent& content);

} // namespace gapfem::output
