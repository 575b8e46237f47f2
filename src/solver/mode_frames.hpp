#pragma once
/// @file mode_frames.hpp
/// The output of an eigenvalue step (*FREQUENCY, *BUCKLE): the writers' table of the modes and a
/// frame per mode, whose U and UR are its shape and whose element output is that of the shape.
#include "linalg/eigen_solver.hpp"
#include "results/results.hpp"
#include "solver/analysis.hpp"

#include <string_view>

namespace gapfem {

struct StepRun;

/// `pairs.vectors` per equation of the step's problem, normalised as `sum` says; the element
/// output of a mode is the change of the elements' values along its shape (linear perturbation).
void write_mode_frames(Analysis::Impl& a, StepRun& r, const EigenPairs& pairs,
                       const EigenSummary& sum);

} // namespace gapfem
