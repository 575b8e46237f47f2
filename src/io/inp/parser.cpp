#include "io/inp/parser.hpp"

#include "io/inp/handlers.hpp"
#include "io/inp/spelling.hpp"

#include <array>
#include <fmt/format.h>
#include <unordered_map>
#include <utility>

namespace gapfem::inp {
namespace {

constexpr unsigned bit(Parent p) {
  return 1u << static_cast<unsigned>(p);
}
constexpr unsigned kMaterial = bit(Parent::Material);
constexpr unsigned kGap = bit(Parent::Gap);
constexpr unsigned kOutput = bit(Parent::FieldOutput) | bit(Parent::HistoryOutput);
constexpr unsigned kFriction = bit(Parent::Gap) | bit(Parent::ChangeFriction);
constexpr unsigned kCoupling = bit(Parent::Coupling);
constexpr unsigned kBeam = bit(Parent::BeamSection);
constexpr unsigned kSection = kBeam | bit(Parent::ShellSection);
constexpr unsigned kUserElement = bit(Parent::UserElement);

using W = Where;
using P = Parent;

// clang-format off
constexpr std::array<KeywordSpec, 123> kTable = {{
  // model data: mesh
  {"*HEADING", handle_heading, W::Model, ""},
  {"*PREPRINT", handle_print_control, W::Model, "*"},
  {"*PART", handle_part, W::Model, "NAME"},
  {"*END PART", handle_end_part, W::Model, ""},
  {"*ASSEMBLY", handle_assembly, W::Model, "NAME"},
  {"*END ASSEMBLY", handle_end_assembly, W::Model, ""},
  {"*INSTANCE", handle_instance, W::Model, "NAME|PART"},
  {"*END INSTANCE", handle_end_instance, W::Model, ""},
  {"*NODE", handle_node, W::Model, "NSET|INPUT|SYSTEM"},
  {"*SYSTEM", handle_system, W::Model, ""},
  {"*NGEN", handle_ngen, W::Model, "LINE|NSET|SYSTEM"},
  {"*NFILL", handle_nfill, W::Model, "NSET|BIAS|SINGULAR|TWO STEP"},
  {"*ELGEN", handle_elgen, W::Model, "ELSET"},
  {"*ELEMENT", handle_element, W::Model, "TYPE|ELSET|INPUT|FILE"},
  {"*NSET", handle_nset, W::Model, "NSET|GENERATE|INPUT|UNSORTED|INSTANCE|INTERNAL"},
  {"*ELSET", handle_elset, W::Model, "ELSET|GENERATE|INPUT|UNSORTED|INSTANCE|INTERNAL"},
  {"*SURFACE", handle_surface, W::Model, "NAME|TYPE|INTERNAL"},
  // materials and properties
  {"*MATERIAL", handle_material, W::Model, "NAME", 0, P::Material},
  {"*ELASTIC", handle_elastic, W::Model, "TYPE|DEPENDENCIES|MODULI", kMaterial},
  {"*DENSITY", handle_density, W::Model, "DEPENDENCIES", kMaterial},
  {"*EXPANSION", handle_expansion, W::Model, "TYPE|ZERO|DEPENDENCIES", kMaterial},
  {"*CONDUCTIVITY", handle_conductivity, W::Model, "TYPE|DEPENDENCIES", kMaterial},
  {"*SPECIFIC HEAT", handle_specific_heat, W::Model, "DEPENDENCIES", kMaterial},
  {"*DAMPING", handle_damping, W::Model, "ALPHA|BETA|STRUCTURAL|COMPOSITE", kMaterial | kSection},
  {"*SOLID SECTION", handle_solid_section, W::Model, "ELSET|MATERIAL|ORIENTATION|CONTROLS"},
  {"*SECTION CONTROLS", handle_section_controls, W::Model,
   "NAME|HOURGLASS|DISTORTION CONTROL|LENGTH RATIO|KINEMATIC SPLIT|SECOND ORDER ACCURACY|"
   "ELEMENT DELETION|MAX DEGRADATION|VISCOSITY"},
  {"*BEAM SECTION", handle_beam_section, W::Model, "ELSET|MATERIAL|SECTION|TEMPERATURE|ROTARY INERTIA", 0, P::BeamSection},
  {"*BEAM GENERAL SECTION", handle_beam_general_section, W::Model, "ELSET|SECTION|DENSITY|DEPENDENCIES|TEMPERATURE|ROTARY INERTIA", 0, P::BeamSection},
  {"*TRANSVERSE SHEAR STIFFNESS", handle_transverse_shear, W::Model, "", kSection},
  {"*SECTION POINTS", handle_section_points, W::Model, "", kBeam},
  {"*BEAM ADDED INERTIA", handle_beam_added_inertia, W::Model, "ALPHA|COMPOSITE", kBeam},
  {"*SHELL SECTION", handle_shell_section, W::Model, "ELSET|MATERIAL|OFFSET|NODAL THICKNESS|ORIENTATION|COMPOSITE|POISSON|SECTION INTEGRATION|TEMPERATURE", 0, P::ShellSection},
  {"*SHELL GENERAL SECTION", handle_shell_general_section, W::Model, "ELSET|MATERIAL|OFFSET|NODAL THICKNESS|ORIENTATION|COMPOSITE|POISSON|DENSITY|ZERO|USER|DEPENDENCIES|UNSYMM", 0, P::ShellSection},
  {"*NODAL THICKNESS", handle_nodal_thickness, W::Model, ""},
  {"*SPRING", handle_spring, W::Model, "ELSET|NONLINEAR|ORIENTATION"},
  {"*DASHPOT", handle_dashpot, W::Model, "DEPENDENCIES|ELSET|NONLINEAR|ORIENTATION|RTOL"},
  {"*MASS", handle_mass, W::Model, "ELSET|ALPHA|COMPOSITE|TYPE"},
  {"*ROTARY INERTIA", handle_rotary_inertia, W::Model, "ELSET|ALPHA|COMPOSITE|ORIENTATION"},
  {"*USER ELEMENT", handle_user_element, W::Model, "TYPE|NODES|COORDINATES|LINEAR|PROPERTIES|I PROPERTIES|VARIABLES|UNSYMM|FILE|OLD ELEMENT|STEP|INCREMENT|INTEGRATION|TENSOR", 0, P::UserElement},
  {"*MATRIX", handle_matrix, W::Model, "TYPE|INPUT", kUserElement},
  {"*UEL PROPERTY", handle_uel_property, W::Model, "ELSET|MATERIAL|ORIENTATION|ALPHA|BETA"},
  {"*MATRIX INPUT", handle_matrix_input, W::Model, "NAME|INPUT|MATRIX|SCALE FACTOR|TYPE"},
  {"*MATRIX ASSEMBLE", handle_matrix_assemble, W::Model, "STIFFNESS|MASS|VISCOUS DAMPING|STRUCTURAL DAMPING|NSET"},
  {"*SUBSTRUCTURE PROPERTY", handle_substructure_property, W::Model, "ELSET|POSITION TOL"},
  {"*AMPLITUDE", handle_amplitude, W::Both, "NAME|TIME|VALUE|DEFINITION|INPUT|FIXED INTERVAL|BEGIN|SCALEX|SCALEY|SHIFTX|SHIFTY|SMOOTH"},
  {"*INITIAL CONDITIONS", handle_initial_conditions, W::Model, "TYPE"},
  {"*PHYSICAL CONSTANTS", handle_physical_constants, W::Model, "*"},
  // gap contact
  {"*GAP", handle_gap, W::Model, "ELSET", 0, P::Gap},
  {"*SURFACE BEHAVIOR", handle_surface_behavior, W::Model,
   "PRESSURE-OVERCLOSURE|NO SEPARATION|PENALTY|AUGMENTED LAGRANGE|DIRECT", kGap},
  {"*FRICTION", handle_friction, W::Both,
   "ROUGH|LAGRANGE|ELASTIC SLIP|SLIP TOLERANCE|TAUMAX|EXPONENTIAL DECAY|ANISOTROPIC|USER|DEPENDENCIES",
   kFriction},
  {"*CONTACT DAMPING", handle_contact_damping, W::Model, "DEFINITION|TANGENT FRACTION", kGap},
  {"*GAP CONDUCTANCE", handle_gap_conductance, W::Model, "PRESSURE|USER|DEPENDENCIES", kGap},
  {"*GAP RADIATION", handle_gap_radiation, W::Model, "", kGap},
  {"*GAP HEAT GENERATION", handle_gap_heat_generation, W::Model, "", kGap},
  // linear constraints
  {"*EQUATION", handle_equation, W::Model, "INPUT"},
  {"*TRANSFORM", handle_transform, W::Model, "NSET|TYPE"},
  {"*ORIENTATION", handle_orientation, W::Model, "NAME|SYSTEM|DEFINITION"},
  {"*MPC", handle_mpc, W::Model, "MODE|USER"},
  {"*TIE", handle_tie, W::Model, "NAME|POSITION TOLERANCE|ADJUST|TYPE|NO ROTATION|NO THICKNESS|CYCLIC SYMMETRY"},
  {"*CYCLIC SYMMETRY MODEL", handle_cyclic_symmetry_model, W::Model, "N|TIE|NGRAPH|ELSET|CHECK"},
  {"*KINEMATIC COUPLING", handle_kinematic_coupling, W::Model, "REF NODE"},
  {"*COUPLING", handle_coupling, W::Model, "CONSTRAINT NAME|REF NODE|SURFACE|INFLUENCE RADIUS|ORIENTATION", 0, P::Coupling},
  {"*KINEMATIC", handle_kinematic, W::Model, "", kCoupling},
  {"*DISTRIBUTING", handle_distributing, W::Model, "COUPLING|WEIGHTING METHOD|ROTATIONAL COUPLING|FREE NODES", kCoupling},
  // model or history
  {"*BOUNDARY", handle_boundary, W::Both, "OP|AMPLITUDE|FIXED|TYPE"},
  // history: steps and procedures
  {"*STEP", handle_step, W::Both, "NAME|NLGEOM|INC|INCF|AMPLITUDE|UNSYMM|PERTURBATION|EXTRAPOLATION"},
  {"*END STEP", handle_end_step, W::Both, ""},
  {"*STATIC", handle_static, W::History, "DIRECT|RIKS|STABILIZE|ALLSDTOL|FACTOR|CONTINUE|SOLVER"},
  {"*HEAT TRANSFER", handle_heat_transfer, W::History, "STEADY STATE|DELTMX|END|SOLVER"},
  {"*COUPLED TEMPERATURE-DISPLACEMENT", handle_coupled, W::History, "STEADY STATE|DELTMX|END|CREEP|SOLVER"},
  {"*RESPONSE SPECTRUM", handle_response_spectrum, W::History, "COMP|SUM|RIGID RESPONSE"},
  {"*MODAL DAMPING", handle_modal_damping, W::History, "MODAL|RAYLEIGH|VISCOUS|STRUCTURAL|DEFINITION"},
  {"*SELECT EIGENMODES", handle_select_eigenmodes, W::History, "GENERATE|DEFINITION"},
  {"*SPECTRUM", handle_spectrum, W::Model, "NAME|TYPE|G|INPUT|CREATE"},
  {"*FREQUENCY", handle_frequency, W::History, "EIGENSOLVER|NORMALIZATION|ACOUSTIC COUPLING|PROPERTY EVALUATION|RESIDUAL MODES|SIM|DAMPING PROJECTION|STORAGE|GLOBAL|CYCMPC|SOLVER|MATRIX STORAGE"},
  {"*BUCKLE", handle_buckle, W::History, "EIGENSOLVER|SIM|SOLVER"},
  {"*STEADY STATE DYNAMICS", handle_steady_state_dynamics, W::History, "DIRECT|SUBSPACE PROJECTION|FREQUENCY SCALE|INTERVAL|REAL ONLY|HARMONIC"},
  {"*MODAL DYNAMIC", handle_modal_dynamic, W::History, "CONTINUE|SOLVER|DIRECT|DELTMX"},
  {"*BASE MOTION", handle_base_motion, W::History, "DOF|AMPLITUDE|SCALE|TYPE|IMAGINARY|REAL|BASE NAME|LOAD CASE"},
  {"*DYNAMIC", handle_dynamic, W::History, "ALPHA|BETA|GAMMA|APPLICATION|INITIAL|DIRECT|HAFTOL|NOHAF|TIME INTEGRATOR|IMPACT|SUBSPACE|EXPLICIT|ADIABATIC|SOLVER"},
  {"*CONTROLS", handle_controls, W::History, "PARAMETERS|FIELD|RESET|ANALYSIS"},
  {"*SUBSTRUCTURE GENERATE", handle_substructure_generate, W::History, "TYPE|OVERWRITE|LIBRARY|MASS MATRIX|STRUCTURAL DAMPING MATRIX|VISCOUS DAMPING MATRIX|GRAVITY LOAD|RECOVERY MATRIX|NSET|ELSET|PROPERTY EVALUATION"},
  {"*RETAINED NODAL DOFS", handle_retained_nodal_dofs, W::History, "SORTED"},
  {"*SUBSTRUCTURE MATRIX OUTPUT", handle_substructure_matrix_output, W::History, "*"},
  {"*SUBSTRUCTURE PATH", handle_substructure_path, W::History, ""},
  {"*RESTART", handle_restart, W::Both, "WRITE|READ|FREQUENCY|NUMBER INTERVAL|OVERLAY|TIME MARKS|STEP|INC|END STEP"},
  {"*CHANGE FRICTION", handle_change_friction, W::History, "ELSET|INTERACTION", 0, P::ChangeFriction},
  // history: loads
  {"*CLOAD", handle_cload, W::History, "OP|AMPLITUDE|REAL|IMAGINARY"},
  {"*CFLUX", handle_cflux, W::History, "OP|AMPLITUDE"},
  {"*DLOAD", handle_dload, W::History, "OP|AMPLITUDE"},
  {"*DSLOAD", handle_dsload, W::History, "OP|AMPLITUDE"},
  {"*DFLUX", handle_dflux, W::History, "OP|AMPLITUDE"},
  {"*DSFLUX", handle_dsflux, W::History, "OP|AMPLITUDE"},
  {"*FILM", handle_film, W::History, "OP|AMPLITUDE|FILM AMPLITUDE"},
  {"*SFILM", handle_sfilm, W::History, "OP|AMPLITUDE|FILM AMPLITUDE"},
  {"*RADIATE", handle_radiate, W::History, "OP|AMPLITUDE"},
  {"*SRADIATE", handle_sradiate, W::History, "OP|AMPLITUDE"},
  {"*TEMPERATURE", handle_temperature, W::History, "OP|AMPLITUDE|FILE"},
  {"*CONTACT INTERFERENCE", handle_contact_interference, W::History, "TYPE|SHRINK|AMPLITUDE|OP"},
  // history: output
  {"*NODE PRINT", handle_node_print, W::History, "NSET|FREQUENCY|FREQ|TOTALS|SUMMARY|GLOBAL|FREQUENCYF"},
  {"*EL PRINT", handle_el_print, W::History, "ELSET|FREQUENCY|FREQ|POSITION|TOTALS|SUMMARY|GLOBAL|FREQUENCYF"},
  {"*OUTPUT", handle_output, W::History, "FIELD|HISTORY|FREQUENCY|FREQ|VARIABLE|NUMBER INTERVAL|TIME INTERVAL|TIME MARKS|FREQUENCYF"},
  {"*NODE OUTPUT", handle_node_output, W::History, "NSET", kOutput},
  {"*ELEMENT OUTPUT", handle_element_output, W::History, "ELSET|DIRECTIONS|POSITION", kOutput},
  {"*NODE FILE", handle_node_file, W::History, "NSET|FREQUENCY|FREQ|GLOBAL|FREQUENCYF|OUTPUT|TOTALS"},
  {"*ENERGY OUTPUT", handle_output_suboption, W::History, "*", kOutput},
  {"*CONTACT OUTPUT", handle_output_suboption, W::History, "*", kOutput},
  // print and results-file controls: accepted with a note
  {"*ENERGY PRINT", handle_print_control, W::Both, "*"},
  {"*ENERGY FILE", handle_print_control, W::Both, "*"},
  {"*CONTACT PRINT", handle_print_control, W::Both, "*"},
  {"*CONTACT FILE", handle_print_control, W::Both, "*"},
  {"*SECTION PRINT", handle_print_control, W::Both, "*"},
  {"*SECTION FILE", handle_print_control, W::Both, "*"},
  {"*FILE FORMAT", handle_print_control, W::Both, "*"},
  {"*FILE OUTPUT", handle_print_control, W::Both, "*"},
  {"*MONITOR", handle_monitor, W::Both, "NODE|DOF|FREQUENCY|FREQ"},
  {"*PRINT", handle_print_control, W::Both, "*"},
  {"*DIAGNOSTICS", handle_print_control, W::Both, "*"},
  {"*EL FILE", handle_el_file, W::History, "ELSET|NSET|FREQUENCY|FREQ|POSITION|GLOBAL|FREQUENCYF|OUTPUT|TOTALS"},
}};
// clang-format on

/// The table minus the spare slots (the array size is a compile-time upper bound).
std::span<const KeywordSpec> table() {
  std::size_t n = 0;
  while (n < kTable.size() && !kTable[n].name.empty()) ++n;
  return {kTable.data(), n};
}

const KeywordSpec* find_spec(const std::string& key) {
  // canonical key -> spec, built once (a deck looks up every keyword line)
  static const std::unordered_map<std::string, const KeywordSpec*> index = [] {
    std::unordered_map<std::string, const KeywordSpec*> m;
    for (const auto& spec : table()) m.emplace(canonical(spec.name.substr(1)), &spec);
    return m;
  }();
  const auto it = index.find(key);
  return it == index.end() ? nullptr : it->second;
}

bool accepts(const KeywordSpec& spec, const std::string& param_key) {
  if (spec.params == "*") return true;
  std::string_view list = spec.params;
  while (!list.empty()) {
    const auto bar = list.find('|');
    if (canonical(list.substr(0, bar)) == param_key) return true;
    if (bar == std::string_view::npos) break;
    list = list.substr(bar + 1);
  }
  return false;
}

/// Abaqus reads a parameter from as many of its first letters as tell it apart from the keyword's
/// other parameters ("NLGEO" for NLGEOM, "AMP" for AMPLITUDE: Input Syntax Rules): a key of three
/// letters or more that begins exactly one parameter of `spec` becomes that parameter.
bool expand_abbreviation(const KeywordSpec& spec, Parameter& p) {
  if (spec.params == "*" || p.key.size() < 3) return false;
  std::string_view list = spec.params, found;
  int matches = 0;
  while (!list.empty()) {
    const auto bar = list.find('|');
    const std::string_view name = list.substr(0, bar);
    if (canonical(name).starts_with(p.key)) {
      found = name;
      ++matches;
    }
    if (bar == std::string_view::npos) break;
    list = list.substr(bar + 1);
  }
  if (matches != 1) return false;
  p.key = canonical(found);
  p.name = std::string(found);
  return true;
}

std::string parent_names(unsigned parents) {
  if (parents == kMaterial || parents == (kMaterial | kSection)) // the latter: *DAMPING
    return "*MATERIAL (it defines a property of the material above it)";
  if (parents == kGap) return "*GAP (it defines a property of the gap elements above it)";
  if (parents == kOutput) return "*OUTPUT inside a step";
  if (parents == kCoupling) return "*COUPLING (it defines the coupling above it)";
  if (parents == kUserElement)
    return "*USER ELEMENT, LINEAR (it gives the matrix of the user element type above it)";
  if (parents == kBeam)
    return "*BEAM SECTION or *BEAM GENERAL SECTION (it defines a property of the section above it)";
  if (parents == kSection)
    return "*BEAM SECTION, *BEAM GENERAL SECTION or *SHELL SECTION (it defines a property of the "
           "section above it)";
  return "*GAP (model data) or *CHANGE FRICTION (inside a step)";
}

/// Unknown keywords that change nothing gapfem computes: output requests and controls (`output`:
/// always skipped with a warning, an output request never stops a run), and named definitions
/// only used through parameters gapfem rejects anyway (skipped under --ignore-unknown).
bool skippable_keyword(const std::string& key, bool* output = nullptr) {
  static const char* const kOutputKeywords[] = {"INTEGRATEDOUTPUT",    "INTEGRATEDOUTPUTSECTION",
                                                "RADIATIONPRINT",      "RADIATIONFILE",
                                                "RADIATIONOUTPUT",     "MODALPRINT",
                                                "MODALFILE",           "MODALOUTPUT",
                                                "USEROUTPUTVARIABLES", "SUBSTRUCTUREPRINT",
                                                "EQUATIONPRINT",       "INTERACTIONPRINT",
                                                "INTERACTIONFILE",     "INTERACTIONOUTPUT",
                                                "SURFACEOUTPUT",       "SECTIONOUTPUT",
                                                "TIMEPOINTS"};
  static const char* const kDefinitions[] = {"NODERESPONSE", "ELEMENTRESPONSE"};
  if (output) *output = false;
  for (const char* k : kOutputKeywords)
    if (key == k) {
      if (output) *output = true;
      return true;
    }
  for (const char* k : kDefinitions)
    if (key == k) return true;
  return false;
}

/// Keywords whose unknown parameters are skipped with a warning: output requests only.
bool output_keyword(const std::string& key) {
  static const char* const kOutputKeys[] = {"NODEPRINT",     "ELPRINT",  "OUTPUT", "NODEOUTPUT",
                                            "ELEMENTOUTPUT", "NODEFILE", "ELFILE", "PREPRINT"};
  for (const char* k : kOutputKeys)
    if (key == k) return true;
  return false;
}

/// Analysis procedures of Abaqus and CalculiX that gapfem does not run.
bool procedure_keyword(const std::string& key) {
  static const char* const kProcedures[] = {"VISCO",
                                            "SOILS",
                                            "GEOSTATIC",
                                            "MASSDIFFUSION",
                                            "ELECTROMAGNETIC",
                                            "ELECTROMAGNETICS",
                                            "COUPLEDTHERMAL-ELECTRIC",
                                            "COUPLEDTHERMAL-ELECTRICAL-STRUCTURAL",
                                            "RANDOMRESPONSE",
                                            "COMPLEXFREQUENCY",
                                            "MATRIXGENERATE",
                                            "DIRECTCYCLIC",
                                            "ANNEAL",
                                            "CFD",
                                            "GREEN",
                                            "SENSITIVITY",
                                            "UNCOUPLEDTEMPERATURE-DISPLACEMENT",
                                            "CRACKPROPAGATION",
                                            "HEATTRANSFERCFD",
                                            "FEASIBILITY",
                                            "FEASIBLEDIRECTION",
                                            "ACOUSTIC",
                                            "NOANALYSIS",
                                            "ROBUSTDESIGN"};
  for (const char* k : kProcedures)
    if (key == k) return true;
  return false;
}

/// Unsupported Abaqus keywords that open a block of sub-options gapfem also knows (*FRICTION,
/// *SURFACE BEHAVIOR, *GAP CONDUCTANCE, …): those sub-options belong to the unsupported block.
bool unsupported_block(const std::string& key) {
  return key == "SURFACEINTERACTION" || key == "CONTACTPROPERTYASSIGNMENT" ||
         key == "CONTACTPAIR" || key == "CONTACTINTERFERENCE";
}

/// The keyword a sub-option's block starts with (*OUTPUT for *NODE OUTPUT), or nullptr.
const KeywordSpec* block_spec(Parent p) {
  switch (p) {
  case Parent::Material:
    return find_spec("MATERIAL");
  case Parent::Gap:
    return find_spec("GAP");
  case Parent::FieldOutput:
  case Parent::HistoryOutput:
    return find_spec("OUTPUT");
  case Parent::ChangeFriction:
    return find_spec("CHANGEFRICTION");
  case Parent::Coupling:
    return find_spec("COUPLING");
  case Parent::BeamSection:
    return find_spec("BEAMSECTION");
  case Parent::ShellSection:
    return find_spec("SHELLSECTION");
  case Parent::UserElement:
    return find_spec("USERELEMENT");
  case Parent::None:
  case Parent::Unsupported:
    break;
  }
  return nullptr;
}

/// The parameters a keyword accepts (display names).
std::vector<std::string> spec_params(const KeywordSpec& spec) {
  std::vector<std::string> out;
  if (spec.params == "*") return out;
  std::string_view list = spec.params;
  while (!list.empty()) {
    const auto bar = list.find('|');
    out.emplace_back(list.substr(0, bar));
    if (bar == std::string_view::npos) break;
    list = list.substr(bar + 1);
  }
  return out;
}

/// Reports a keyword or parameter the table does not have: `what` names it ("the keyword *X",
/// "the parameter P of *X"), `sentence`, when given, says what it is instead (a misspelling, a
/// parameter of the block keyword). Output requests and unused definitions are skipped with a
/// warning under --ignore-unknown; everything else is an error.
void unknown(BuildState& s, const SourceLocation& loc, const std::string& what,
             const std::string& key, bool parameter, const std::string& sentence = {}) {
  bool output = parameter && output_keyword(key);
  const bool skippable = parameter ? output : skippable_keyword(key, &output);
  if (output && sentence.empty()) { // output only: never a stop
    s.warn(loc, what + " is not supported by gapfem and was ignored (it controls output only, "
                       "not the model)");
    return;
  }
  if (!sentence.empty()) {
    if (s.opts.ignore_unknown && skippable)
      s.warn(loc, sentence + "; it was ignored (--ignore-unknown)");
    else
      s.error(loc, "", sentence);
  } else if (s.opts.ignore_unknown && skippable) {
    s.warn(loc, what + " is not supported by gapfem and was ignored (--ignore-unknown)");
  } else if (s.opts.ignore_unknown) {
    s.error(loc, "",
            what + " is not supported by gapfem, and --ignore-unknown does not skip it: it would "
                   "change the model (--ignore-unknown skips only output requests and unused "
                   "definitions); remove it or replace it with what gapfem supports");
  } else {
    s.error(loc, "",
            what + " is not supported by gapfem; remove it" +
                (skippable ? std::string(", or run with --ignore-unknown to skip it with a warning")
                           : std::string(" or replace it with what gapfem supports")));
  }
}

/// An unknown parameter of `spec`: a parameter of the block keyword above (FREQUENCY on *NODE
/// OUTPUT belongs on *OUTPUT), a misspelling of one of its own (NODESET for NSET), or a parameter
/// gapfem does not support.
void unknown_parameter(BuildState& s, const Keyword& kw, const KeywordSpec& spec,
                       const Parameter& p) {
  std::string sentence;
  if (const KeywordSpec* block = spec.parents != 0 ? block_spec(s.parent) : nullptr;
      block && accepts(*block, p.key))
    sentence = fmt::format("{} is a parameter of {}, not of {}; give it on the {} line above",
                           p.name, block->name, kw.name, block->name);
  else if (const auto near = foreign_parameter(p.key) ? std::vector<std::string>{}
                                                      : misspelling_of(p.key, spec_params(spec));
           !near.empty())
    sentence = fmt::format("unknown parameter {}; did you mean {}?", p.name, one_of(near));
  unknown(s, kw.loc, fmt::format("the parameter {} of {}", p.name, kw.name), kw.key, true,
          sentence);
}

/// An unknown keyword: a real Abaqus or CalculiX keyword gapfem lacks, a misspelling of a keyword
/// (gapfem's or Abaqus's), or text written after a single star (a title or a comment).
void unknown_keyword(BuildState& s, const Keyword& kw, bool after_empty_heading) {
  if (foreign_keyword(kw.key) || skippable_keyword(kw.key) || procedure_keyword(kw.key)) {
    unknown(s, kw.loc, fmt::format("the keyword {}", kw.name), kw.key, false);
    if (unsupported_block(kw.key)) s.parent = Parent::Unsupported;
    return;
  }
  // gapfem's keywords and Abaqus's, the closest wins
  static const std::vector<std::string> known = [] {
    std::vector<std::string> names;
    for (const auto& spec : table()) names.emplace_back(spec.name);
    for (const std::string& n : foreign_keyword_names())
      if (!find_spec(canonical(n))) names.push_back("*" + n);
    return names;
  }();
  const std::vector<std::string> near = misspelling_of(kw.key, known);
  if (near.empty()) {
    s.error(kw.loc, "",
            after_empty_heading
                ? "unknown keyword; the *HEADING above has no title line, and a line starting "
                  "with a single * is a keyword line: write the title without the * (comments "
                  "start with **)"
                : "unknown keyword; if this line is a title or a comment: a line starting with a "
                  "single * is a keyword line; a title or comment must not start with * "
                  "(comments start with **)");
    return;
  }
  std::string unsupported;
  for (const std::string& n : near)
    if (const KeywordSpec* spec = find_spec(canonical(n.substr(1))); spec) {
      // what the meant keyword would have opened or given: no false follow-on errors
      if (spec->opens != Parent::None) s.parent = Parent::Unsupported;
      if (s.in_step && (spec->handler == handle_static || spec->handler == handle_heat_transfer ||
                        spec->handler == handle_coupled))
        s.scratch.procedure_given = true;
    } else {
      unsupported = fmt::format(" ({} is an Abaqus keyword gapfem does not support)", n);
    }
  s.error(kw.loc, "",
          fmt::format("unknown keyword; did you mean {}?{}", one_of(near),
                      near.size() == 1 ? unsupported : std::string()));
}

void dispatch(BuildState& s, Keyword& kw);

/// The text of a data line for a message: as written, shortened beyond 80 characters.
std::string quoted_line(const DataLine& line) {
  const std::string_view t = trim(line.text);
  return t.size() <= 80 ? fmt::format("'{}'", t) : fmt::format("'{}...'", t.substr(0, 77));
}

/// After a keyword's handler has run: a data line it did not read belongs to no keyword, and the
/// user thinks it was read. One error names the first such line (and counts the others).
void report_unread_lines(BuildState& s, const Keyword& kw) {
  int n_read = 0, n_unread = 0;
  const DataLine* first = nullptr;
  int first_index = 0; // 1-based among the keyword's non-blank lines
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    if (line.read) {
      ++n_read;
      continue;
    }
    if (n_unread++ == 0) {
      first = &line;
      first_index = n_read + n_unread;
    }
  }
  // a keyword that read nothing in a deck with errors may skip its data on purpose (what it
  // refers to failed, reported): its lines are reported once the deck has no other error
  if (!first || (n_read == 0 && s.diag.n_errors() > 0)) return;
  const std::string others = n_unread == 1 ? ""
                                           : fmt::format(" (and {} more line{} after it)",
                                                         n_unread - 1, n_unread == 2 ? "" : "s");
  std::string head;
  if (first->empty())
    head = fmt::format("line {} holds only commas ({}), no value: {} reads nothing from it{}",
                       first->line, trim(first->text), kw.name, others);
  else if (n_read == 0)
    head = fmt::format("{} takes no data lines; line {} is one: {}{}", kw.name, first->line,
                       quoted_line(*first), others);
  else
    head = fmt::format("{} takes {} data line{}; line {} is {}: {}{}", kw.name,
                       n_read == 1 ? "one" : std::to_string(n_read), n_read == 1 ? "" : "s",
                       first->line, first_index == 2 ? "a second one" : "one more",
                       quoted_line(*first), others);
  s.error(s.loc(kw, *first), "",
          head + ". Remove it, or put the keyword line it belongs to above it");
}

/// The node (*NODE) or element (*ELEMENT) numbers that `lines` of `kw` would have defined, noted
/// as failed definitions: their uses raise no false "is not defined".
void note_failed_labels(BuildState& s, const Keyword& kw, const std::vector<DataLine>& lines) {
  const bool nodes = kw.key == "NODE";
  if (!nodes && kw.key != "ELEMENT") return;
  for (const DataLine& d : lines) {
    long long label = 0;
    if (d.fields.empty() || check_integer(d.fields[0], 1, kMaxLabel, label) != IntCheck::Ok)
      continue;
    (nodes ? s.bad_nodes : s.bad_elements).insert(s.key(label));
  }
}

/// After `kw` failed as a whole (an InputError left its handler, or the lexer reported its
/// keyword line): the names it would have
/// defined are remembered, so that their uses raise no false "is not defined", and the sub-options
/// of a failed block keyword are skipped quietly instead of attaching to an earlier block.
void note_failed_definition(BuildState& s, const Keyword& kw) {
  auto name = [&](std::string_view param) -> std::string {
    const Parameter* p = kw.find(param);
    return p && p->has_value ? to_upper(trim(p->value)) : std::string();
  };
  auto add = [](std::unordered_set<std::string>& names, std::string n) {
    if (!n.empty()) names.insert(std::move(n));
  };
  auto add_set = [&](std::string_view param) {
    std::string n = name(param);
    if (n.empty()) return;
    const auto dot = n.find('.');
    if (dot == std::string::npos || !s.instance_index.count(n.substr(0, dot))) n = s.set_name(n);
    s.bad_sets.insert(std::move(n));
  };
  if (kw.key == "AMPLITUDE") add(s.bad_amplitudes, name("NAME"));
  if (kw.key == "MATERIAL") add(s.bad_materials, name("NAME"));
  if (kw.key == "PART") add(s.bad_parts, name("NAME"));
  if (kw.key == "INSTANCE") add(s.bad_instances, name("NAME"));
  if (kw.key == "USERELEMENT") add(s.bad_user_types, name("TYPE"));
  const bool known = find_spec(kw.key) != nullptr; // (a garbled keyword line: any of its names)
  if (kw.key == "NSET" || kw.key == "NODE" || !known) add_set("NSET");
  if (kw.key == "ELSET" || kw.key == "ELEMENT" || !known) add_set("ELSET");
  if (!known)
    for (auto* names : {&s.bad_amplitudes, &s.bad_materials, &s.bad_parts, &s.bad_instances})
      add(*names, name("NAME"));
  note_failed_labels(s, kw, kw.data);
  note_failed_labels(s, kw, kw.rejected);
  if (const KeywordSpec* spec = find_spec(kw.key);
      spec && spec->opens != Parent::None && (s.parent == spec->opens || kw.failed))
    s.parent = Parent::Unsupported;
}

/// Runs one keyword; an input error is recorded and the keyword's definitions are noted as failed.
void run_keyword(BuildState& s, Keyword& kw) {
  try {
    dispatch(s, kw);
  } catch (const InputError& e) {
    s.diag.error(e);
    note_failed_definition(s, kw);
  }
}

/// *END INSTANCE: reads the part's keywords (and the instance's own) again in the instance's
/// scope. Errors of a part are reported for its first instance only: a later instance whose part
/// failed is not read again.
void expand_instance(BuildState& s) {
  BuildState::InstanceDef def = std::move(s.instance);
  s.instance = BuildState::InstanceDef{};
  if (def.failed) return; // its *INSTANCE line was reported
  BuildState::PartDef& part = s.parts.at(def.part);
  const int index = static_cast<int>(s.model.instances.size()) + 1;
  s.model.instances.push_back(def.name);
  s.instance_parts.push_back(def.part);
  s.instance_index[def.name] = index;
  ++part.instances;
  if (part.failed) return;
  def.scope.instance = index;
  const BuildState::Scope outer = s.scope;
  s.scope = def.scope;
  s.parent = Parent::None;
  // the part's *NODE lines: its *ELEMENT and *NSET may name nodes defined further down
  const auto lines = s.part_node_lines.find(def.part);
  s.node_lines = lines == s.part_node_lines.end() ? nullptr : &lines->second;
  s.node_lines_instance = index;
  const std::size_t errors_before = static_cast<std::size_t>(s.diag.n_errors());
  auto run = [&](Keyword* kw) { run_keyword(s, *kw); };
  for (Keyword* kw : part.keywords) run(kw);
  part.failed = static_cast<std::size_t>(s.diag.n_errors()) > errors_before;
  s.node_lines = nullptr;
  for (Keyword* kw : def.keywords) run(kw);
  s.scope = outer;
  s.parent = Parent::None;
  s.node_lines = &s.top_node_lines;
  s.node_lines_instance = 0;
}

/// Before the keywords run: the node numbers each *NODE line of the model data defines, for the
/// flat deck (and assembly) and for each part, so that *ELEMENT and *NSET may name a node whose
/// *NODE line comes further down (Abaqus reads the model data in any order).
void note_node_lines(BuildState& s, const Deck& deck) {
  BuildState::LabelLines* part = nullptr;
  bool in_instance = false;
  for (const Keyword& kw : deck.keywords) {
    if (kw.key == "STEP") break;
    if (kw.key == "PART" && !s.transparent_parts) {
      const Parameter* name = kw.find("NAME");
      part = &s.part_node_lines[name ? to_upper(trim(name->value)) : std::string()];
    } else if (kw.key == "ENDPART") {
      part = nullptr;
    } else if (kw.key == "INSTANCE" || kw.key == "ENDINSTANCE") {
      in_instance = kw.key == "INSTANCE";
    } else if (kw.key == "NODE" && !in_instance && !kw.failed) {
      BuildState::LabelLines& lines = part ? *part : s.top_node_lines;
      for (const DataLine& d : kw.data) {
        long long label = 0;
        if (!d.fields.empty() && check_integer(d.fields[0], 1, kMaxLabel, label) == IntCheck::Ok)
          lines.emplace(label, SourceRef{d.file, d.line});
      }
    }
  }
  s.node_lines = &s.top_node_lines;
}

void dispatch(BuildState& s, Keyword& kw) {
  const bool after_empty_heading = std::exchange(s.heading_untitled, false);
  if (record_keyword(s, kw)) return; // inside *PART or *INSTANCE: read per instance
  if (kw.failed) {                   // its keyword line was reported by the lexer
    note_failed_definition(s, kw);
    kw.mark_read();
    if (kw.key == "STEP" || kw.key == "ENDSTEP") { // the steps keep their place all the same
      try {
        (kw.key == "STEP" ? handle_step : handle_end_step)(s, kw);
      } catch (const InputError&) { // about the line reported already
      }
    }
    return;
  }
  // data lines the lexer rejected (reported): the names they would define are failed ones
  if (!kw.rejected.empty()) note_failed_labels(s, kw, kw.rejected);
  const KeywordSpec* spec = find_spec(kw.key);
  if (!spec) {
    // unknown keyword: the current block stays open (an ignored *PLASTIC keeps its *MATERIAL)
    if (s.in_step && procedure_keyword(kw.key)) {
      // the step has its procedure, one gapfem does not run: no "step has no procedure" later
      s.scratch.procedure_given = true;
      s.scratch.unknown_procedure = true; // its step's other checks would be follow-on errors
      s.error(
          kw.loc, "",
          fmt::format(
              "the procedure {} is not supported by gapfem, which runs *STATIC, *DYNAMIC, "
              "*FREQUENCY, *HEAT TRANSFER and *COUPLED TEMPERATURE-DISPLACEMENT steps; replace the "
              "step or remove it",
              kw.name));
      return;
    }
    unknown_keyword(s, kw, after_empty_heading);
    return;
  }
  kw.name = std::string(spec->name);
  kw.loc.keyword = kw.name;
  // (a restart deck's *RESTART, READ follows the old deck's last step: reader.cpp)
  if (s.model_done && !s.in_step && spec->handler != handle_step &&
      spec->handler != handle_end_step && !(spec->handler == handle_restart && kw.has("READ"))) {
    s.error(kw.loc, "",
            fmt::format("{} after *END STEP; after the first *STEP every keyword belongs inside a "
                        "step (between *STEP and *END STEP)",
                        kw.name));
    return;
  }
  const bool history_keyword = spec->where == Where::History;
  if (spec->parents != 0) {
    if (!(spec->parents & bit(s.parent))) {
      if (s.parent != Parent::Unsupported) // else: a sub-option of a reported block
        s.error(kw.loc, "", fmt::format("{} must follow {}", kw.name, parent_names(spec->parents)));
      return;
    }
  } else {
    s.parent = spec->opens;
  }
  if (history_keyword && !s.in_step) {
    s.error(kw.loc, "",
            fmt::format("{} is history data; put it inside a step (between *STEP and *END STEP)",
                        kw.name));
    return;
  }
  if (spec->where == Where::Model && (s.in_step || s.model_done)) {
    s.error(kw.loc, "", fmt::format("{} is model data; move it before the first *STEP", kw.name));
    return;
  }
  for (auto& p : kw.params)
    if (!accepts(*spec, p.key) && !expand_abbreviation(*spec, p))
      unknown_parameter(s, kw, *spec, p);
  spec->handler(s, kw);
  report_unread_lines(s, kw);
  if (spec->handler == handle_end_instance) expand_instance(s);
}

} // namespace

std::span<const KeywordSpec> keyword_table() {
  return table();
}

void parse_deck(Deck& deck, BuildState& s) {
  bool part = false, assembly = false;
  for (const Keyword& kw : deck.keywords) {
    part |= kw.key == "PART";
    assembly |= kw.key == "ASSEMBLY" || kw.key == "INSTANCE";
  }
  s.transparent_parts = part && !assembly;
  note_node_lines(s, deck);
  for (Keyword& kw : deck.keywords) run_keyword(s, kw);
  finish_deck(s);
}

} // namespace gapfem::inp
