#include "output/sta_writer.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>

namespace gapfem {

StaWriter::StaWriter(std::filesystem::path path) : _path(std::move(path)) {}

void StaWriter::begin(const Model& model) {
  _out.open(_path);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  localtime_r(&now, &tm);
  char date[64];
  std::strftime(date, sizeof date, "DATE %d-%b-%Y TIME %H:%M:%S", &tm);
  auto out = std::back_inserter(_out.buffer());
  fmt::format_to(out, "{:<42}{}\n", fmt::format("gapfem {}", GAPFEM_VERSION), date);
  fmt::format_to(out, " SUMMARY OF JOB INFORMATION:\n");
  // Abaqus's columns; DOF MONITOR holds the *MONITOR value (blank without one)
  fmt::format_to(out, " STEP  INC ATT SEVERE EQUIL TOTAL  TOTAL      STEP       INC OF     DOF\n");
  fmt::format_to(out,
                 "               DISCON ITERS ITERS  TIME       TIME       TIME       MONITOR\n");
  fmt::format_to(out, "               ITERS\n");
  _out.flush();
}

void StaWriter::save_state(ArchiveWriter& a) {
  a.pod(static_cast<std::uint64_t>(_out.position()));
}

void StaWriter::resume(const Model&, int, ArchiveReader& a, const ResumeFiles& from) {
  _out.open_resumed(_path, from.file(".sta"), a.get<std::uint64_t>());
}

char StaWriter::attempt_marker(const IncrementInfo& info) {
  // Abaqus marks an attempt that did not converge (and was cut back) with "U" after ATT. An
  // attempt that converged but changed a temperature by more than DELTMX is repeated smaller
  // without having failed: gapfem marks it "D".
  if (info.deltmx_exceeded) return 'D';
  return info.converged ? ' ' : 'U';
}

void StaWriter::increment(const IncrementInfo& info) {
  if (!_out.is_open()) return;
  const int severe = std::max(0, info.severe_discontinuities);
  const int equil = std::max(0, info.iterations - severe);
  // like Abaqus, a rejected attempt shows the times reached so far (the last converged
  // increment's), with the increment it tried in the last column: time never runs backwards
  const double back = info.converged ? 0.0 : info.dt;
  const std::string inc = fmt::format("{:.5G}", info.dt);
  fmt::format_to(std::back_inserter(_out.buffer()),
                 "{:>4}{:>6}{:>4}{}{:>5}{:>6}{:>6}  {:<11}{:<11}{}", info.step, info.increment,
                 info.attempts, attempt_marker(info), severe, equil, info.iterations,
                 fmt::format("{:.5G}", info.total_time - back),
                 fmt::format("{:.5G}", info.step_time - back),
                 info.monitor ? fmt::format("{:<11}", inc) : inc);
  if (info.monitor) fmt::format_to(std::back_inserter(_out.buffer()), "{:.4E}", *info.monitor);
  if (info.converged && info.energies) // dynamic steps, after Abaqus's columns
    fmt::format_to(std::back_inserter(_out.buffer()), "  ALLKE={:.4E} ETOTAL={:.4E}",
                   info.energies->allke, info.energies->etotal());
  _out.buffer().push_back('\n');
  _out.flush();
}

void StaWriter::end(const Model& model, const RunSummary& summary) {
  if (!_out.is_open()) return;
  auto out = std::back_inserter(_out.buffer());
  if (summary.completed) {
    fmt::format_to(out, "\n\n THE ANALYSIS HAS COMPLETED SUCCESSFULLY\n");
  } else {
    fmt::format_to(out, "\n\n ***ERROR: {}\n",
                   summary.failure.empty() ? "the analysis stopped" : summary.failure);
    fmt::format_to(out, "\n THE ANALYSIS HAS NOT BEEN COMPLETED\n");
  }
  _out.close();
}

} // namespace gapfem
