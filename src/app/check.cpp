// gapfem check: validate a deck and summarise the model without solving (check.hpp).
#include "app/check.hpp"

#include "app/environment.hpp"
#include "app/user_code_loader.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/memory.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"
#include "solver/analysis.hpp"

#include <fmt/format.h>
#include <map>
#include <unistd.h>

namespace gapfem {

namespace {

std::string summary_of(const Model& model, const ModelCheck& c, const std::string& deck) {
  std::string s = fmt::format("gapfem check: {}\n", deck);
  std::map<std::string_view, int> by_type;
  for (ElemId e = 0; e < model.mesh.n_elements(); ++e) ++by_type[model.element_type_name(e)];
  std::string types;
  for (const auto& [name, n] : by_type)
    types += fmt::format("{}{} {}", types.empty() ? "" : ", ", name, n);
  s += fmt::format("  nodes {}, elements {}{}{}\n", model.mesh.n_nodes(), model.mesh.n_elements(),
                   types.empty() ? "" : ": ", types);
  s += fmt::format("  active nodal DOFs {}\n", c.dofs);
  int gaps = 0;
  for (const auto& g : c.gaps) gaps += g.total;
  if (gaps > 0) {
    s += fmt::format("  gaps {}, status at the start:", gaps);
    for (const auto& g : c.gaps)
      s += fmt::format(" {} {} ({} open, {} closed);", g.type, g.total, g.open, g.closed);
    s.back() = '\n';
  }
  s += fmt::format("  steps {}\n", c.steps.size());
  for (const auto& st : c.steps)
    s += fmt::format("    step {}{} ({}): {} equations, {} constraint rows, factor of K about {} "
                     "(CHOLMOD's symbolic analysis)\n",
                     st.number, st.name.empty() ? "" : " " + st.name, st.procedure, st.equations,
                     st.constraint_rows, memory_size_text(static_cast<double>(st.factor_bytes)));
  for (const auto& st : c.steps)
    if (st.factor_seconds > 0)
      s += fmt::format("  one factorisation of step {}'s stiffness (CHOLMOD, reference state): "
                       "{:.3f} s\n",
                       st.number, st.factor_seconds);
  if (!model.warnings.empty()) {
    s += fmt::format("  {} warning(s):\n", model.warnings.size());
    for (const auto& w : model.warnings) s += fmt::format("    {}\n", w);
  }
  s += "The deck is valid; nothing was solved.\n";
  return s;
}

} // namespace

CheckResult check_job(const JobOptions& given) {
  JobOptions options = given;
  options.deck = resolve_deck(given.deck);
  CheckResult result;
  try {
    ReadOptions ro;
    ro.ignore_unknown = options.ignore_unknown;
    Model model = read_deck(options.deck, ro);
    require_steps(model, options.deck);
    if (!options.user_code.empty()) // compiled and loaded as for a run (its errors are the run's)
      model.user_code =
          load_user_code(options.user_code,
                         std::filesystem::temp_directory_path() /
                             fmt::format("gapfem-check-{}.scratch", static_cast<long>(getpid())));
    AnalysisOptions ao;
    apply_environment(ao); // the GAPFEM_* switches, as for a run
    Analysis analysis(model, {}, ao);
    const ModelCheck c = analysis.check(options.time_factorization);
    result.summary = summary_of(model, c, options.deck.string());
    if (!options.quiet)
      log::info("{}", std::string_view(result.summary).substr(0, result.summary.size() - 1));
  } catch (const InputError& e) {
    result.exit_code = kExitInputError;
    result.error = e.what();
    log::error("{}", e.what());
  } catch (const AnalysisError& e) { // e.g. a symbolic analysis CHOLMOD cannot do
    result.exit_code = kExitNoConvergence;
    result.error = e.what();
    log::error("{}", e.what());
  }
  return result;
}

} // namespace gapfem
