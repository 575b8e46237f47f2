#include "output/report_writer.hpp"

#include "common/error.hpp"
#include "model/element_types.hpp"
#include "model/model.hpp"
#include "output/output_file.hpp"
#include "output/report_page.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace gapfem {
namespace {

using nlohmann::json;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool is_gap(const Model& m, ElemId e) {
  return element_info(m.mesh.elem_types[e]).family == ElementFamily::Gap;
}

/// A finite number for the page (JSON has no NaN or infinity).
double finite(double v) {
  return std::isfinite(v) ? v : 0.0;
}

} // namespace

ReportWriter::ReportWriter(std::filesystem::path path, std::string job,
                           std::vector<std::string> gaps)
    : _path(std::move(path)), _job(std::move(job)), _gap_names(std::move(gaps)) {}

void ReportWriter::begin(const Model& model) {
  for (const std::string& name : _gap_names) {
    std::vector<ElemId> found;
    if (const auto it = model.elsets.find(upper(name)); it != model.elsets.end()) {
      for (ElemId e : it->second)
        if (is_gap(model, e)) found.push_back(e);
      if (found.empty())
        throw InputError(SourceLocation{}, fmt::format("--report-gaps {}", name),
                         "this element set has no gap elements; name gap element labels or a "
                         "set of gaps");
    } else {
      for (ElemId e = 0; e < model.mesh.n_elements(); ++e)
        if (model.element_label(e).str() == upper(name)) found.push_back(e);
      if (found.empty())
        throw InputError(SourceLocation{}, fmt::format("--report-gaps {}", name),
                         "this is neither an element label nor an element set of the model");
      if (!is_gap(model, found[0]))
        throw InputError(SourceLocation{}, fmt::format("--report-gaps {}", name),
                         fmt::format("element {} is a {}, not a gap element", name,
                                     element_info(model.mesh.elem_types[found[0]]).name));
    }
    for (ElemId e : found)
      if (std::find(_named.begin(), _named.end(), e) == _named.end()) _named.push_back(e);
  }
}

void ReportWriter::save_state(ArchiveWriter& a) {
  a.pod(static_cast<std::uint64_t>(_attempts.size()));
  for (const Attempt& t : _attempts) {
    a.pod(t.step);
    a.pod(t.increment);
    a.pod(t.attempt);
    a.pod(t.total_time);
    a.pod(t.converged);
    a.vec(t.residuals);
  }
  a.vec(_contact_set);
  a.vec(_energies);
  a.strings(_history_columns);
  a.pod(static_cast<std::uint64_t>(_history.size()));
  for (const auto& row : _history) a.vec(row);
  a.pod(static_cast<std::uint64_t>(_steps.size()));
  for (const StepSummary& s : _steps) save(a, s);
  a.vec(_gap_ids);
  for (const History& h : _histories) {
    a.vec(h.time);
    a.vec(h.force);
    a.vec(h.clearance);
    a.vec(h.status);
    a.pod(h.peak);
  }
  a.vec(_kept);
  a.pod(_samples);
  a.pod(_pruned);
}

void ReportWriter::resume(const Model& model, int, ArchiveReader& a, const ResumeFiles&) {
  begin(model);
  _attempts.resize(a.get<std::uint64_t>());
  for (Attempt& t : _attempts) {
    a.pod(t.step);
    a.pod(t.increment);
    a.pod(t.attempt);
    a.pod(t.total_time);
    a.pod(t.converged);
    a.vec(t.residuals);
  }
  a.vec(_contact_set);
  a.vec(_energies);
  a.strings(_history_columns);
  _history.resize(a.get<std::uint64_t>());
  for (auto& row : _history) a.vec(row);
  _steps.resize(a.get<std::uint64_t>());
  for (StepSummary& s : _steps) load(a, s);
  a.vec(_gap_ids);
  _histories.resize(_gap_ids.size());
  for (History& h : _histories) {
    a.vec(h.time);
    a.vec(h.force);
    a.vec(h.clearance);
    a.vec(h.status);
    a.pod(h.peak);
  }
  a.vec(_kept);
  a.pod(_samples);
  a.pod(_pruned);
}

void ReportWriter::increment(const IncrementInfo& info) {
  _attempts.push_back({info.step, info.increment, info.attempts, info.total_time, info.converged,
                       info.residual_history});
  if (info.converged && info.energies) {
    const Energies& e = *info.energies;
    _energies.push_back({info.total_time, e.allke, e.allse, e.allie, e.allvd, e.allfd, e.allkl,
                         e.allwk, e.etotal()});
  }
  if (info.converged && info.history_columns) {
    // the columns of the first step with history output; a later step with others is not drawn
    if (_history_columns.empty()) _history_columns = *info.history_columns;
    if (*info.history_columns == _history_columns) {
      std::vector<double> row = {info.total_time};
      row.insert(row.end(), info.history.begin(), info.history.end());
      _history.push_back(std::move(row));
    }
  }
  if (!info.converged || info.gaps_closed < 0) return;
  _contact_set.emplace_back(info.total_time, info.gaps_closed);
  if (_gap_ids.empty()) {
    for (const GapSample& g : info.gaps) _gap_ids.push_back(g.elem);
    _histories.resize(_gap_ids.size());
    _kept.assign(_gap_ids.size(), 1);
  }
  const std::size_t n = std::min(info.gaps.size(), _gap_ids.size());
  for (std::size_t k = 0; k < n; ++k) {
    const GapSample& g = info.gaps[k];
    History& h = _histories[k];
    h.peak = std::max(h.peak, std::fabs(g.force));
    if (!_kept[k]) continue;
    h.time.push_back(static_cast<float>(info.total_time));
    h.force.push_back(g.force);
    h.clearance.push_back(g.clearance);
    h.status.push_back(static_cast<std::uint8_t>(g.status));
    ++_samples;
  }
  if (_samples > kMaxSamples && !_pruned) prune();
}

void ReportWriter::prune() {
  // keep the named gaps and the most loaded so far; the others' histories are dropped
  std::vector<std::size_t> order(_gap_ids.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  const std::size_t keep = std::min<std::size_t>(kKeptWhenPruned, order.size());
  std::partial_sort(
      order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep), order.end(),
      [&](std::size_t a, std::size_t b) { return _histories[a].peak > _histories[b].peak; });
  std::vector<char> kept(_gap_ids.size(), 0);
  for (std::size_t i = 0; i < keep; ++i) kept[order[i]] = 1;
  for (std::size_t k = 0; k < _gap_ids.size(); ++k)
    if (std::find(_named.begin(), _named.end(), _gap_ids[k]) != _named.end()) kept[k] = 1;
  for (std::size_t k = 0; k < _gap_ids.size(); ++k)
    if (!kept[k]) {
      const float peak = _histories[k].peak;
      _histories[k] = History{};
      _histories[k].peak = peak;
    }
  _kept = std::move(kept);
  _pruned = true;
}

void ReportWriter::end_step(const Model& model, int step_index, const StepSummary& summary) {
  _steps.push_back(summary);
}

void ReportWriter::modes(const Model& model, int step_index, const EigenSummary& modes) {
  _modes.emplace_back(model.steps[step_index].number, modes);
}

std::vector<ElemId> ReportWriter::plotted() const {
  if (!_named.empty()) return _named;
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < _gap_ids.size(); ++k)
    if (_kept[k]) order.push_back(k);
  const std::size_t n = std::min<std::size_t>(kMostLoaded, order.size());
  std::partial_sort(
      order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
      [&](std::size_t a, std::size_t b) { return _histories[a].peak > _histories[b].peak; });
  std::vector<ElemId> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(_gap_ids[order[i]]);
  return out;
}

std::string ReportWriter::data_json(const Model& model, const RunSummary& run) const {
  json d;
  d["job"] = _job;
  json gaps = json::array();
  for (ElemId e : plotted()) {
    const auto it = std::find(_gap_ids.begin(), _gap_ids.end(), e);
    if (it == _gap_ids.end()) continue;
    const History& h = _histories[static_cast<std::size_t>(it - _gap_ids.begin())];
    json g;
    g["label"] = fmt::format("{} ({})", model.element_label(e).str(),
                             element_info(model.mesh.elem_types[e]).name);
    g["time"] = h.time;
    g["force"] = h.force;
    g["clearance"] = h.clearance;
    g["status"] = h.status;
    gaps.push_back(std::move(g));
  }
  d["gaps"] = std::move(gaps);
  d["named"] = !_named.empty();
  d["pruned"] = _pruned;
  json cs = json::array();
  for (const auto& [t, n] : _contact_set) cs.push_back({finite(t), n});
  d["contact_set"] = std::move(cs);
  json en = json::array();
  for (const auto& e : _energies) {
    json row = json::array();
    for (double v : e) row.push_back(finite(v));
    en.push_back(std::move(row));
  }
  d["energies"] = std::move(en);
  json hist = json::array();
  for (const auto& row : _history) {
    json r = json::array();
    for (double v : row) r.push_back(finite(v));
    hist.push_back(std::move(r));
  }
  d["history_columns"] = _history_columns;
  d["history"] = std::move(hist);
  json at = json::array();
  for (const Attempt& a : _attempts) {
    json r = json::array();
    for (double v : a.residuals) r.push_back(finite(v));
    at.push_back({{"step", a.step},
                  {"increment", a.increment},
                  {"attempt", a.attempt},
                  {"time", finite(a.total_time)},
                  {"converged", a.converged},
                  {"residuals", std::move(r)}});
  }
  d["attempts"] = std::move(at);
  json time = json::array();
  for (int c = 0; c < kNumTimeCategories; ++c)
    time.push_back({std::string(time_category_name(static_cast<TimeCategory>(c))),
                    finite(run.stats.seconds[static_cast<std::size_t>(c)])});
  d["time_split"] = std::move(time);
  d["wall_seconds"] = finite(run.wall_seconds);
  return d.dump();
}

void ReportWriter::end(const Model& model, const RunSummary& summary) {
  output::ReportContent page;
  page.job = _job;
  page.data_json = data_json(model, summary);
  page.run = &summary;
  page.steps = &_steps;
  page.modes = &_modes;
  page.has_gaps = !_gap_ids.empty();
  page.has_energies = !_energies.empty();
  page.has_history = !_history.empty();
  page.named_gaps = !_named.empty();
  output::OutputFile out;
  out.open(_path, output::OutputFile::Mode::Replace);
  output::write_report_page(out.buffer(), page);
  out.close();
}

} // namespace gapfem
