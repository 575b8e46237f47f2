#pragma once
/// @file vtu_cell_data.hpp
/// The cell data of a ParaView frame, gathered from the element results of a Frame: S and E in
/// Voigt slots (the average over the integration points; a shell's SNEG and SPOS sides as well;
/// a beam's most stressed section point, where the extreme fibre is), SF/SM section forces and
/// moments, HFL, and the gap status, clearance and pressure.
#include "model/model.hpp"
#include "results/results.hpp"

#include <cstdint>
#include <vector>

namespace gapfem::output {

struct VtuCellData {
  std::vector<double> S, E;                       ///< 6 Voigt slots per element
  std::vector<double> S_neg, S_pos, E_neg, E_pos; ///< shells: SNEG, SPOS section points
  std::vector<double> SF;                         ///< SF1 … SF6 per element
  std::vector<double> SM;                         ///< SM1 … SM3 per element
  std::vector<double> HFL;                        ///< 3 per element
  std::vector<std::int32_t> gap_status;
  std::vector<double> gap_clearance, gap_pressure;
  bool any_S = false, any_E = false, any_sides = false, any_SF = false, any_SM = false,
       any_HFL = false;

  /// Fills every array from the frame's element results (NaN for elements without the value).
  void collect(const Model& model, const Frame& frame, bool has_gaps);

 private:
  std::vector<double> _avg;
};

} // namespace gapfem::output
