#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gapfem {

std::string_view procedure_name(Procedure p) {
  switch (p) {
  case Procedure::Static:
    return "STATIC";
  case Procedure::HeatTransfer:
    return "HEAT TRANSFER";
  case Procedure::CoupledTempDisp:
    return "COUPLED TEMPERATURE-DISPLACEMENT";
  }
  return "?";
}

SourceLocation Model::element_location(ElemId e) const {
  SourceLocation loc;
  if (e < 0 || e >= mesh.n_elements()) return loc;
  const SourceRef ref = mesh.elem_src[e];
  if (ref.file >= 0 && ref.file < static_cast<int>(source_files.size()))
    loc.file = source_files[ref.file];
  loc.line = ref.line;
  loc.keyword = "*ELEMENT";
  return loc;
}

std::string EntityLabel::str() const {
  const int i = instance();
  if (i <= 0 || !instances || i > static_cast<int>(instances->size())) return std::to_string(key);
  return (*instances)[static_cast<std::size_t>(i - 1)] + "." + std::to_string(local());
}

double Model::model_size() const {
  if (mesh.coords.empty()) return 1.0;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi{-lo[0], -lo[1], -lo[2]};
  for (const auto& x : mesh.coords)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], x[i]);
      hi[i] = std::max(hi[i], x[i]);
    }
  const double d = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                             (hi[2] - lo[2]) * (hi[2] - lo[2]));
  return d > 0 ? d : 1.0;
}

} // namespace gapfem
