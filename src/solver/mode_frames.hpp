#pragma once
/// @file mode_frames.hpp
/// The output of an eigenvalue step (*FREQUENCY, *BUCKLE): the writers' table of the modes and a
/// frame per mode, whose U and UR are its shape.
#include "linalg/eigen_solver.hpp"
#include "results/results.hpp"
#include "solver/analysis.hpp"

#include <string_view>

namespace gapfem {

struct StepRun;

/// `pairs.vectors` per equation of the step's problem, normalised as `sum` says; `procedure`
/// and `what` name the step's procedure and its modes in the warning about element output.
void write_mode_frames(Analysis::Impl& a, StepRun& r, const EigenPairs& pairs,
                       const EigenSummary& sum, std::string_view procedure, std::string_view what);

} // namespace gapfem
