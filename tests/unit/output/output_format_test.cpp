// Formatting helpers shared by the writers (output/output_file.hpp).
#include "output/output_file.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <nlohmann/json.hpp>

namespace gapfem::output {
namespace {

std::string str(const fmt::memory_buffer& b) {
  return fmt::to_string(b);
}

TEST(OutputFormat, SpacedCapitals) {
  EXPECT_EQ(spaced("STATIC ANALYSIS"), "S T A T I C   A N A L Y S I S");
  EXPECT_EQ(spaced("node output"), "N O D E   O U T P U T");
  EXPECT_EQ(spaced("TEMPERATURE-DISPLACEMENT"), "T E M P E R A T U R E - D I S P L A C E M E N T");
}

TEST(OutputFormat, AbaqusE12) {
  // 1P E-format with 4 decimals, right-aligned in 12 columns (Abaqus .dat
  // tables).
  fmt::memory_buffer b;
  append_e12(b, 1.23456e-3);
  EXPECT_EQ(str(b), "  1.2346E-03");
  b.clear();
  append_e12(b, -2.9412e8);
  EXPECT_EQ(str(b), " -2.9412E+08");
  b.clear();
  append_e12(b, 0.0);
  EXPECT_EQ(str(b), "  0.0000E+00");
  b.clear();
  append_e12(b,
             -1e-100); // three-digit exponent: wider, but still separated by a blank
  EXPECT_EQ(str(b), " -1.0000E-100");
}

TEST(OutputFormat, JsonNumbersRoundTrip) {
  const double values[] = {0.1,
                           1.0 / 3.0,
                           -2.5e-308,
                           4.9406564584124654e-324,
                           1.7976931348623157e308,
                           123456789012345678.0,
                           -0.0};
  for (double v : values) {
    fmt::memory_buffer b;
    append_json_number(b, v);
    const auto j = nlohmann::json::parse(str(b));
    EXPECT_EQ(j.get<double>(), v) << str(b);
  }
  fmt::memory_buffer b;
  append_json_number(b, std::numeric_limits<double>::quiet_NaN());
  b.push_back(' ');
  append_json_number(b, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(str(b), "null null");
}

TEST(OutputFormat, JsonStringsEscaped) {
  const std::string s = "quote \" backslash \\ tab \t newline \n bell \x07 euro \xE2\x82\xAC";
  fmt::memory_buffer b;
  append_json_string(b, s);
  EXPECT_EQ(nlohmann::json::parse(str(b)).get<std::string>(), s);
  // Latin-1 bytes from an old deck are not UTF-8: replaced, and the result
  // still parses.
  b.clear();
  append_json_string(b, "Temp \xB0"
                        "C");
  EXPECT_EQ(nlohmann::json::parse(str(b)).get<std::string>(), "Temp \xEF\xBF\xBD"
                                                              "C");
}

TEST(OutputFormat, VoigtSlots) {
  EXPECT_EQ(voigt_slot("S11"), 0);
  EXPECT_EQ(voigt_slot("S22"), 1);
  EXPECT_EQ(voigt_slot("E33"), 2);
  EXPECT_EQ(voigt_slot("S12"), 3);
  EXPECT_EQ(voigt_slot("E13"), 4);
  EXPECT_EQ(voigt_slot("S23"), 5);
  EXPECT_EQ(voigt_slot("SF1"), -1);
  EXPECT_EQ(voigt_slot("HFL1"), -1);
}

TEST(OutputFormat, AverageOverPoints) {
  static constexpr std::array<std::string_view, 2> names = {"S11", "S22"};
  OutputBlock block{ElemVar::S, names, 3, {1.0, 10.0, 2.0, 20.0, 6.0, 60.0}};
  std::vector<double> avg;
  average_block(block, avg);
  EXPECT_EQ(avg, (std::vector<double>{3.0, 30.0})); // (1+2+6)/3, (10+20+60)/3
}

} // namespace
} // namespace gapfem::output
