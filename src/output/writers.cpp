#include "output/writers.hpp"

#include "common/error.hpp"
#include "output/dat_writer.hpp"
#include "output/frd_writer.hpp"
#include "output/json_writer.hpp"
#include "output/msg_writer.hpp"
#include "output/report_writer.hpp"
#include "output/sta_writer.hpp"
#include "output/substructure_recovery.hpp"
#include "output/terminal_writer.hpp"
#include "output/vtu_writer.hpp"

#include <fmt/format.h>
#include <system_error>

namespace gapfem {

std::vector<std::unique_ptr<ResultWriter>> make_result_writers(const WriterOptions& options) {
  std::vector<std::unique_ptr<ResultWriter>> writers;
  const std::filesystem::path dir = options.directory.empty() ? "." : options.directory;
  const std::string job = options.job.empty() ? "job" : options.job;
  if (options.dat || options.sta || options.json || options.vtu || options.frd || options.report) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
      throw AnalysisError(
          fmt::format("cannot create the output directory '{}': {}", dir.string(), ec.message()));
  }
  // The files that report progress (.sta, terminal) come last: an increment they report is
  // already in the result files.
  if (options.dat) writers.push_back(std::make_unique<DatWriter>(dir / (job + ".dat")));
  if (options.json)
    writers.push_back(std::make_unique<JsonWriter>(dir / (job + ".results.json"), job));
  if (options.vtu) writers.push_back(std::make_unique<VtuWriter>(dir, job));
  if (options.frd) writers.push_back(std::make_unique<FrdWriter>(dir / (job + ".frd"), job));
  if (options.json && options.substructure_recovery) // *SUBSTRUCTURE PATH
    writers.push_back(std::make_unique<SubstructureRecoveryWriter>(dir, job));
  if (options.report)
    writers.push_back(
        std::make_unique<ReportWriter>(dir / (job + ".report.html"), job, options.report_gaps));
  if (options.sta) writers.push_back(std::make_unique<StaWriter>(dir / (job + ".sta")));
  if (options.msg) writers.push_back(std::make_unique<MsgWriter>(dir / (job + ".msg")));
  if (options.terminal) writers.push_back(std::make_unique<TerminalWriter>());
  return writers;
}

} // namespace gapfem
