#pragma once
/// @file finite_check.hpp
/// A converged increment may not hold a number that is not finite (inf or NaN): loads or material
/// values beyond double precision (about 1.8E308) overflow in products that Newton's residual
/// does not see, such as the stresses recovered for output. The analysis checks the solution,
/// reactions and every element's history and multipliers (gap forces) after each converged
/// increment, and the element output of each frame before it is written; the first value found
/// stops the analysis (AnalysisError, exit 2) with a sentence naming where it is.
#include "results/results.hpp"

#include <span>
#include <string>

namespace gapfem {

struct Model;
class Discretization;

/// The first non-finite value of a converged state: the solution and reactions per DOF slot, then
/// the elements' trial histories and multipliers. "" when every value is finite.
std::string first_non_finite_state(const Model& model, const Discretization& disc,
                                   std::span<const double> u, std::span<const double> reactions);

/// The first non-finite value of a frame's element output. "" when every value is finite.
std::string first_non_finite_output(const Model& model, const Frame& frame);

/// The AnalysisError message for a non-finite value found in increment `increment` (the step
/// driver puts "step N: " before it).
std::string non_finite_message(int increment, const std::string& where);

} // namespace gapfem
