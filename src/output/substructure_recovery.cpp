#include "output/substructure_recovery.hpp"

#include "common/error.hpp"
#include "common/safe_file.hpp"
#include "model/model.hpp"
#include "output/output_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>

namespace gapfem {

namespace {

/// One frame of a recovered substructure as a JSON object.
void append_frame(fmt::memory_buffer& out, const Frame& f, const RecoveredSubstructure& r) {
  fmt::format_to(fmt::appender(out),
                 "\n{{\"step\":{},\"increment\":{},\"step_time\":{},\"total_time\":{},\"nodes\":{{",
                 f.step, f.increment, f.step_time, f.total_time);
  bool first = true;
  for (const auto& [node, x] : r.nodes) {
    fmt::format_to(fmt::appender(out), "{}\"{}\":{{\"U\":", first ? "" : ",", node);
    output::append_json_array(out, std::span<const double>(x.data(), 3));
    out.append(std::string_view(",\"UR\":"));
    output::append_json_array(out, std::span<const double>(x.data() + 3, 3));
    out.push_back('}');
    first = false;
  }
  out.push_back('}');
  if (r.stresses) { // stresses and strains of the substructure's elements
    out.append(std::string_view(",\"elements\":{"));
    first = true;
    for (const RecoveredSubstructure::Element& e : r.elements) {
      fmt::format_to(fmt::appender(out), "{}\"{}\":{{\"type\":\"{}\"", first ? "" : ",", e.label,
                     e.type);
      for (const auto& [var, avg] : e.averages) {
        fmt::format_to(fmt::appender(out), ",\"{}\":", elem_var_name(var));
        output::append_json_array(out, avg);
      }
      out.push_back('}');
      first = false;
    }
    out.push_back('}');
  }
  out.push_back('}');
}

} // namespace

SubstructureRecoveryWriter::SubstructureRecoveryWriter(std::filesystem::path directory,
                                                       std::string job)
    : _dir(std::move(directory)), _job(std::move(job)) {}

SubstructureRecoveryWriter::~SubstructureRecoveryWriter() = default;

void SubstructureRecoveryWriter::begin(const Model&) {
  _documents.clear();
}

void SubstructureRecoveryWriter::frame(const Model&, int, const Frame& f) {
  for (const RecoveredSubstructure& r : f.substructures) {
    auto [it, fresh] = _documents.try_emplace(r.elem);
    Document& d = it->second;
    if (fresh) {
      std::string label = r.label;
      std::replace(label.begin(), label.end(), '.', '_');
      d.file = _dir / fmt::format("{}_{}_{}.results.json", _job, r.type, label);
    } else {
      d.frames.push_back(',');
    }
    d.head.label = r.label;
    d.head.type = r.type;
    d.head.library = r.library;
    d.head.deck = r.deck;
    d.head.stresses = r.stresses;
    d.head.note = r.note;
    append_frame(d.frames, f, r);
    write(d);
  }
}

void SubstructureRecoveryWriter::write(const Document& d) const {
  const RecoveredSubstructure& r = d.head;
  fmt::memory_buffer doc;
  fmt::format_to(fmt::appender(doc), "{{\"schema\":\"gapfem.substructure_recovery/1\",\"job\":");
  output::append_json_string(doc, _job);
  fmt::format_to(fmt::appender(doc), ",\"element\":");
  output::append_json_string(doc, r.label);
  fmt::format_to(fmt::appender(doc), ",\"substructure\":");
  output::append_json_string(doc, r.type);
  fmt::format_to(fmt::appender(doc), ",\"library\":");
  output::append_json_string(doc, r.library);
  fmt::format_to(fmt::appender(doc), ",\"generation_deck\":");
  output::append_json_string(doc, r.deck);
  fmt::format_to(fmt::appender(doc), ",\"stresses\":{},\"note\":", r.stresses ? "true" : "false");
  output::append_json_string(doc, r.note);
  doc.append(std::string_view(",\"frames\":["));
  doc.append(d.frames.data(), d.frames.data() + d.frames.size());
  doc.append(std::string_view("\n]}\n"));
  // aside, then renamed: the file is always one complete document (never through a link)
  if (!files::write_replace(d.file, std::string_view(doc.data(), doc.size())))
    throw AnalysisError(fmt::format("cannot write '{}': {}; free space and run again",
                                    d.file.string(), std::strerror(errno)));
}

void SubstructureRecoveryWriter::end(const Model&, const RunSummary&) {}

} // namespace gapfem
