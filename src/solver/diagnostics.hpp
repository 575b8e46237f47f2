#pragma once
/// @file diagnostics.hpp
/// Sentences for the user when the analysis cannot go on: a singular system (which body is free,
/// which open gaps hold it, what to do) and chattering contact.
#include "common/types.hpp"

#include <span>
#include <string>

namespace gapfem {

struct Model;
class Discretization;
class Assembler;
class StepProblem;

std::string describe_singularity(const Model& model, Discretization& disc, Assembler& assembler,
                                 StepProblem& prob, std::span<const LocalIndex> equations);
std::string describe_chattering(const Model& model, std::span<const ElemId> elements);

} // namespace gapfem
