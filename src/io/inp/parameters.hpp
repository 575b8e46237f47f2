#pragma once
/// @file parameters.hpp
/// Abaqus's parametric input (*PARAMETER, "Parametric input" in the Analysis User's Guide): data
/// lines `name = expression` define parameters in deck order, Python's syntax, and `<name>` in any
/// later keyword-line value or data line is replaced by the parameter's value before the deck is
/// read. The expressions are the arithmetic part of Python 3 (numbers, strings, + - * / // % **,
/// parentheses, the math module's functions and constants with or without `math.`, abs, min, max,
/// int, float, round); docs/keywords.md, "*PARAMETER".
#include "io/inp/diagnostics.hpp"
#include "io/inp/lexer.hpp"

#include <map>
#include <string>
#include <variant>

namespace gapfem::inp {

/// A parameter's value: a Python int, float or str.
using ParameterValue = std::variant<long long, double, std::string>;

/// Evaluates one expression with the parameters defined so far; throws std::invalid_argument with
/// a sentence naming what is wrong.
ParameterValue evaluate_parameter(std::string_view expression,
                                  const std::map<std::string, ParameterValue>& parameters);

/// The text `<name>` becomes: Python's str() of the value (an int as digits, a float with the
/// digits that read back to it, a string as it is).
std::string parameter_text(const ParameterValue& value);

/// Reads the deck's *PARAMETER blocks, removes them, and substitutes `<name>` in every later
/// keyword-line value and data line. Errors (a bad definition, an undefined name) go to `diag`.
/// Decks without *PARAMETER are left as they are.
void substitute_parameters(Deck& deck, Diagnostics& diag);

} // namespace gapfem::inp
