// job.results.json: the end of a step (status and self-checks), the document's tail (element
// types, run summary) and the checkpoints that keep the file one complete document at all times.
#include "model/model.hpp"
#include "output/json_writer.hpp"

#include <system_error>

namespace gapfem {
namespace {

using output::append_json_array;
using output::append_json_number;
using output::append_json_string;

void key(fmt::memory_buffer& b, std::string_view k) {
  output::append_json_key(b, k);
}
void number_field(fmt::memory_buffer& b, std::string_view k, double v) {
  output::append_json_field(b, k, v);
}

/// An element key as JSON: null for none, the number of a flat deck, the string "INSTANCE.n" of a
/// part instance.
void label_or_null(fmt::memory_buffer& b, const Model& model, Label l) {
  if (l == 0)
    b.append(std::string_view("null"));
  else if (key_instance(l) == 0)
    fmt::format_to(fmt::appender(b), "{}", l);
  else
    append_json_string(b, model.label_of_key(l).str());
}

} // namespace

void JsonWriter::modes(const Model&, int, const EigenSummary& sum) {
  fmt::memory_buffer b;
  b.append(std::string_view(",\"modes\":["));
  if (sum.buckling) { // load multipliers
    for (const ModeInfo& m : sum.modes) {
      fmt::format_to(fmt::appender(b), "{}{{\"mode\":{}", m.mode > 1 ? "," : "", m.mode);
      number_field(b, "eigenvalue", m.eigenvalue);
      b.push_back('}');
    }
    b.append(std::string_view("],\"buckling\":true"));
    _modes_json = fmt::to_string(b);
    return;
  }
  for (const ModeInfo& m : sum.modes) {
    fmt::format_to(fmt::appender(b), "{}{{\"mode\":{}", m.mode > 1 ? "," : "", m.mode);
    number_field(b, "eigenvalue", m.eigenvalue);
    number_field(b, "frequency", m.frequency());
    number_field(b, "circular_frequency", m.circular());
    number_field(b, "generalized_mass", m.generalized_mass);
    b.push_back(',');
    key(b, "participation");
    append_json_array(b, m.participation);
    b.push_back(',');
    key(b, "effective_mass");
    append_json_array(b, m.effective_mass);
    b.push_back('}');
  }
  b.push_back(']');
  b.push_back(',');
  key(b, "total_effective_mass");
  append_json_array(b, sum.total_effective_mass);
  b.push_back(',');
  key(b, "model_mass");
  append_json_array(b, sum.model_mass);
  fmt::format_to(fmt::appender(b), ",\"rigid_body_modes\":{},\"normalization\":\"{}\"",
                 sum.rigid_body_modes, sum.mass_normalized ? "MASS" : "DISPLACEMENT");
  number_field(b, "shift", sum.shift);
  _modes_json = fmt::to_string(b);
}

void JsonWriter::close_step(const StepSummary* s) {
  append_step_end(_out.buffer(), s, "the step was not finished");
  _step_open = false;
}

namespace {

/// `{"columns":[…],"rows":[[…],…]}`
template <typename Rows>
void append_table(fmt::memory_buffer& b, const std::vector<std::string>& columns,
                  const Rows& rows) {
  b.append(std::string_view("{\"columns\":["));
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (c) b.push_back(',');
    append_json_string(b, columns[c]);
  }
  b.append(std::string_view("],\"rows\":["));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    b.append(i ? std::string_view(",[") : std::string_view("["));
    for (std::size_t k = 0; k < rows[i].size(); ++k) {
      if (k) b.push_back(',');
      append_json_number(b, rows[i][k]);
    }
    b.push_back(']');
  }
  b.append(std::string_view("]}"));
}

} // namespace

void JsonWriter::append_history(fmt::memory_buffer& b) const {
  if (_energy_history.empty() && _history_rows.empty()) return;
  static const std::vector<std::string> kEnergyColumns = {
      "increment", "step_time", "total_time", "ALLKE",  "ALLIE", "ALLVD",
      "ALLFD",     "ALLKL",     "ALLWK",      "ETOTAL", "ALLSE", "ALLAE"};
  b.append(std::string_view(",\"history\":{"));
  if (!_energy_history.empty()) {
    b.append(std::string_view("\"energies\":"));
    append_table(b, kEnergyColumns, _energy_history);
  }
  if (!_history_rows.empty()) {
    if (!_energy_history.empty()) b.push_back(',');
    std::vector<std::string> columns = {"increment", "step_time", "total_time"};
    columns.insert(columns.end(), _history_columns.begin(), _history_columns.end());
    b.append(std::string_view("\"values\":"));
    append_table(b, columns, _history_rows);
  }
  b.push_back('}');
}

void JsonWriter::append_step_end(fmt::memory_buffer& b, const StepSummary* s,
                                 std::string_view unfinished) const {
  b.push_back(']');
  b.append(_modes_json);
  append_history(b);
  if (!s) {
    b.append(std::string_view(",\"converged\":false,\"failure\":"));
    append_json_string(b, unfinished);
    b.push_back('}');
    return;
  }
  fmt::format_to(fmt::appender(b),
                 ",\"converged\":{},\"increments\":{},\"attempts\":{},"
                 "\"iterations\":{},\"failure\":",
                 s->converged, s->increments, s->attempts, s->iterations);
  if (s->converged && s->failure.empty())
    b.append(std::string_view("null"));
  else
    append_json_string(b, s->failure.empty() ? "the step did not converge" : s->failure);

  const StepChecks& c = s->checks;
  fmt::format_to(fmt::appender(b),
                 ",\"checks\":{{\"gaps\":{{\"total\":{},\"open\":{},\"closed\":"
                 "{},\"stick\":{},"
                 "\"slip\":{}}}",
                 c.n_gaps, c.n_open, c.n_closed, c.n_stick, c.n_slip);
  b.append(std::string_view(",\"max_penetration\":{\"value\":"));
  append_json_number(b, c.max_penetration);
  b.append(std::string_view(",\"element\":"));
  label_or_null(b, *_model, c.max_penetration_elem);
  b.append(std::string_view("},\"max_tensile_force\":{\"value\":"));
  append_json_number(b, c.max_tensile_force);
  b.append(std::string_view(",\"element\":"));
  label_or_null(b, *_model, c.max_tensile_elem);
  b.append(std::string_view("},\"equilibrium\":{\"reaction_sum\":"));
  append_json_array(b, c.reaction_sum);
  b.append(std::string_view(",\"applied_sum\":"));
  append_json_array(b, c.applied_sum);
  number_field(b, "error", c.equilibrium_error);
  number_field(b, "force_scale", c.force_scale);
  b.append(std::string_view(",\"relative_error\":"));
  if (c.force_scale > 0)
    append_json_number(b, c.relative_equilibrium);
  else
    b.append(std::string_view("null"));
  b.append(std::string_view("},\"heat_balance\":"));
  if (c.thermal) {
    b.append(std::string_view("{\"reaction_flux_sum\":"));
    append_json_number(b, c.reaction_flux_sum);
    number_field(b, "applied_flux_sum", c.applied_flux_sum);
    number_field(b, "stored_heat", c.stored_heat);
    number_field(b, "error", c.heat_balance_error);
    number_field(b, "heat_scale", c.heat_scale);
    b.append(std::string_view(",\"relative_error\":"));
    if (c.heat_scale > 0)
      append_json_number(b, c.relative_heat_balance);
    else
      b.append(std::string_view("null"));
    b.push_back('}');
  } else {
    b.append(std::string_view("null"));
  }
  number_field(b, "max_damping_force", c.max_damping_force);
  if (c.hourglass) {
    b.append(std::string_view(",\"energy\":{\"ALLAE\":"));
    append_json_number(b, c.allae);
    number_field(b, "ALLSE", c.allse);
    b.push_back('}');
  }
  if (c.dynamic) {
    b.append(std::string_view(",\"energy_balance\":{\"change\":"));
    append_json_number(b, c.energy_change);
    number_field(b, "scale", c.energy_scale);
    b.append(c.conserving ? std::string_view(",\"conserving\":true")
                          : std::string_view(",\"conserving\":false"));
    output::append_energies(b, c.energies);
    b.push_back('}');
  }
  if (c.stabilized) {
    b.append(std::string_view(",\"stabilization\":{\"damping_factor\":"));
    append_json_number(b, c.stabilization_factor);
    number_field(b, "ALLSD", c.allsd);
    number_field(b, "ALLIE", c.allie);
    b.push_back('}');
  }
  b.append(std::string_view("}}"));
}

void JsonWriter::append_tail(fmt::memory_buffer& b, const RunSummary& summary) const {
  b.append(std::string_view("],\n\"element_types\":{"));
  bool first_type = true;
  for (const auto& [type, tc] : _components) {
    if (!tc.seen) continue;
    if (!first_type) b.push_back(',');
    first_type = false;
    fmt::format_to(fmt::appender(b), "\"{}\":{{", type.second);
    bool first_var = true;
    for (std::size_t v = 0; v < tc.names.size(); ++v) {
      if (tc.names[v].empty()) continue;
      if (!first_var) b.push_back(',');
      first_var = false;
      key(b, elem_var_name(static_cast<ElemVar>(v)));
      b.push_back('[');
      for (std::size_t i = 0; i < tc.names[v].size(); ++i) {
        if (i) b.push_back(',');
        append_json_string(b, tc.names[v][i]);
      }
      b.push_back(']');
    }
    b.push_back('}');
  }
  const RunStatistics& st = summary.stats;
  fmt::format_to(fmt::appender(b),
                 "}},\n\"summary\":{{\"completed\":{},\"failure\":", summary.completed);
  if (summary.completed && summary.failure.empty())
    b.append(std::string_view("null"));
  else
    append_json_string(b, summary.failure);
  number_field(b, "wall_seconds", summary.wall_seconds);
  fmt::format_to(fmt::appender(b),
                 ",\"increments\":{},\"attempts\":{},\"iterations\":{},"
                 "\"factorizations\":{},\"factor_updates\":{},"
                 "\"linear_solves\":{},\"evaluations\":{},\"tangent_assemblies\":{},"
                 "\"peak_memory_kb\":{},\"seconds\":{{",
                 st.increments, st.attempts, st.iterations, st.factorizations, st.factor_updates,
                 st.linear_solves, st.evaluations, st.tangent_assemblies, summary.peak_memory_kb);
  for (int c = 0; c < kNumTimeCategories; ++c) {
    if (c) b.push_back(',');
    append_json_string(b, time_category_name(static_cast<TimeCategory>(c)));
    b.push_back(':');
    append_json_number(b, st.seconds[c]);
  }
  b.append(std::string_view("},\"last_converged\":"));
  if (_has_last) {
    fmt::format_to(fmt::appender(b), "{{\"step\":{},\"increment\":{}", _last.step, _last.increment);
    number_field(b, "step_time", _last.step_time);
    number_field(b, "total_time", _last.total_time);
    b.push_back('}');
  } else {
    b.append(std::string_view("null"));
  }
  // time spent publishing the document after increments (part of "output")
  number_field(b, "publication_seconds", _publish_seconds);
  b.append(std::string_view(",\"warnings\":["));
  for (std::size_t i = 0; i < summary.warnings.size(); ++i) {
    if (i) b.push_back(',');
    append_json_string(b, summary.warnings[i]);
  }
  b.append(std::string_view("]}}\n"));
}

std::filesystem::path JsonWriter::part_path() const {
  std::filesystem::path p = _path;
  p += ".part";
  return p;
}

void JsonWriter::increment(const IncrementInfo& info) {
  ++_seen.attempts;
  _seen.iterations += info.iterations;
  if (!info.converged) return;
  if (info.history_columns) {
    if (_history_rows.empty()) _history_columns = *info.history_columns;
    std::vector<double> row = {static_cast<double>(info.increment), info.step_time,
                               info.total_time};
    row.insert(row.end(), info.history.begin(), info.history.end());
    _history_rows.push_back(std::move(row));
  }
  if (info.energies) {
    const Energies& e = *info.energies;
    _energy_history.push_back({static_cast<double>(info.increment), info.step_time, info.total_time,
                               e.allke, e.allie, e.allvd, e.allfd, e.allkl, e.allwk, e.etotal(),
                               e.allse, e.allae});
  }
  ++_seen.increments;
  _last = info;
  _has_last = true;
  checkpoint();
}

void JsonWriter::publish(std::string_view suffix) {
  if (_failed || !_out.is_open()) return;
  try {
    const Stopwatch watch;
    _out.flush();
    _shadow.publish(_out.path(), std::filesystem::file_size(_out.path()), suffix);
    _publish_seconds += watch.seconds();
  } catch (const AnalysisError&) {
    _failed = true; // the previous complete document stays; the first error is reported
    _shadow.finish();
    throw;
  } catch (const std::filesystem::filesystem_error& e) {
    _failed = true;
    _shadow.finish();
    throw AnalysisError(
        fmt::format("cannot write results file '{}': {}", _path.string(), e.code().message()));
  }
}

void JsonWriter::checkpoint() {
  fmt::memory_buffer suffix;
  if (_step_open) append_step_end(suffix, nullptr, "the step is running, or the run stopped in it");
  RunSummary partial;
  partial.completed = false;
  partial.failure = "the analysis is running, or it stopped before the end: this document holds "
                    "the increments completed so far";
  partial.wall_seconds = _watch.seconds();
  partial.stats = _seen;
  partial.warnings = _model->warnings;
  append_tail(suffix, partial);
  publish(std::string_view(suffix.data(), suffix.size()));
}

void JsonWriter::end(const Model& model, const RunSummary& summary) {
  if (_failed || !_out.is_open()) return;
  if (_step_open) close_step(nullptr);
  fmt::memory_buffer suffix;
  append_tail(suffix, summary);
  publish(std::string_view(suffix.data(), suffix.size()));
  _shadow.finish();
  _out.close();
  std::error_code ec;
  std::filesystem::remove(part_path(), ec);
}

} // namespace gapfem
