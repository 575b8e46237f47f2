#include "model/output_request.hpp"

#include <array>
#include <utility>

namespace gapfem {
namespace {
constexpr std::array<std::pair<std::string_view, NodeVar>, kNumNodeVars> kNodeVars = {{
    {"U", NodeVar::U},
    {"UR", NodeVar::UR},
    {"RF", NodeVar::RF},
    {"RM", NodeVar::RM},
    {"CF", NodeVar::CF},
    {"CM", NodeVar::CM},
    {"NT", NodeVar::NT},
    {"RFL", NodeVar::RFL},
    {"CFL", NodeVar::CFL},
    {"V", NodeVar::V},
    {"VR", NodeVar::VR},
    {"A", NodeVar::A},
    {"AR", NodeVar::AR},
}};
// SM (section moments) reads as SF: gapfem's SF table of beams and shells holds the section
// forces and the moments (SM1…) side by side; SENER (the strain energy density) is ENER's
// component gapfem has
constexpr std::array<std::pair<std::string_view, ElemVar>, 11> kElemVars = {{
    {"S", ElemVar::S},
    {"E", ElemVar::E},
    {"SF", ElemVar::SF},
    {"HFL", ElemVar::HFL},
    {"SM", ElemVar::SF},
    {"NFORC", ElemVar::NFORC},
    {"ENER", ElemVar::ENER},
    {"SENER", ElemVar::ENER},
    {"ELSE", ElemVar::ELSE},
    {"EVOL", ElemVar::EVOL},
    {"COORD", ElemVar::COORD},
}};
} // namespace

std::optional<NodeVar> node_var_from_name(std::string_view name) {
  for (auto [n, v] : kNodeVars)
    if (n == name) return v;
  return std::nullopt;
}
std::optional<ElemVar> elem_var_from_name(std::string_view name) {
  for (auto [n, v] : kElemVars)
    if (n == name) return v;
  return std::nullopt;
}
std::string_view node_var_name(NodeVar v) {
  for (auto [n, x] : kNodeVars)
    if (x == v) return n;
  return "?";
}
std::string_view elem_var_name(ElemVar v) {
  for (auto [n, x] : kElemVars)
    if (x == v) return n;
  return "?";
}

} // namespace gapfem
