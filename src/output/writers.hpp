#pragma once
/// @file writers.hpp
/// The set of result writers of a job: job.dat, job.sta, job.results.json,
/// ParaView files and job.frd (docs/results.md), created together from WriterOptions.
#include "results/results.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace gapfem {

/// Which result files to write, and where.
struct WriterOptions {
  std::filesystem::path directory; ///< created if missing; empty: the current directory
  std::string job;                 ///< file stem: job.dat, job.sta, job.results.json, job.pvd
  bool dat = true;                 ///< *NODE PRINT / *EL PRINT tables, self-checks (job.dat)
  bool sta = true;                 ///< status file, one line per increment attempt (job.sta)
  bool json = true;                ///< machine-readable results (job.results.json)
  bool vtu = true;                 ///< ParaView frames (job_<step>_<inc>.vtu, job.pvd)
  bool frd = true;                 ///< *NODE FILE / *EL FILE results for cgx (job.frd), when asked
  bool report = true;              ///< the run report with plots (job.report.html)
  std::vector<std::string> report_gaps; ///< --report-gaps: gap labels or sets to plot
  bool msg = true; ///< message file: the whole log, iterations included (job.msg)
  /// the recovered insides of used substructures (<job>_<Zn>_<element>.results.json), for a model
  /// whose steps ask for them with *SUBSTRUCTURE PATH
  bool substructure_recovery = false;
  bool terminal = false; ///< also add a TerminalWriter (progress through gapfem::log)
};

/// The writers selected by `options`, in the order dat, json, vtu, frd, report, sta, msg,
/// terminal (what reports an increment comes after what stores it). Files are opened in begin();
/// errors opening or writing them raise AnalysisError.
std::vector<std::unique_ptr<ResultWriter>> make_result_writers(const WriterOptions& options);

} // namespace gapfem
