// A failure no smaller increment can cure (the linear solver out of memory, a result file that
// cannot be written) ends the run with complete result files: job.results.json stays valid JSON
// with "completed": false and the reason, job.dat ends with the error, and the frames of the
// converged increments are kept.
#include "common/error.hpp"
#include "io/inp/reader.hpp"
#include "output/writers.hpp"
#include "solver/analysis.hpp"
#include "test_util.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace gapfem;

namespace {

using gapfem::test::slurp;

const char* kDeck = R"(*HEADING
spring and gap, three fixed increments
*NODE
1, 0., 0., 0.
2, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SPR
1, 1
*SPRING, ELSET=SPR
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G
2, 1, 2
*GAP, ELSET=G
0.5, 0., -1., 0., 1.
*BOUNDARY
2, 1, 3
1, 1, 1
1, 3, 3
*STEP
*STATIC, DIRECT
0.25, 1.
*CLOAD
1, 2, -100.
*NODE PRINT
U
*END STEP
)";

/// Stands for a solver failure: throws AnalysisError when the given increment is reported.
class FailingWriter final : public ResultWriter {
 public:
  explicit FailingWriter(int increment) : _increment(increment) {}
  void increment(const IncrementInfo& info) override {
    if (info.increment == _increment)
      throw AnalysisError("UMFPACK LU factorisation ran out of memory on 3 equations");
  }

 private:
  int _increment;
};

} // namespace

TEST(AnalysisFailure, FatalErrorInsideAStepLeavesCompleteResultFiles) {
  const auto dir = test::test_dir();
  const Model model = read_deck_string(kDeck, "job.inp");
  WriterOptions wo;
  wo.directory = dir;
  wo.job = "job";
  wo.vtu = false;
  auto writers = make_result_writers(wo);
  FailingWriter failing(3);
  std::vector<ResultWriter*> ptrs;
  for (auto& w : writers) ptrs.push_back(w.get());
  ptrs.push_back(&failing);
  Analysis analysis(model, ptrs);
  EXPECT_THROW(analysis.run(), AnalysisError);

  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(slurp(dir / "job.results.json")));
  EXPECT_FALSE(j["summary"]["completed"].get<bool>());
  EXPECT_NE(j["summary"]["failure"].get<std::string>().find("out of memory"), std::string::npos);
  ASSERT_EQ(j["steps"].size(), 1u);
  EXPECT_FALSE(j["steps"][0]["converged"].get<bool>());
  // increments 1 to 3 converged and were written (a converged increment is reported after its
  // frame is stored); the failure came as increment 3 was reported
  ASSERT_EQ(j["steps"][0]["frames"].size(), 3u);
  EXPECT_DOUBLE_EQ(j["steps"][0]["frames"][2]["step_time"].get<double>(), 0.75);
  EXPECT_EQ(j["summary"]["last_converged"]["increment"].get<int>(), 3);

  const std::string dat = slurp(dir / "job.dat");
  EXPECT_NE(dat.find("out of memory"), std::string::npos);
  EXPECT_NE(dat.find("THE ANALYSIS HAS NOT BEEN COMPLETED"), std::string::npos);
}
