// The sections of the benchmark pages (bench_report.cpp puts them together),
// each written to a stream from the model and the entries the page shows:
// `byBackend` on the overview (colours and lines per backend), else per mode
// or quantity on a backend's page. Internal to reports/.
#pragma once

#include "reports/bench_page_model.h"

#include <ostream>

namespace reports::benchpages {

// bench_speed_error.cpp: the speed-against-error scatter per scene with its
// Pareto front, and its table.
void speedErrorSection(std::ostream& out, const BenchModel& m, const Entries& candidates, bool byBackend);
// bench_speed_error.cpp too: SPEC 3.9's shadow-map modes (`shadows-<filter>-<N>`)
// alone, per backend, with their Pareto front of resolution and filter and
// the shadow passes' own time; nothing when none ran.
void shadowMapSection(std::ostream& out, const BenchModel& m, const Entries& candidates);
// bench_lightmap_section.cpp: the lightmap-N modes against N; nothing when none ran.
void lightmapSection(std::ostream& out, const BenchModel& m, const Entries& candidates, bool byBackend);
// bench_curve_sections.cpp: frame time against each curve's load, and the
// CPU preparation curves with their complexity fits.
void costCurveSection(std::ostream& out, const BenchModel& m, const Entries& candidates, bool byBackend);
void prepareSection(std::ostream& out, const BenchModel& m);
// bench_curve_sections.cpp too: each backend's two-term limit
// (two_term_limit.h) with its residual beside the flop roof.
void twoTermSection(std::ostream& out, const BenchModel& m, const Entries& candidates);

}  // namespace reports::benchpages
