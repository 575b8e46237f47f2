#pragma once
/// @file factor_reuse.hpp
/// The policy for reusing a factorisation across Newton iterations and increments (KktSolver).

namespace gapfem {

/// When may a factor from an earlier matrix be used for the current one?
enum class FactorReuse {
  Auto,   ///< when the measured solve/factor times say it pays (large models)
  Always, ///< whenever the tangent drift allows it (tests)
  Never   ///< only for a bitwise identical matrix and contact set
};

} // namespace gapfem
