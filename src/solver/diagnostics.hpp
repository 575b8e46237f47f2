#pragma once
/// @file diagnostics.hpp
/// Sentences for the user when the analysis cannot go on: a singular system (which body is free,
/// which open gaps hold it, what to do) and chattering contact.
#include "common/types.hpp"

#include <span>
#include <string>
#include <vector>

namespace gapfem {

struct Model;
class Discretization;
class Assembler;
class StepProblem;

/// `supported`: the stiffness at the last converged state is not singular (so the singularity
/// came with the deformation of the increment: a limit load or a crushed element, not a missing
/// support).
std::string describe_singularity(const Model& model, Discretization& disc, Assembler& assembler,
                                 StepProblem& prob, std::span<const LocalIndex> equations,
                                 bool supported = false);
std::string describe_chattering(const Model& model, std::span<const ElemId> elements);

/// The problems met by the failed attempts of one increment, so that the message of a step that
/// cannot go on names every cause seen in its cut-backs (an element turned inside out in one
/// attempt and a singular system in the next is an inverted element, not a missing support).
class AttemptLog {
 public:
  /// A new increment starts: forget the previous one's problems (but not the last structural
  /// one, see add()).
  void clear() { _entries.clear(); }
  /// `kind` groups repeats of one cause (e.g. "element 12" for its det F failures); `text` is the
  /// sentence of the latest occurrence. A `structural` cause (singular system, failed element,
  /// chattering contact) is also remembered for the rest of the step, with its increment, since
  /// a step that creeps towards a limit load ends with plain iteration failures.
  void add(int increment, int attempt, std::string kind, std::string text, bool structural);
  /// "Last problem: <last>" and, when earlier attempts failed for other reasons,
  /// "; earlier attempts: <text> (attempts 1, 3); …".
  std::string summary() const;

 private:
  struct Entry {
    std::string kind, text;
    std::vector<int> attempts;
  };
  std::vector<Entry> _entries;
  std::string _last_kind;
  Entry _structural; ///< attempts holds the increment number
};

} // namespace gapfem
