#include "output/report_page.hpp"

#include "output/output_file.hpp"

#include <cstddef>
#include <string_view>

namespace gapfem::embedded {
extern const char chart_js[];
extern const std::size_t chart_js_size;
} // namespace gapfem::embedded

namespace gapfem::output {
namespace {

constexpr std::string_view kStyle = R"(<style>
body{font-family:system-ui,sans-serif;max-width:1100px;margin:1em auto;padding:0 1em;color:#222}
h1{font-size:1.5em}h2{font-size:1.2em;margin-top:1.6em;border-bottom:1px solid #ddd}
.chart{position:relative;height:300px;margin:0.5em 0}
table{border-collapse:collapse;font-size:0.9em}td,th{border:1px solid #ccc;padding:2px 8px}
td{text-align:right}.bad{color:#b00;font-weight:bold}.ok{color:#070}
.note{color:#555;font-size:0.9em}
</style>
)";

// Draws the charts from DATA; every chart is drawn synchronously (no animation), then <body>
// records what was drawn for the browser test.
constexpr std::string_view kScript = R"(
Chart.defaults.animation = false;
Chart.defaults.maintainAspectRatio = false;
const palette = ['#1f77b4','#d62728','#2ca02c','#ff7f0e','#9467bd','#8c564b','#e377c2','#17becf'];
const charts = [];
function chart(id, config) {
  const c = document.getElementById(id);
  if (c) charts.push(new Chart(c, config));
}
function linear(title) { return {type: 'linear', title: {display: true, text: title}}; }
function gapSets(key) {
  return DATA.gaps.map((g, i) => ({
    label: 'gap ' + g.label, borderColor: palette[i % palette.length],
    backgroundColor: palette[i % palette.length], pointRadius: 2, stepped: key === 'status',
    data: g.time.map((t, k) => ({x: t, y: g[key][k]}))}));
}
if (DATA.gaps.length) {
  chart('gap-force', {type: 'line', data: {datasets: gapSets('force')},
    options: {scales: {x: linear('total time'), y: linear('normal force (compressive)')}}});
  chart('gap-clearance', {type: 'line', data: {datasets: gapSets('clearance')},
    options: {scales: {x: linear('total time'), y: linear('clearance h')}}});
  const names = ['open', 'closed', 'stick', 'slip'];
  chart('gap-status', {type: 'line', data: {datasets: gapSets('status')},
    options: {clip: false, scales: {x: linear('total time'),
      y: {min: 0, max: 3, ticks: {stepSize: 1, callback: v => names[v] || ''},
          title: {display: true, text: 'status'}}}}});
  chart('contact-set', {type: 'line', data: {datasets: [{label: 'closed gaps (closed, stick, slip)',
      stepped: true, borderColor: palette[0], backgroundColor: palette[0], pointRadius: 2,
      data: DATA.contact_set.map(p => ({x: p[0], y: p[1]}))}]},
    options: {scales: {x: linear('total time'), y: Object.assign(linear('gaps'), {min: 0})}}});
}
if (DATA.energies.length) {
  const names = ['ALLKE', 'ALLSE', 'ALLIE', 'ALLVD', 'ALLFD', 'ALLKL', 'ALLWK', 'ETOTAL'];
  chart('energies', {type: 'line', data: {datasets: names.map((n, i) => ({
      label: n, borderColor: palette[i % palette.length], backgroundColor: palette[i % palette.length],
      pointRadius: 1, data: DATA.energies.map(e => ({x: e[0], y: e[i + 1]}))}))},
    options: {scales: {x: linear('total time'), y: linear('energy')}}});
}
if (DATA.history.length) { // at most 16 curves: the first columns of the history output
  const cols = DATA.history_columns.slice(0, 16);
  chart('history', {type: 'line', data: {datasets: cols.map((n, i) => ({
      label: n, borderColor: palette[i % palette.length], backgroundColor: palette[i % palette.length],
      pointRadius: 1, data: DATA.history.map(r => ({x: r[0], y: r[i + 1]}))}))},
    options: {scales: {x: linear('total time'), y: linear('value')}}});
}
{
  const ok = [], cut = [];
  let it = 0;
  for (const a of DATA.attempts) {
    const into = a.converged ? ok : cut;
    for (const r of a.residuals) { it += 1; into.push({x: it, y: Math.max(r, 1e-16)}); }
    ok.push({x: it + 0.5, y: null}); cut.push({x: it + 0.5, y: null});
  }
  chart('residuals', {type: 'line', data: {datasets: [
      {label: 'converged increments', data: ok, borderColor: palette[0], backgroundColor: palette[0],
       pointRadius: 2},
      {label: 'attempts cut back', data: cut, borderColor: palette[1], backgroundColor: palette[1],
       pointRadius: 4, pointStyle: 'crossRot'}]},
    options: {spanGaps: false, scales: {x: linear('Newton iteration (all increments)'),
      y: {type: 'logarithmic', title: {display: true, text: 'residual / flux'},
          ticks: {callback: v => Number(v).toExponential(0)}}}}});
}
chart('time-split', {type: 'bar', data: {labels: DATA.time_split.map(p => p[0]),
    datasets: [{label: 'seconds', data: DATA.time_split.map(p => p[1]),
                backgroundColor: palette[0]}]},
  options: {indexAxis: 'y', scales: {x: linear('seconds')}}});
function painted(c) {
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 3; i < d.length; i += 64) if (d[i] > 0) n += 1;
  return n > 50;
}
document.body.dataset.charts = String(charts.length);
document.body.dataset.painted =
    String(Array.from(document.querySelectorAll('canvas')).filter(painted).length);
)";

void text(fmt::memory_buffer& out, std::string_view s) {
  append_xml_text(out, s);
}

void canvas(fmt::memory_buffer& out, std::string_view id) {
  fmt::format_to(fmt::appender(out), "<div class=\"chart\"><canvas id=\"{}\"></canvas></div>\n",
                 id);
}

void summary(fmt::memory_buffer& out, const RunSummary& run) {
  auto o = fmt::appender(out);
  if (run.completed) {
    fmt::format_to(o, "<p class=\"ok\">The analysis completed.</p>\n");
  } else {
    fmt::format_to(o, "<p class=\"bad\">The analysis stopped: ");
    text(out, run.failure);
    fmt::format_to(o, "</p>\n");
  }
  const RunStatistics& s = run.stats;
  fmt::format_to(o,
                 "<p>{:.2f} s wall time; {} increments in {} attempts, {} Newton iterations, "
                 "{} factorisations, {} linear solves; peak memory {:.0f} MB.</p>\n",
                 run.wall_seconds, s.increments, s.attempts, s.iterations, s.factorizations,
                 s.linear_solves, run.peak_memory_kb / 1024.0);
}

void checks_table(fmt::memory_buffer& out, const std::vector<StepSummary>& steps) {
  auto o = fmt::appender(out);
  fmt::format_to(o, "<table><tr><th>step</th><th>procedure</th><th>result</th><th>increments"
                    "</th><th>attempts</th><th>iterations</th><th>gaps open / closed / stick / "
                    "slip</th><th>max penetration (element)</th><th>max tension in a closed gap"
                    "</th><th>equilibrium error / force scale</th><th>heat balance error / scale"
                    "</th></tr>\n");
  for (const StepSummary& s : steps) {
    const StepChecks& c = s.checks;
    fmt::format_to(o, "<tr><td>{} ", s.step);
    text(out, s.name);
    fmt::format_to(o, "</td><td>");
    text(out, s.procedure);
    fmt::format_to(o, "</td><td class=\"{}\">{}</td><td>{}</td><td>{}</td><td>{}</td>",
                   s.converged ? "ok" : "bad", s.converged ? "converged" : "stopped", s.increments,
                   s.attempts, s.iterations);
    fmt::format_to(o, "<td>{} / {} / {} / {}</td><td>{:.4g} ({})</td><td>{:.4g}</td>", c.n_open,
                   c.n_closed, c.n_stick, c.n_slip, c.max_penetration, c.max_penetration_elem,
                   c.max_tensile_force);
    fmt::format_to(o, "<td>{:.3g} / {:.3g}</td>", c.equilibrium_error, c.force_scale);
    if (c.thermal)
      fmt::format_to(o, "<td>{:.3g} / {:.3g}</td></tr>\n", c.heat_balance_error, c.heat_scale);
    else
      fmt::format_to(o, "<td>-</td></tr>\n");
  }
  fmt::format_to(o, "</table>\n");
}

/// A *FREQUENCY step's modes: eigenvalue, frequency, generalized mass and the effective masses
/// in X, Y, Z as fractions of the free DOFs' mass.
void modes_table(fmt::memory_buffer& out, int step, const EigenSummary& m) {
  auto o = fmt::appender(out);
  if (m.buckling) {
    fmt::format_to(o,
                   "<h3>Step {} (buckling)</h3>\n<table><tr><th>mode</th><th>eigenvalue (load "
                   "multiplier)</th></tr>\n",
                   step);
    for (const ModeInfo& mi : m.modes)
      fmt::format_to(o, "<tr><td>{}</td><td>{:.6g}</td></tr>\n", mi.mode, mi.eigenvalue);
    fmt::format_to(o, "</table>\n");
    return;
  }
  fmt::format_to(o,
                 "<h3>Step {}</h3>\n<table><tr><th>mode</th><th>eigenvalue</th><th>frequency "
                 "(cycles/time)</th><th>generalized mass</th><th>effective mass X</th><th>"
                 "Y</th><th>Z</th></tr>\n",
                 step);
  const auto share = [&](const ModeInfo& mi, int i) {
    return m.model_mass[i] > 0.0 ? fmt::format("{:.4g} ({:.1f} %)", mi.effective_mass[i],
                                               100.0 * mi.effective_mass[i] / m.model_mass[i])
                                 : fmt::format("{:.4g}", mi.effective_mass[i]);
  };
  for (const ModeInfo& mi : m.modes)
    fmt::format_to(o,
                   "<tr><td>{}</td><td>{:.6g}</td><td>{:.6g}</td><td>{:.4g}</td><td>{}</td>"
                   "<td>{}</td><td>{}</td></tr>\n",
                   mi.mode, mi.eigenvalue, mi.frequency(), mi.generalized_mass, share(mi, 0),
                   share(mi, 1), share(mi, 2));
  fmt::format_to(o, "</table>\n");
}

} // namespace

void write_report_page(fmt::memory_buffer& out, const ReportContent& c) {
  auto o = fmt::appender(out);
  fmt::format_to(o, "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                    "<title>gapfem report: ");
  text(out, c.job);
  fmt::format_to(o, "</title>\n{}<script>\n", kStyle);
  out.append(embedded::chart_js, embedded::chart_js + embedded::chart_js_size);
  fmt::format_to(o, "\n</script></head>\n<body>\n<h1>gapfem run report: ");
  text(out, c.job);
  fmt::format_to(o, "</h1>\n");
  if (c.run) summary(out, *c.run);
  if (c.has_gaps) {
    fmt::format_to(o, "<h2>Gaps</h2>\n<p class=\"note\">{}</p>\n",
                   c.named_gaps ? "The gaps named with --report-gaps."
                                : "The most loaded gaps (largest normal force in any converged "
                                  "increment); name others with --report-gaps LABEL,SET,...");
    canvas(out, "gap-force");
    canvas(out, "gap-clearance");
    canvas(out, "gap-status");
    fmt::format_to(o, "<h2>Contact set</h2>\n");
    canvas(out, "contact-set");
  }
  if (c.has_energies) {
    fmt::format_to(o, "<h2>Energies</h2>\n<p class=\"note\">Whole-model energies after each "
                      "increment of the dynamic steps (ETOTAL = ALLKE + ALLIE + ALLVD + ALLFD + "
                      "ALLKL - ALLWK; ALLSE, the recoverable strain energy, is part of ALLIE; "
                      "docs/theory/dynamics.md).</p>\n");
    canvas(out, "energies");
  }
  if (c.has_history) {
    fmt::format_to(o, "<h2>History output</h2>\n<p class=\"note\">The *OUTPUT, HISTORY values "
                      "(up to 16 curves; all of them in job.results.json, each step's "
                      "history.values).</p>\n");
    canvas(out, "history");
  }
  if (c.modes && !c.modes->empty()) {
    fmt::format_to(o, "<h2>Natural frequencies</h2>\n<p class=\"note\">The modes of the "
                      "*FREQUENCY steps about their base states (effective masses as a share of "
                      "the free degrees of freedom's mass; docs/theory/frequency.md).</p>\n");
    for (const auto& [step, m] : *c.modes) modes_table(out, step, m);
  }
  fmt::format_to(o, "<h2>Newton iterations</h2>\n<p class=\"note\">The residual after each "
                    "iteration of every attempt; attempts that did not converge (cut back) in "
                    "red.</p>\n");
  canvas(out, "residuals");
  if (c.steps) {
    fmt::format_to(o, "<h2>Step self-checks</h2>\n");
    checks_table(out, *c.steps);
  }
  fmt::format_to(o, "<h2>Where the time went</h2>\n");
  canvas(out, "time-split");
  if (c.run && !c.run->warnings.empty()) {
    fmt::format_to(o, "<h2>Warnings ({})</h2>\n<ul>\n", c.run->warnings.size());
    for (const auto& w : c.run->warnings) {
      fmt::format_to(o, "<li>");
      text(out, w);
      fmt::format_to(o, "</li>\n");
    }
    fmt::format_to(o, "</ul>\n");
  }
  // the data: JSON with "</" written as "<\/" so no string can end the script element
  fmt::format_to(o, "<script>\nconst DATA = ");
  std::string_view d = c.data_json;
  for (std::size_t at = d.find("</"); at != std::string_view::npos; at = d.find("</")) {
    out.append(d.data(), d.data() + at);
    out.append(std::string_view("<\\/"));
    d.remove_prefix(at + 2);
  }
  out.append(d.data(), d.data() + d.size());
  fmt::format_to(o, ";\n{}</script>\n</body></html>\n", kScript);
}

} // namespace gapfem::output
