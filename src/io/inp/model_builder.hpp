#pragma once
/// @file model_builder.hpp
/// The state shared by the keyword handlers while a deck is turned into a Model, and the helpers
/// they use: locations, node/element/set references, amplitudes, enumerated parameters. The builder
/// also binds elements to their properties and validates the model once the model data is complete
/// (finish_model_data), and resolves the steps (handlers_step.cpp).
#include "io/inp/diagnostics.hpp"
#include "io/inp/fields.hpp"
#include "io/inp/keyword.hpp"
#include "io/inp/orientation.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"

#include <array>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace gapfem::inp {

/// Which block a sub-option keyword attaches to.
enum class Parent : std::uint8_t {
  None,
  Material,
  Gap,
  FieldOutput,
  HistoryOutput,
  ChangeFriction,
  Coupling,
  BeamSection,
  ShellSection,
  UserElement, ///< *USER ELEMENT: its *MATRIX follow
  /// after an unsupported block keyword (*SURFACE INTERACTION): its sub-options are skipped
  /// quietly (the block was reported), never attached to an earlier block
  Unsupported
};

/// What a step has seen so far (for defaults and "exactly one" rules).
struct StepScratch {
  bool procedure_given = false;
  bool unknown_procedure = false; ///< the step's procedure is one gapfem does not run (reported)
  bool amplitude_given = false;   ///< *STEP, AMPLITUDE= was given
  bool transient = false;         ///< transient heat transfer / coupled procedure
  bool node_print_given = false, el_print_given = false, field_given = false;
  bool node_file_given = false, el_file_given = false; ///< *NODE FILE / *EL FILE in this step
  /// Field-output requests of this step that asked for VARIABLE=PRESELECT or ALL (index, all?).
  std::vector<std::pair<int, bool>> preset_fields;
};

/// Everything the handlers read and write while building the model.
struct BuildState {
  BuildState(const ReadOptions& o, Diagnostics& d) : opts(o), diag(d) {}

  const ReadOptions& opts;
  Diagnostics& diag;
  Model model;

  // failed definitions: later references to these labels are skipped without another error
  std::unordered_set<Label> bad_nodes, bad_elements;
  std::unordered_set<std::string> bad_sets;
  /// a node or element number out of range was reported at its definition (read_label)
  bool label_out_of_range = false;
  /// node and element sets defined with UNSORTED (gapfem keeps every set sorted)
  std::unordered_set<std::string> unsorted_sets;
  /// names that a keyword in error would have defined (note_failed_definition): amplitudes,
  /// materials, parts and instances; uses of them raise no "is not defined"
  std::unordered_set<std::string> bad_amplitudes, bad_materials, bad_parts, bad_instances,
      bad_user_types;
  /// materials whose *ELASTIC (0) or *CONDUCTIVITY (1) was in error (reported): no follow-on
  /// "the material has none"
  std::set<std::pair<int, int>> bad_material_options;
  /// Surfaces with a data line whose elements or nodes failed to be defined (reported there):
  /// constraints on them stay quiet when nothing is left.
  std::unordered_set<std::string> incomplete_surfaces;
  std::vector<SourceRef> node_src; ///< per node: its *NODE data line
  /// The node numbers each *NODE data line of the model data defines, by scope: the flat deck or
  /// assembly (top_node_lines) and each part (part_node_lines, local numbers), read before the
  /// keywords run; node_lines is the current scope's (nullptr: none), for the instance
  /// node_lines_instance. With them *ELEMENT and *NSET may name a node defined further down.
  using LabelLines = std::unordered_map<long long, SourceRef>;
  LabelLines top_node_lines;
  std::map<std::string, LabelLines> part_node_lines;
  const LabelLines* node_lines = nullptr;
  int node_lines_instance = 0;
  /// Nodes named by *ELEMENT or *NSET before the *NODE line that defines them (forward_node):
  /// created with their label, their coordinates set when that line is read.
  std::unordered_set<NodeId> awaiting;
  /// The keyword being read may name nodes defined further down (*ELEMENT, *NSET).
  bool forward_nodes_ok = false;
  std::vector<NodeId> all_nodes;    ///< the implicit set NALL (find_nset)
  std::vector<ElemId> all_elements; ///< the implicit set EALL (find_elset)

  /// *INITIAL CONDITIONS, TYPE=TEMPERATURE entries, applied when the model data
  /// is complete.
  std::vector<std::pair<NodeId, double>> initial_temperatures;

  std::map<std::string, int> material_index;  ///< upper-case name → Model::materials
  std::map<std::string, int> amplitude_index; ///< upper-case name → Model::amplitudes
  std::vector<std::string> solid_material;    ///< per solid section: material name
  std::vector<std::string> solid_controls;    ///< per solid section: CONTROLS= name or empty
  std::map<std::string, int> controls_index;  ///< upper-case name → Model::section_controls
  std::vector<std::string> beam_material;     ///< per beam section: material name
  /// the last *BEAM (GENERAL) SECTION was read without error (its sub-options may attach to it)
  bool beam_section_ok = false;
  std::vector<std::string> shell_material; ///< per shell section: material name
  bool shell_section_ok = false;           ///< as beam_section_ok, for *SHELL SECTION
  /// Per spring section: its first data line (DOFs; blank for SPRINGA), read once the element types
  /// of the ELSET are known.
  std::vector<DataLine> spring_dof_line;
  /// *ORIENTATION by upper-case name (orientation.hpp), resolved where one is referred to
  std::map<std::string, OrientationDef> orientations;
  /// *ROTARY INERTIA, ORIENTATION=: the mass section's index and the orientation's name (its
  /// tensor is turned to global axes once every *ORIENTATION is read)
  std::vector<std::pair<std::size_t, std::string>> rotary_orientations;

  Parent parent = Parent::None;
  int current_material = -1, current_gap = -1, current_field = -1, current_change = -1;
  int current_history = -1; ///< the *OUTPUT, HISTORY request its sub-options add to
  /// the *USER ELEMENT being read (its *MATRIX follow), and whether it is a part's definition
  /// read again for a later instance (its *MATRIX were read with the first)
  int current_user_element = -1;
  bool user_element_replayed = false;

  /// Constraints whose rows need the complete model data (the model space, the nodes' final
  /// coordinates): built at the end of the model data, ties first (ADJUST moves slave nodes).
  struct DeferredConstraint {
    int order = 1; ///< 0: ties, 1: everything else
    std::function<void(BuildState&)> build;
  };
  std::vector<DeferredConstraint> deferred_constraints;
  /// *CYCLIC SYMMETRY MODEL: the number of sectors in 360 degrees and the axis from a to b (the
  /// ties with CYCLIC SYMMETRY use it); `tie` CalculiX's TIE= (empty: every cyclic tie's).
  struct CyclicModelDef {
    double n = 0.0;
    Vec3 a{}, b{};
    std::string tie;
    SourceLocation loc;
  };
  std::vector<CyclicModelDef> cyclic_models; ///< one, or one per TIE= (CalculiX)
  std::vector<std::pair<std::string, SourceLocation>> cyclic_ties; ///< *TIE, CYCLIC SYMMETRY
  /// The *COUPLING being read (its *KINEMATIC / *DISTRIBUTING follow it).
  struct CouplingDef {
    std::string name;
    SourceLocation loc;
    NodeId ref = -1;
    std::vector<std::pair<NodeId, double>> nodes; ///< coupling nodes and tributary areas
    double radius = 0.0;                          ///< INFLUENCE RADIUS (0: none)
    std::string orientation; ///< ORIENTATION=: the DOFs of its *KINEMATIC / *DISTRIBUTING are local
    bool defined = false;    ///< a *KINEMATIC or *DISTRIBUTING was given
    bool failed = false;     ///< the *COUPLING line had an error (its sub-options are skipped)
  };
  std::vector<CouplingDef> couplings;

  std::vector<BoundaryEntry> model_boundary; ///< *BOUNDARY in model data
  std::optional<DofMonitor> model_monitor;   ///< *MONITOR in model data (every step)
  RestartWrite model_restart;                ///< *RESTART, WRITE in model data
  bool model_boundary_value_warned = false;  ///< the non-zero model-data *BOUNDARY remark
  bool model_done = false;                   ///< finish_model_data() has run
  bool in_step = false;
  std::unordered_set<std::string> noted_keywords; ///< print controls already remarked
  /// The keyword just read was a *HEADING without a title line (a title written with a * reads
  /// as an unknown keyword: its message says so)
  bool heading_untitled = false;
  Step step;
  StepScratch scratch;

  // ---------------------------------------------------------------- parts and instances
  /// Where the labels and set names of the keywords being read belong: a flat deck or the
  /// assembly level (instance 0, no prefix), or a part instance (its keys and "INSTANCE." names;
  /// the part's coordinates are placed by the instance's translation and rotation).
  struct Scope {
    int instance = 0;
    std::string prefix;
    bool placed = false;
    Vec3 translation{}, axis_point{};
    std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1}; ///< row-major
    /// *SYSTEM: the local system later *NODE coordinates are given in (origin, then its axes as
    /// the columns of a row-major rotation); none: global
    bool local_system = false;
    Vec3 system_origin{};
    std::array<double, 9> system_axes{1, 0, 0, 0, 1, 0, 0, 0, 1};
  };
  Scope scope;
  /// A *PART ... *END PART block: its keywords, read again for every instance.
  struct PartDef {
    std::string name;
    SourceLocation loc;
    std::vector<Keyword*> keywords;
    bool failed = false; ///< its first instance had input errors (not read again)
    int instances = 0;
  };
  std::map<std::string, PartDef> parts;
  PartDef* recording = nullptr; ///< inside *PART ... *END PART
  bool in_assembly = false;     ///< inside *ASSEMBLY ... *END ASSEMBLY
  SourceLocation assembly_loc;  ///< the *ASSEMBLY line
  /// The deck has *PART but no *ASSEMBLY and no *INSTANCE (a CalculiX-style deck): *PART and
  /// *END PART only mark a region of ordinary model data.
  bool transparent_parts = false;
  bool assembly_seen = false;
  /// The *INSTANCE being read (up to *END INSTANCE) and its own keywords.
  struct InstanceDef {
    bool open = false;
    bool failed = false; ///< *INSTANCE had an error: the instance is skipped
    std::string name, part;
    SourceLocation loc;
    Scope scope;
    std::vector<Keyword*> keywords;
  };
  InstanceDef instance;
  std::map<std::string, int> instance_index; ///< upper-case name → 1-based instance index
  std::vector<std::string> instance_parts;   ///< per instance (Model::instances): its part

  /// Key of a node or element label read in the current scope.
  Label key(long long label) const { return make_key(scope.instance, label); }
  /// Name of a set defined or referenced (without an instance qualifier) in the current scope.
  std::string set_name(const std::string& upper) const { return scope.prefix + upper; }
  /// Reference coordinates of a node read in the current scope (placed by its instance).
  Vec3 place(const Vec3& x) const;
  /// Coordinates entered in the current *SYSTEM (none: as they are), before place().
  Vec3 from_system(const Vec3& x) const;

  // ---------------------------------------------------------------- helpers
  /// Location of a data line of `kw`.
  SourceLocation loc(const Keyword& kw, const DataLine& line) const {
    return SourceLocation{model.source_files[line.file], line.line, kw.name};
  }
  SourceRef ref(const DataLine& line) const { return SourceRef{line.file, line.line}; }
  /// Field reader for a data line of `kw`.
  FieldReader reader(const Keyword& kw, const DataLine& line) const {
    return FieldReader(line, loc(kw, line));
  }
  void warn(const SourceLocation& at, const std::string& message) { diag.warning(at, message); }
  /// Records an error and continues.
  void error(const SourceLocation& at, std::string entity, std::string message) {
    diag.error(std::move(at), std::move(entity), std::move(message));
  }
};

/// Calls f(line) for every non-empty data line of `lines`; an InputError thrown by f is recorded
/// and the next line is read. Returns the number of lines in error, so that a caller reports no
/// false "data missing" error after lines it has already reported.
template <typename F>
int for_each_line(BuildState& s, std::span<const DataLine> lines, F&& f) {
  int failed = 0;
  for (const DataLine& line : lines) {
    if (line.empty()) continue; // (a line of only commas stays unread: the parser reports it)
    line.read = true;
    try {
      f(line);
    } catch (const InputError& e) {
      s.diag.error(e);
      ++failed;
    }
  }
  return failed;
}
/// for_each_line over all data lines of `kw`.
template <typename F>
int for_each_line(BuildState& s, const Keyword& kw, F&& f) {
  return for_each_line(s, std::span<const DataLine>(kw.data), std::forward<F>(f));
}

/// Checks the property values of one table row; returns an error sentence or "".
using RowCheck = std::string (*)(const std::vector<double>& values);
/// Reads rows of `names.size()` values plus an optional temperature column (Abaqus material-data
/// layout) from `lines` into a table sorted by temperature. DEPENDENCIES > 0 on `kw` is rejected.
/// The values from index `required` on may be blank: 0, as Abaqus reads a blank field.
PropertyTable read_property_table(BuildState& s, const Keyword& kw, std::span<const DataLine> lines,
                                  std::vector<std::string_view> names, RowCheck check,
                                  std::size_t required = static_cast<std::size_t>(-1));

// ---------------------------------------------------------------- numbers
/// The sentence for a DOF number gapfem does not have, {} standing for the number as written.
inline constexpr std::string_view kUnknownDof =
    "DOF {} is not available; gapfem knows DOFs 1-6 (displacements, rotations) and 11-25 "
    "(temperatures: 11, and 12-25 through the thickness of heat-transfer shells)";
static_assert(kMaxAbaqusDof == 25, "kUnknownDof names the DOFs");
/// An Abaqus DOF number gapfem has (1-6, 11-25) from field i; kUnknownDof otherwise.
int dof_number(const FieldReader& r, std::size_t i, std::string_view what);
/// The sentence for a node or element number out of range ({}: the number as written).
inline constexpr std::string_view kLabelRule =
    "{} is out of range: node and element numbers run from 1 to 999999999 (Abaqus's limit)";
static_assert(kMaxLabel == 999'999'999, "kLabelRule names the limit");
/// The node or element number that field 0 of a *NODE or *ELEMENT line defines (1 to kMaxLabel).
/// One out of range is reported here, and later references to numbers out of range are then
/// skipped quietly (BuildState::label_out_of_range) instead of repeating it.
long long read_label(BuildState& s, const FieldReader& r, std::string_view what);

/// "a" or "an" before `word` as it is read aloud: "an S4R", "an axisymmetric", "a C3D8", "a
/// GAPUNI", "a *SHELL SECTION" (a type name whose second character is a digit is spelled out).
std::string_view article(std::string_view word);
/// `word` with its article: "an S4R".
std::string with_article(std::string_view word);

// ---------------------------------------------------------------- references
/// What a node or element reference names: a label key, or a set name (upper case, qualified).
struct EntityRef {
  std::optional<Label> key;
  std::string set;
  /// qualified by an instance whose definition failed (reported there), or a number out of
  /// range after one was reported at its definition (read_label)
  bool failed = false;
};
/// Reads a reference of the current scope: `12`, `SET-1`, or qualified by an instance,
/// `PART-1-1.12` or `PART-1-1.SET-1` (the instance must exist). `what` names the field for errors.
EntityRef parse_reference(BuildState& s, const FieldReader& r, std::size_t field);
/// Nodes named by a data field: a node label or an NSET name. Throws InputError naming the field
/// when neither exists. Returns nothing (silently) for labels/sets whose definition already failed.
std::vector<NodeId> resolve_nodes(BuildState& s, const FieldReader& r, std::size_t field);
/// The single node named by a parameter (REF NODE=, NODE=): a label or a set of one node.
NodeId param_node(BuildState& s, const Keyword& kw, std::string_view param);
/// What a name the deck uses can be.
enum class NameKind : std::uint8_t { NodeSet, ElementSet, Surface };
/// The sentence for `name` (upper case, qualified as looked up) used as a `kind` but not defined
/// as one: it is another kind of name ("SOLID is an element set, not a node set; *CLOAD needs
/// `need` here: ..."), a set of a part named without its instance ("... is defined in part BLOCK;
/// ... e.g. BLOCK-1.CORNERS"), or undefined ("this node set is not defined; `remedy`").
std::string undefined_name(const BuildState& s, const std::string& name, NameKind kind,
                           std::string_view keyword, std::string_view need,
                           std::string_view remedy);
/// The sentence for a node number `key` that names no node: a number the instance's part does not
/// have, a part's node named in the assembly without its instance, or a node never defined.
/// `named`: the message's entity names the node already ("this node is not defined");
/// `before_use`: the keyword needs the node defined above it (all but *ELEMENT and *NSET).
std::string undefined_node(const BuildState& s, Label key, bool named, bool before_use);
/// A node that *ELEMENT or *NSET names before the *NODE line of the model data that defines it
/// further down (Abaqus reads the model data in any order): created now with its label, its
/// coordinates set when that line is read (BuildState::awaiting). -1 when no *NODE line of the
/// current scope defines it.
NodeId forward_node(BuildState& s, Label key);
/// The *NODE line further down that defines node `key` of the current scope, or nullptr.
const SourceRef* later_node_line(const BuildState& s, Label key);
/// The sentence for a node that a keyword other than *ELEMENT and *NSET names before the *NODE
/// line that defines it (`line`).
std::string node_defined_later(const BuildState& s, Label key, SourceRef line,
                               std::string_view keyword);

/// Elements named by a data field: an element label or an ELSET name.
std::vector<ElemId> resolve_elements(BuildState& s, const FieldReader& r, std::size_t field);
/// Elements of an ELSET parameter value (upper-cased), or nullptr when the set does not exist.
/// EALL, when the deck defines no set of that name, holds every element (CalculiX dialect).
const std::vector<ElemId>* find_elset(BuildState& s, const std::string& name);
/// Nodes of a node set (upper-cased name), or nullptr; NALL as EALL for nodes.
const std::vector<NodeId>* find_nset(BuildState& s, const std::string& name);
/// Index of the amplitude named by the AMPLITUDE (or `param`) parameter, -1 when absent.
int amplitude_param(BuildState& s, const Keyword& kw, std::string_view param = "AMPLITUDE");

// ---------------------------------------------------------------- parameters
/// Value of a parameter that must have one; throws InputError when missing/empty if required.
std::string param_value(const Keyword& kw, std::string_view param, bool required);
/// Upper-case name value (set, material and amplitude names): trimmed and upper case.
std::string name_param(const Keyword& kw, std::string_view param, bool required);
/// A set name parameter (NSET=, ELSET=, NAME= of a surface) in the current scope: upper case,
/// qualified by the instance inside a part instance, or as written (`PART-1-1.SET-1`) when the
/// value already names an instance.
std::string set_param(BuildState& s, const Keyword& kw, std::string_view param, bool required);
/// An enumerated parameter: returns the index of the matching choice (compared canonically) or
/// `def` when the parameter is absent; throws listing the choices when the value is not one.
int enum_param(const Keyword& kw, std::string_view param,
               std::initializer_list<std::string_view> choices, int def);
/// YES/NO parameter; a bare parameter (no value) means YES.
bool yes_no_param(const Keyword& kw, std::string_view param, bool def);
/// Real-valued parameter; nullopt when absent.
std::optional<double> real_param(const Keyword& kw, std::string_view param);
/// Integer-valued parameter, a whole number from `min` to `max`; nullopt when absent. `what` names
/// it in the message of a value out of range ("the maximum number of increments").
std::optional<long long> int_param(const Keyword& kw, std::string_view param, std::string_view what,
                                   long long min, long long max);
/// DEPENDENCIES= (the number of field variables a table depends on; 0 when absent).
long long dependencies_param(const Keyword& kw);
/// "NAME=value" as the keyword line gives a parameter (its name alone without a value; "" when
/// absent): the entity of a message about its value.
std::string param_text(const Keyword& kw, std::string_view param);
/// Throws "PARAM is not supported by gapfem" for a parameter that is present.
void reject_param(const Keyword& kw, std::string_view param, std::string_view why);

/// Adds nodes/elements to a set (creating it) and keeps it sorted and unique.
void add_to_nset(BuildState& s, const std::string& name, const std::vector<NodeId>& nodes);
void add_to_elset(BuildState& s, const std::string& name, const std::vector<ElemId>& elems);

/// What an element face is used for.
enum class FaceUse : std::uint8_t {
  Any,      ///< *SURFACE faces: a face that some load can use
  Pressure, ///< Pn, *DSLOAD: continuum elements with displacements
  Thermal   ///< Sn, Fn, *DSFLUX, *SFILM: elements with the temperature DOF 11
};
/// Number of faces S1..Sn (Pn, Fn) of an element type for a use (0: none). The counts match the
/// kernels' supports_load: faces of continuum cells in Abaqus numbering (fe/element_faces.hpp:
/// bricks 6, tetrahedra 4, quadrilaterals 4, triangles 3) for pressure and heat loads, and the two
/// ends of the heat-conducting links DC1D2, T2D2T, T3D2T (S1 at node 1, S2 at node 2) for heat
/// loads only. Springs, beams, gaps and mechanical trusses have none.
int n_faces(ElementType type, FaceUse use = FaceUse::Any);

/// Binds elements to properties, resolves materials, checks the model space and the gap
/// definitions. Runs once, at the first *STEP or at the end of the deck.
void finish_model_data(BuildState& s);
/// Final checks after the last keyword (open step, …).
void finish_deck(BuildState& s);

} // namespace gapfem::inp
