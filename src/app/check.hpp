#pragma once
/// @file check.hpp
/// `gapfem check deck.inp` (Abaqus's datacheck): read and validate everything the analysis would —
/// the deck, every element's geometry and data, the procedures, each step's loads, equations and
/// symbolic factorisation — and print a model summary, without solving.
#include "app/job.hpp"

#include <filesystem>
#include <string>

namespace gapfem {

struct CheckResult {
  int exit_code = kExitOk; ///< 0 valid, 1 input error
  std::string error;       ///< the message printed for a non-zero exit
  std::string summary;     ///< the model summary printed for a valid deck
};

/// Uses options.deck, ignore_unknown and quiet (no summary on the terminal); writes no file.
CheckResult check_job(const JobOptions& options);

/// The deck a job reads: `job` (no extension, the `abaqus job=job` / `ccx -i job` habit) means
/// job.inp when there is no file `job`. Used by run_job and check_job.
std::filesystem::path resolve_deck(const std::filesystem::path& deck);

} // namespace gapfem
