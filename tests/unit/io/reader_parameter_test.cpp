// *PARAMETER and <name> substitution (io/inp/parameters.cpp): Python 3's arithmetic, checked
// against the values Python gives (written by hand: 7 / 2 = 3.5, 7 // 2 = 3, -7 // 2 = -4,
// -7 % 3 = 2, -2 ** 2 = -4, 2 ** 3 ** 2 = 512, ...), the text a value becomes, and a parametrised
// deck against its literal twin (the same answer) with one clear error per undefined name.
#include "io/inp/parameters.hpp"
#include "test_util.hpp"
#include "unit/io/reader_test_util.hpp"

#include <cmath>

namespace gapfem {
namespace {

using inp::evaluate_parameter;
using inp::ParameterValue;
using test::error_text;

ParameterValue eval(std::string_view e, const std::map<std::string, ParameterValue>& t = {}) {
  return evaluate_parameter(e, t);
}

TEST(ReaderParameter, PythonArithmetic) {
  EXPECT_EQ(eval("2 + 3*4"), ParameterValue(14LL));
  EXPECT_EQ(eval("7/2"), ParameterValue(3.5));
  EXPECT_EQ(eval("6/2"), ParameterValue(3.0)); // Python 3: a float
  EXPECT_EQ(eval("7//2"), ParameterValue(3LL));
  EXPECT_EQ(eval("-7//2"), ParameterValue(-4LL));
  EXPECT_EQ(eval("7.0//2"), ParameterValue(3.0));
  EXPECT_EQ(eval("-7 % 3"), ParameterValue(2LL));
  EXPECT_EQ(eval("2**10"), ParameterValue(1024LL));
  EXPECT_EQ(eval("2**-1"), ParameterValue(0.5));
  EXPECT_EQ(eval("-2**2"), ParameterValue(-4LL));
  EXPECT_EQ(eval("2**3**2"), ParameterValue(512LL));
  EXPECT_EQ(eval("(1 + 2) * (3 - 5)"), ParameterValue(-6LL));
  EXPECT_EQ(eval("1.5e3 + 1E-3"), ParameterValue(1500.001));
  EXPECT_DOUBLE_EQ(std::get<double>(eval("sin(pi/2)")), 1.0);
  EXPECT_DOUBLE_EQ(std::get<double>(eval("3.0*sin(45*pi/180.0)")), 3.0 * std::sqrt(0.5));
  EXPECT_EQ(eval("math.sqrt(16)"), ParameterValue(4.0));
  EXPECT_EQ(eval("max(1, 2.5, 2)"), ParameterValue(2.5));
  EXPECT_EQ(eval("min(3, 2)"), ParameterValue(2LL));
  EXPECT_EQ(eval("int(2.9) + abs(-3)"), ParameterValue(5LL));
  EXPECT_EQ(eval("'STEEL' + '-1'"), ParameterValue(std::string("STEEL-1")));
  EXPECT_EQ(eval("width*2", {{"width", 2.5}}), ParameterValue(5.0));
}

TEST(ReaderParameter, BadExpressionsSaySo) {
  const auto message = [](std::string_view e) {
    try {
      eval(e);
    } catch (const std::invalid_argument& x) {
      return std::string(x.what());
    }
    return std::string("(no error)");
  };
  EXPECT_CONTAINS(message("width * 2"), "'width' is not defined");
  EXPECT_CONTAINS(message("1 / 0"), "division by zero");
  EXPECT_CONTAINS(message("(1 + 2"), "')' is missing");
  EXPECT_CONTAINS(message("1 +"), "ends too early");
  EXPECT_CONTAINS(message("2 $ 3"), "unexpected '$'");
  EXPECT_CONTAINS(message("frobnicate(1)"), "frobnicate() is not known");
  EXPECT_CONTAINS(message("sqrt(-1)"), "sqrt() is not defined there");
}

TEST(ReaderParameter, ValuesBecomePythonsText) {
  EXPECT_EQ(inp::parameter_text(ParameterValue(12LL)), "12");
  EXPECT_EQ(inp::parameter_text(ParameterValue(2.5)), "2.5");
  EXPECT_EQ(inp::parameter_text(ParameterValue(2.0)), "2.0");
  EXPECT_EQ(inp::parameter_text(ParameterValue(0.1)), "0.1");
  EXPECT_EQ(inp::parameter_text(ParameterValue(std::string("S1"))), "S1");
}

/// A cantilever truss pair under a tip load, literal or parametrised.
std::string truss(bool parametric) {
  if (!parametric)
    return "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1.5, 0., 0.\n3, 1.5, 1., 0.\n*ELEMENT, TYPE=T3D2, "
           "ELSET=BARS\n1, 1, 2\n2, 3, 2\n*SOLID SECTION, ELSET=BARS, MATERIAL=STEEL\n0.02\n"
           "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*BOUNDARY\n1, 1, 3\n3, 1, 3\n2, 3, 3\n"
           "*STEP\n*STATIC\n*CLOAD\n2, 2, -12.5\n*END STEP\n";
  return "*HEADING\nparametric\n*PARAMETER\n# geometry\nlength = 1.5\nheight = length / 1.5  "
         "# 1.0\narea = 2 * 0.01\nmaterial = 'STEEL'\nmodulus = 2.1e5\nload = -100 / 8\n"
         "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, <length>, 0., 0.\n3, <length>, <height>, 0.\n"
         "*ELEMENT, TYPE=T3D2, ELSET=BARS\n1, 1, 2\n2, 3, 2\n*SOLID SECTION, ELSET=BARS, "
         "MATERIAL=<material>\n<area>\n*MATERIAL, NAME=<material>\n*ELASTIC\n<modulus>, 0.3\n"
         "*BOUNDARY\n1, 1, 3\n3, 1, 3\n2, 3, 3\n*STEP\n*STATIC\n*CLOAD\n2, 2, <load>\n*END STEP\n";
}

TEST(ReaderParameter, AParametrisedDeckGivesItsLiteralTwinsAnswer) {
  const JobResult a = test::run_deck(truss(true)), b = test::run_deck(truss(false));
  ASSERT_EQ(a.exit_code, 0) << a.error;
  ASSERT_EQ(b.exit_code, 0) << b.error;
  const Frame* fa = a.step_end(1);
  const Frame* fb = b.step_end(1);
  ASSERT_TRUE(fa && fb);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(test::U(a, *fa, 2)[c], test::U(b, *fb, 2)[c]);
  EXPECT_LT(test::U(a, *fa, 2)[1], -1e-4);
}

TEST(ReaderParameter, UndefinedNamesAndBadDefinitionsAreOneErrorEach) {
  std::string d = truss(true);
  d.replace(d.find("<load>"), 6, "<lod>");
  const std::string e = error_text(d);
  EXPECT_CONTAINS(e, "*CLOAD: <lod>: this parameter is not defined; define it with *PARAMETER");
  EXPECT_EQ(e.find("not a number"), std::string::npos) << e; // no follow-on error
  d = truss(true);
  d.replace(d.find("load = -100 / 8"), 15, "load = -100 / 0");
  EXPECT_CONTAINS(error_text(d), "*PARAMETER: parameter load: division by zero");
  d = truss(true);
  d.replace(d.find("area = 2 * 0.01"), 15, "2 * 0.01 = area");
  EXPECT_CONTAINS(error_text(d), "a parameter definition is `name = expression`");
}

} // namespace
} // namespace gapfem
