#include "output/vtu_cell_data.hpp"

#include "output/output_file.hpp"

#include <cmath>
#include <limits>

namespace gapfem::output {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The values at section point `k` (averaged over the integration points) in the Voigt slots of
/// element `e` of `target` (zeros in components the block does not have).
void put_point(const OutputBlock& block, int k, std::size_t e, std::vector<double>& target,
               std::vector<double>& avg) {
  average_section_point(block, k, avg);
  std::fill_n(target.begin() + static_cast<std::ptrdiff_t>(6 * e), 6, 0.0);
  for (std::size_t c = 0; c < block.names.size(); ++c)
    if (const int slot = voigt_slot(block.names[c]); slot >= 0) target[6 * e + slot] = avg[c];
}

/// The section point of a beam's S block with the largest |S11| (the extreme fibre).
int extreme_fibre(const OutputBlock& block, std::vector<double>& avg) {
  int best = 0;
  double peak = -1.0;
  for (int k = 0; k < block.section_points; ++k) {
    average_section_point(block, k, avg);
    for (std::size_t c = 0; c < block.names.size(); ++c)
      if (block.names[c] == "S11" && std::abs(avg[c]) > peak) {
        peak = std::abs(avg[c]);
        best = k;
      }
  }
  return best;
}

/// "SF3" -> 2, "SM1" -> 0 (with `prefix` "SF" or "SM"), else -1.
int component(std::string_view name, std::string_view prefix, int n) {
  if (name.size() != 3 || name.substr(0, 2) != prefix) return -1;
  const int k = name[2] - '1';
  return k >= 0 && k < n ? k : -1;
}

} // namespace

void VtuCellData::collect(const Model& model, const Frame& frame, bool has_gaps) {
  const Mesh& mesh = model.mesh;
  const auto ne = static_cast<std::size_t>(mesh.n_elements());
  for (auto* v : {&S, &E, &S_neg, &S_pos, &E_neg, &E_pos}) v->assign(6 * ne, kNaN);
  SF.assign(6 * ne, kNaN);
  SM.assign(3 * ne, kNaN);
  HFL.assign(3 * ne, kNaN);
  any_S = any_E = any_sides = any_SF = any_SM = any_HFL = false;
  if (has_gaps) {
    gap_status.assign(ne, -1);
    gap_clearance.assign(ne, kNaN);
    gap_pressure.assign(ne, kNaN);
  }
  for (const ElementResult& res : frame.elements) {
    if (res.elem < 0 || static_cast<std::size_t>(res.elem) >= ne) continue;
    const auto e = static_cast<std::size_t>(res.elem);
    const ElementFamily family = element_info(mesh.elem_types[res.elem]).family;
    // a beam shows S and E at its most stressed section point (the S block decides for both)
    int fibre = -1;
    if (family == ElementFamily::Beam)
      for (const OutputBlock& block : res.data.blocks)
        if (block.var == ElemVar::S && block.section_points > 1) fibre = extreme_fibre(block, _avg);
    for (const OutputBlock& block : res.data.blocks) {
      const bool tensor = block.var == ElemVar::S || block.var == ElemVar::E;
      auto& target = block.var == ElemVar::S ? S : E;
      if (tensor && block.section_points > 1 && family == ElementFamily::Shell) {
        put_point(block, 0, e, block.var == ElemVar::S ? S_neg : E_neg, _avg);
        put_point(block, block.section_points - 1, e, block.var == ElemVar::S ? S_pos : E_pos,
                  _avg);
        any_sides = true;
      }
      if (tensor && fibre >= 0 && fibre < block.section_points) {
        put_point(block, fibre, e, target, _avg);
        (block.var == ElemVar::S ? any_S : any_E) = true;
        continue;
      }
      average_block(block, _avg);
      for (std::size_t c = 0; c < block.names.size(); ++c) {
        const std::string_view name = block.names[c];
        if (block.var == ElemVar::HFL) {
          if (name.size() == 4 && name.substr(0, 3) == "HFL" && name[3] >= '1' && name[3] <= '3') {
            if (std::isnan(HFL[3 * e])) std::fill_n(HFL.begin() + 3 * e, 3, 0.0);
            HFL[3 * e + static_cast<std::size_t>(name[3] - '1')] = _avg[c];
            any_HFL = true;
          }
          continue;
        }
        if (block.var == ElemVar::SF) {
          // (components an element does not have stay NaN: a beam has no SF4 … SF6)
          if (const int k = component(name, "SF", 6); k >= 0) {
            SF[6 * e + static_cast<std::size_t>(k)] = _avg[c];
            any_SF = true;
          } else if (const int m = component(name, "SM", 3); m >= 0) {
            SM[3 * e + static_cast<std::size_t>(m)] = _avg[c];
            any_SM = true;
          }
          continue;
        }
        const int slot = voigt_slot(name);
        if (slot < 0) continue;
        // an element that reports the tensor gets zeros in the components it does not have
        if (std::isnan(target[6 * e])) std::fill_n(target.begin() + 6 * e, 6, 0.0);
        target[6 * e + slot] = _avg[c];
        (block.var == ElemVar::S ? any_S : any_E) = true;
      }
    }
    if (has_gaps && res.data.gap) {
      gap_status[e] = static_cast<std::int32_t>(res.data.gap->status);
      gap_clearance[e] = res.data.gap->clearance;
      gap_pressure[e] = res.data.gap->pressure;
    }
  }
}

} // namespace gapfem::output
