#pragma once
/// @file field_selection.hpp
/// Which variables a ParaView frame holds, and where: the union of the `*OUTPUT, FIELD` requests
/// due in the frame. A variable of a `*NODE OUTPUT, NSET=` / `*ELEMENT OUTPUT, ELSET=` line is
/// written on that set only (NaN elsewhere). A step without `*OUTPUT, FIELD` writes, at its end,
/// every variable gapfem has but the applied loads CF, CM, CFL (docs/results.md, "ParaView
/// frames"); velocities and accelerations only in dynamic steps, the only ones that have them.
#include "model/model.hpp"
#include "results/results.hpp"

#include <array>
#include <vector>

namespace gapfem::output {

class FieldSelection {
 public:
  FieldSelection(const Model& model, int step_index, const Frame& frame);

  /// nullptr: the variable is not requested; else 1 per node (element) where it is written.
  const std::vector<char>* nodes(NodeVar v) const { return get(_node, static_cast<int>(v)); }
  const std::vector<char>* elements(ElemVar v) const { return get(_elem, static_cast<int>(v)); }

  /// `values` (one tuple of `width` per node or element) with NaN where `mask` is 0.
  static std::vector<double> masked(const std::vector<double>& values, std::size_t width,
                                    const std::vector<char>& mask);

 private:
  template <std::size_t N>
  static const std::vector<char>* get(const std::array<std::vector<char>, N>& a, int i) {
    return a[static_cast<std::size_t>(i)].empty() ? nullptr : &a[static_cast<std::size_t>(i)];
  }
  std::array<std::vector<char>, kNumNodeVars> _node; ///< per NodeVar
  std::array<std::vector<char>, 4> _elem;            ///< per ElemVar
};

} // namespace gapfem::output
