// *OUTPUT, HISTORY (model/output_request.hpp, HistoryOutputRequest): after every n-th converged
// increment (and the step's last) the requested node variables at their nodes and element
// variables averaged over each element's points, handed to the writers with the increment
// (IncrementInfo::history; docs/results.md, "History output").
#include "model/model.hpp"
#include "solver/analysis_impl.hpp"

#include <fmt/format.h>

namespace gapfem {

namespace {

/// The three components of a vector node variable (nullptr: a scalar or absent in this step).
const std::vector<Vec3>* vector_of(const NodeResults& nr, NodeVar v) {
  switch (v) {
  case NodeVar::U:
    return &nr.U;
  case NodeVar::UR:
    return &nr.UR;
  case NodeVar::RF:
    return &nr.RF;
  case NodeVar::RM:
    return &nr.RM;
  case NodeVar::CF:
    return &nr.CF;
  case NodeVar::CM:
    return &nr.CM;
  case NodeVar::V:
    return &nr.V;
  case NodeVar::VR:
    return &nr.VR;
  case NodeVar::A:
    return &nr.A;
  case NodeVar::AR:
    return &nr.AR;
  default:
    return nullptr;
  }
}

const std::vector<double>* scalar_of(const NodeResults& nr, NodeVar v) {
  switch (v) {
  case NodeVar::NT:
    return &nr.NT;
  case NodeVar::RFL:
    return &nr.RFL;
  case NodeVar::CFL:
    return &nr.CFL;
  default:
    return nullptr;
  }
}

/// The history's values (and, when `names`, their column names) of one request.
struct HistoryRow {
  std::vector<double>& values;
  std::vector<std::string>* names;
  void add(double v, std::string_view name, std::string_view where) {
    values.push_back(v);
    if (names) names->push_back(fmt::format("{} at {}", name, where));
  }
};

void node_values(const Model& model, const HistoryOutputRequest& req, const NodeResults& nr,
                 HistoryRow& row) {
  for (const auto& [var, nodes] : req.node_vars) {
    const std::string_view name = node_var_name(var);
    for (NodeId n : nodes) {
      const std::string where = fmt::format("node {}", model.node_label(n).str());
      if (const auto* vec = vector_of(nr, var); vec && !vec->empty()) {
        for (int c = 0; c < 3; ++c)
          row.add((*vec)[static_cast<std::size_t>(n)][c], fmt::format("{}{}", name, c + 1), where);
      } else if (const auto* sc = scalar_of(nr, var); sc && !sc->empty()) {
        row.add((*sc)[static_cast<std::size_t>(n)], name, where);
      }
    }
  }
}

void element_values(const Model& model, const HistoryOutputRequest& req, Assembler& assembler,
                    StepProblem& prob, HistoryRow& row) {
  const FieldView fields = prob.fields();
  ElementRecovery rec;
  for (const auto& [var, elems] : req.elem_vars)
    for (ElemId e : elems) {
      assembler.recover(e, fields, prob.context(), rec);
      const OutputBlock* b = rec.find(var);
      if (!b || b->names.empty() || b->n_points <= 0) continue; // not reported by the element
      const std::string where = fmt::format("element {}", model.element_label(e).str());
      const std::size_t nc = b->names.size();
      const std::size_t rows = b->values.size() / nc;
      for (std::size_t c = 0; c < nc; ++c) {
        double sum = 0.0;
        for (std::size_t p = 0; p < rows; ++p) sum += b->values[p * nc + c];
        row.add(rows ? sum / static_cast<double>(rows) : 0.0, b->names[c], where);
      }
    }
}

} // namespace

void Analysis::Impl::history_sample(int step_index, StepProblem& prob, int increment, bool last,
                                    IncrementInfo& info) {
  const Step& step = model.steps[step_index];
  bool due = false;
  for (const HistoryOutputRequest& req : step.history_outputs)
    due |= (!req.node_vars.empty() || !req.elem_vars.empty()) &&
           (last || (req.frequency > 0 && increment % req.frequency == 0));
  if (!due) return;
  const bool first = history_step != step_index;
  std::vector<std::string> names;
  HistoryRow row{info.history, first ? &names : nullptr};
  Frame frame;
  frame_nodes(prob, frame);
  // every request every time it is due for one (fixed columns for the step)
  for (const HistoryOutputRequest& req : step.history_outputs) {
    node_values(model, req, frame.nodes, row);
    element_values(model, req, assembler, prob, row);
  }
  if (first) {
    history_columns = std::make_shared<const std::vector<std::string>>(std::move(names));
    history_step = step_index;
  }
  info.history_columns = history_columns;
}

} // namespace gapfem
