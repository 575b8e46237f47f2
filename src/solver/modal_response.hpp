#pragma once
/// @file modal_response.hpp
/// What the mode-based procedures share (docs/theory/modal_dynamics.md): the modes a step uses
/// with their damping, and its excitation projected on them. With unit-mass shapes phi_k each
/// mode obeys q_k'' + 2 zeta_k omega_k q_k' + omega_k^2 q_k = sum_terms F_tk a_t(t), the
/// response u = sum_k phi_k q_k (relative to the base under base motion).
#include "model/model.hpp"
#include "solver/modal_basis.hpp"

#include <complex>
#include <memory>
#include <string>
#include <vector>

namespace gapfem {

class DofMap;
class Discretization;

/// A mode-based step needs a *FREQUENCY step before it: InputError at `loc` otherwise (the
/// datacheck's and the run's message).
void require_frequency_step(const Model& model, const Step& step, const SourceLocation& loc);

/// The basis a mode-based step works on; InputError at `loc` when there is none (its *FREQUENCY
/// step's modes were not kept).
const ModalBasis& basis_of(const std::shared_ptr<const ModalBasis>& b, const Step& step,
                           const SourceLocation& loc);

/// The modes of the basis a step uses (*SELECT EIGENMODES, else all), 0-based, with their
/// circular frequencies and fractions of critical damping (*MODAL DAMPING; none: 0).
struct ModalSelection {
  std::vector<int> modes;
  std::vector<double> omega, zeta;
};
/// Throws InputError (at `loc`) when *SELECT EIGENMODES names a mode the basis does not have.
ModalSelection select_modes(const Step& step, const ModalBasis& b, const SourceLocation& loc);

/// One part of the excitation: a group of concentrated loads sharing an amplitude and a part, or
/// one base motion, as generalized forces on the selected modes.
struct ModalTerm {
  int amplitude = -1;     ///< Model::amplitudes index (-1: constant 1)
  bool imaginary = false; ///< the out-of-phase part (steady-state dynamics)
  bool base = false;      ///< a base motion (its force -Gamma_kd s times the base acceleration)
  BaseMotion::Type type = BaseMotion::Type::Acceleration;
  std::vector<double> force; ///< per selected mode: phi_k^T F, or -Gamma_kd s
};

/// The step's *CLOAD entries (local directions at *TRANSFORM nodes turned global) and *BASE
/// MOTIONs on the selected modes.
std::vector<ModalTerm> modal_excitation(const Model& model, const DofMap& dofs, const Step& step,
                                        const ModalBasis& b, const ModalSelection& sel);

/// The excitation frequencies of a *STEADY STATE DYNAMICS step (cycles per time, ascending, each
/// once): per data line n points from its lower to its upper frequency (one at the lower when the
/// upper is 0), over each interval between the eigenfrequencies inside it (INTERVAL=
/// EIGENFREQUENCY, whose points then include them) or over the whole range (RANGE); within an
/// interval [f1, f2] point k of n at y = -1 + 2 k / (n - 1), f = (f1 + f2) / 2 + (f2 - f1) / 2
/// |y|^(1/p) sign(y) (on log f for FREQUENCY SCALE=LOGARITHMIC, p the bias: p > 1 gathers the
/// points at the ends); the points inside the range multiplied by the frequency scale.
std::vector<double> steady_state_frequencies(const SteadyStateSettings& ss,
                                             std::span<const double> eigenfrequencies);

/// The warning a mode-based step gets when elements of the model have damping of their own
/// (dashpots, ALPHA, material Rayleigh damping): only *MODAL DAMPING damps the modes. Empty when
/// none has.
std::string element_damping_warning(const Discretization& disc, const Step& step);

/// What a mode-based dynamic step works on: the basis, the modes it uses, its excitation.
struct ModalProblem {
  std::shared_ptr<const ModalBasis> basis;
  ModalSelection sel;
  std::vector<ModalTerm> terms;
};
/// The step's ModalProblem on `basis` (basis_of, select_modes, modal_excitation), with the
/// element-damping warning added to `warnings` when it applies.
ModalProblem modal_problem(const Model& model, const Discretization& disc,
                           std::shared_ptr<const ModalBasis> basis, const Step& step,
                           const SourceLocation& loc, std::vector<std::string>& warnings);

/// The response per DOF slot of the modal coordinates q (per selected mode): sum_k phi_k q_k.
std::vector<double> modal_superposition(const ModalBasis& b, const ModalSelection& sel,
                                        std::span<const double> q);

} // namespace gapfem
