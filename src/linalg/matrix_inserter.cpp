#include "linalg/matrix_inserter.hpp"

#include "common/error.hpp"

namespace gapfem {

void CsrInserter::open(int lanes) {
  _lanes = std::max(lanes, 1);
  if (static_cast<int>(_private.size()) < _lanes - 1)
    _private.resize(static_cast<std::size_t>(_lanes - 1));
  _touched.assign(_private.size(), 0);
}

void CsrInserter::add(int lane, std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
                      std::span<const double> block) {
  FE_CHECK(lane >= 0 && lane < _lanes, "matrix inserter lane out of range");
  if (lane == 0) {
    _A->add_block(rows, cols, block);
    return;
  }
  auto& p = _private[static_cast<std::size_t>(lane - 1)];
  if (!_touched[static_cast<std::size_t>(lane - 1)]) {
    // a private copy is zeroed on its first use after open(): lanes that stay idle cost nothing
    if (!p || p->pattern_ptr() != _A->pattern_ptr())
      p = std::make_unique<CsrMatrix>(_A->pattern_ptr());
    else
      p->set_zero();
    _touched[static_cast<std::size_t>(lane - 1)] = 1;
  }
  p->add_block(rows, cols, block);
}

void CsrInserter::close() {
  auto dst = _A->values();
  for (std::size_t l = 0; l < _touched.size(); ++l) {
    if (!_touched[l]) continue;
    const auto src = _private[l]->values();
    for (std::size_t k = 0; k < dst.size(); ++k) dst[k] += src[k];
    _touched[l] = 0;
  }
  _lanes = 1;
}

} // namespace gapfem
