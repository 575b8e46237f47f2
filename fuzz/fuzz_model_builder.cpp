// libFuzzer target: the model builder behind the reader — a deck that reads is turned into the
// analysis's discretization (DOF map, element blocks, gap sets, constraint rows, per-step loads)
// and checked as `gapfem check` does, with a symbolic factorisation of each step's system.
// Every input must pass or raise InputError / AnalysisError.
#include "common/error.hpp"
#include "fuzz_common.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"
#include "solver/analysis.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (gapfem::fuzz::names_a_file(text)) return -1;
  try {
    const gapfem::Model model = gapfem::read_deck_string(text, "fuzz.inp", {}, "/nonexistent");
    // GENERATE can make large but valid models; the fuzzer looks for defects, not for size
    if (model.mesh.n_nodes() > 20000 || model.mesh.n_elements() > 20000) return 0;
    gapfem::Analysis analysis(model, {});
    (void)analysis.check();
  } catch (const gapfem::InputError&) {
  } catch (const gapfem::AnalysisError&) {
  }
  return 0;
}
