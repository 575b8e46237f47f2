// *AMPLITUDE: named time variations of loads and boundary conditions.
#include "io/inp/handlers.hpp"

#include <fmt/format.h>

namespace gapfem::inp {

void handle_amplitude(BuildState& s, const Keyword& kw) {
  const std::string name = name_param(kw, "NAME", true);
  if (const auto it = s.amplitude_index.find(name); it != s.amplitude_index.end())
    throw InputError(kw.loc, fmt::format("amplitude {}", name),
                     fmt::format("this amplitude is defined twice (first at {}); use another NAME",
                                 s.model.amplitudes[it->second].loc.str()));
  Amplitude a;
  a.name = name;
  a.loc = kw.loc;
  a.time = enum_param(kw, "TIME", {"STEP TIME", "TOTAL TIME"}, 0) == 0 ? Amplitude::TimeBase::Step
                                                                       : Amplitude::TimeBase::Total;
  a.absolute = enum_param(kw, "VALUE", {"RELATIVE", "ABSOLUTE"}, 0) == 1;
  enum_param(kw, "DEFINITION", {"TABULAR"}, 0);
  bool ok = true;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(8, "up to four pairs of time, amplitude");
    std::size_t last = line.fields.size();
    while (last > 0 && line.fields[last - 1].empty()) --last;
    if (last % 2 != 0) {
      ok = false;
      r.fail("", "give time, amplitude pairs: this line has an odd number of values");
    }
    for (std::size_t i = 0; i < last; i += 2) {
      const double t = r.real(i, "time");
      const double v = r.real(i + 1, "amplitude");
      if (!a.t.empty() && !(t > a.t.back())) {
        ok = false;
        r.fail(fmt::format("time {}", t),
               fmt::format("amplitude times must increase strictly; {} follows {}", t, a.t.back()));
      }
      a.t.push_back(t);
      a.a.push_back(v);
    }
  });
  if (a.t.empty() && ok)
    throw InputError(kw.loc, fmt::format("amplitude {}", name),
                     "no time, amplitude pairs are given; add data lines t1, a1, t2, a2, …");
  s.amplitude_index[name] = static_cast<int>(s.model.amplitudes.size());
  s.model.amplitudes.push_back(std::move(a));
}

} // namespace gapfem::inp
