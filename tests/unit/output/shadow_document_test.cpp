// ShadowDocument: a growing body plus a changing tail, published as one complete file after
// every change (docs/results.md, "Results that survive"), checked against the document it must
// equal after each of many random publications, with an injected full disk at random points.
#include "common/error.hpp"
#include "output/output_file.hpp"
#include "output/shadow_document.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <sys/stat.h>

namespace gapfem {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh(const char* name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "gapfem_shadow" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string random_text(std::mt19937& rng, std::size_t n) {
  std::uniform_int_distribution<int> c('a', 'z');
  std::string s(n, ' ');
  for (char& ch : s) ch = static_cast<char>(c(rng));
  return s;
}

TEST(ShadowDocument, EveryPublicationIsTheWholeDocument) {
  const fs::path dir = fresh("every");
  const fs::path body = dir / "doc.part", final = dir / "doc.json";
  std::mt19937 rng(11);
  std::uniform_int_distribution<std::size_t> grow(0, 20000), tail_len(1, 300);
  output::ShadowDocument doc;
  doc.begin(final);
  std::string expected_body;
  std::ofstream part(body, std::ios::binary);
  for (int i = 0; i < 200; ++i) {
    const std::string add = random_text(rng, grow(rng));
    part << add;
    part.flush();
    expected_body += add;
    const std::string tail = random_text(rng, tail_len(rng));
    doc.publish(body, expected_body.size(), tail);
    ASSERT_EQ(read_all(final), expected_body + tail) << "publication " << i;
    struct stat st {};
    ASSERT_EQ(::stat(final.c_str(), &st), 0);
    EXPECT_EQ(st.st_nlink, 2u); // the published document is one of the two shadows
  }
  doc.finish();
  EXPECT_FALSE(fs::exists(dir / "doc.json.a"));
  EXPECT_FALSE(fs::exists(dir / "doc.json.b"));
  struct stat st {};
  ASSERT_EQ(::stat(final.c_str(), &st), 0);
  EXPECT_EQ(st.st_nlink, 1u);
}

TEST(ShadowDocument, AFullDiskKeepsThePreviousDocument) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 30; ++trial) {
    const fs::path dir = fresh("full");
    const fs::path body = dir / "doc.part", final = dir / "doc.json";
    output::ShadowDocument doc;
    doc.begin(final);
    std::string expected_body, published;
    std::ofstream part(body, std::ios::binary);
    std::uniform_int_distribution<long long> budget(0, 60000);
    bool failed = false;
    for (int i = 0; i < 20 && !failed; ++i) {
      const std::string add = random_text(rng, 3000 + 100 * i);
      part << add;
      part.flush();
      expected_body += add;
      const std::string tail = "tail " + std::to_string(i);
      if (i == 10) output::testing::limit_writes(budget(rng)); // the disk fills up here
      try {
        doc.publish(body, expected_body.size(), tail);
        published = expected_body + tail;
      } catch (const AnalysisError& e) {
        failed = true;
        EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("doc.json"), std::string::npos);
      }
      ASSERT_EQ(read_all(final), published) << "trial " << trial << ", publication " << i;
    }
    output::testing::limit_writes(-1);
    doc.finish();
    EXPECT_EQ(read_all(final), published);
  }
}

TEST(ShadowDocument, BeginRemovesWhatAKilledRunLeft) {
  const fs::path dir = fresh("stale");
  const fs::path final = dir / "doc.json";
  for (const char* s : {".a", ".b", ".tmp"})
    std::ofstream(dir / (std::string("doc.json") + s)) << "old";
  output::ShadowDocument doc;
  doc.begin(final);
  for (const char* s : {".a", ".b", ".tmp"})
    EXPECT_FALSE(fs::exists(dir / (std::string("doc.json") + s))) << s;
}

} // namespace
} // namespace gapfem
