// Spectra's implicitly restarted Lanczos behind the KrylovEigenSolver seam (krylov_eigen.hpp): its
// symmetric base solver driven directly by the caller's T = S A and B, which is what its
// shift-invert (T = (A - sigma B)^-1 B) and regular-inverse (T = B^-1 A) modes do with their own
// operators.
#include "linalg/krylov_eigen.hpp"

#include <Eigen/Core>
#include <Spectra/SymEigsBase.h>
#include <algorithm>
#include <vector>

namespace gapfem {
namespace {

/// A VectorMap as Spectra's operator type.
struct MapOp {
  using Scalar = double;
  const VectorMap* map;
  Eigen::Index n;
  Eigen::Index rows() const { return n; }
  Eigen::Index cols() const { return n; }
  void perform_op(const double* x, double* y) const { (*map)(x, y); }
};

/// T self-adjoint in the B inner product: Spectra's symmetric solver with B as its BOpType.
class OperatorLanczos final : public Spectra::SymEigsBase<MapOp, MapOp> {
 public:
  OperatorLanczos(const MapOp& op, const MapOp& b, Eigen::Index nev, Eigen::Index ncv)
      : Spectra::SymEigsBase<MapOp, MapOp>(MapOp(op), b, nev, ncv) {}
};

class SpectraKrylov final : public KrylovEigenSolver {
 public:
  std::string_view name() const override { return "Spectra (implicitly restarted Lanczos)"; }
  KrylovResult solve(const KrylovRequest& req) override {
    std::vector<double> ax(static_cast<std::size_t>(req.n));
    const VectorMap T = [&](const double* x, double* y) {
      req.apply(x, ax.data());
      req.solve(ax.data(), y);
    };
    const MapOp op{&T, req.n}, b{&req.inner, req.n};
    OperatorLanczos eigs(op, b, req.nev, std::min<Eigen::Index>(req.ncv, req.n));
    eigs.init(req.start.data());
    const auto rule =
        req.largest_algebraic ? Spectra::SortRule::LargestAlge : Spectra::SortRule::LargestMagn;
    const Eigen::Index nconv = eigs.compute(rule, req.max_restarts, req.tolerance, rule);
    KrylovResult out;
    out.restarts = static_cast<int>(eigs.num_iterations());
    out.converged = eigs.info() == Spectra::CompInfo::Successful && nconv >= req.nev;
    if (!out.converged) return out;
    const Eigen::VectorXd theta = eigs.eigenvalues();
    const Eigen::MatrixXd X = eigs.eigenvectors();
    out.theta.assign(theta.data(), theta.data() + theta.size());
    out.vectors.assign(X.data(), X.data() + X.size());
    return out;
  }
};

} // namespace

std::unique_ptr<KrylovEigenSolver> make_spectra_krylov() {
  return std::make_unique<SpectraKrylov>();
}

} // namespace gapfem
