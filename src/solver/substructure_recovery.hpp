#pragma once
/// @file substructure_recovery.hpp
/// Recovery of the internal results of used substructures (*SUBSTRUCTURE PATH; docs/
/// substructures.md). At every frame with field output (and at the end of each step) the
/// retained DOFs' values of a named Zn element are turned back into the substructure's own
/// directions, its internal displacements recovered from them, u_I = -K_II^-1 K_IR u_R (the
/// library's recovery data, K_II factorised once), and, when its generation deck can be read
/// again unchanged, its elements' stresses and strains computed. The analysis puts them into
/// Frame::substructures; output/substructure_recovery.cpp writes them. The generation deck is
/// read by a function the application layer gives (the reader is a layer above the solver).
#include "results/results.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

namespace gapfem {

struct Model;

/// Reads a generation deck again (io's read_deck, given by the application layer).
using DeckReader = std::function<std::unique_ptr<Model>(const std::filesystem::path&)>;

class SubstructureRecoverer {
 public:
  /// Loads every library the model's steps recover: the recovery data (AnalysisError when it
  /// cannot be read or holds none) and the generation model (a note and displacements only when
  /// `read_deck` is empty, the deck cannot be read or has changed).
  SubstructureRecoverer(const Model& model, const DeckReader& read_deck);
  ~SubstructureRecoverer();
  SubstructureRecoverer(const SubstructureRecoverer&) = delete;
  SubstructureRecoverer& operator=(const SubstructureRecoverer&) = delete;

  /// The step's *SUBSTRUCTURE PATH elements at the frame `f` of the usage model.
  std::vector<RecoveredSubstructure> recover(const Model& model, int step_index,
                                             const Frame& f) const;

  struct Library; ///< one library file's recovery data and generation model

 private:
  struct Element {
    ElemId elem = -1;
    std::array<double, 9> R{}; ///< the placement's rotation
    double det = 1.0;
    std::shared_ptr<const Library> lib;
  };
  RecoveredSubstructure recover_one(const Model& model, const Element& el, const Frame& f) const;
  std::vector<Element> _elements;
};

} // namespace gapfem
