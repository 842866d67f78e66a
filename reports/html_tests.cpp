#include "reports/html_escape.h"
#include "reports/html_sections.h"
#include "reports/image_links.h"

#include <algorithm>
#include <set>
#include <vector>

namespace reports::html {
namespace {

// A channel that is none was not finite (results.json has no NaN or infinity).
std::string channels(const std::array<results::Measured, 3>& values, bool noneIsNonFinite = false) {
  std::string text;
  for (const results::Measured& v : values)
    text += (text.empty() ? "" : ", ") + (v ? formatNumber(*v, 6) : std::string(noneIsNonFinite ? "non-finite" : "-"));
  return "(" + text + ")";
}

// The allowed interval per channel: reference +- tolerance * tolerance_scale.
std::string allowedBounds(const results::WorstPixel& pixel) {
  std::string text;
  for (std::size_t c = 0; c < 3; ++c) {
    std::string low = "-", high = "-";
    if (pixel.reference[c] && pixel.tolerance[c]) {
      low = formatNumber(*pixel.reference[c] - *pixel.tolerance[c] * pixel.toleranceScale, 6);
      high = formatNumber(*pixel.reference[c] + *pixel.tolerance[c] * pixel.toleranceScale, 6);
    }
    if (c) text += ' ';
    text += '[';  // appended, not `"[" + ...`: GCC 12's false -Wrestrict (bug 105329)
    text += low;
    text += ", ";
    text += high;
    text += ']';
  }
  return text;
}

void worstPixels(std::ostream& out, const results::Metrics& metrics) {
  if (metrics.worst.empty()) return;
  out << "<table>\n<tr><th>x</th><th>y</th><th>result</th><th>reference</th><th>tolerance</th>"
         "<th>allowed per channel</th></tr>\n";
  for (const results::WorstPixel& p : metrics.worst)
    out << "<tr>" << numberCell(std::to_string(p.x)) << numberCell(std::to_string(p.y))
        << cell(channels(p.result, true)) << cell(channels(p.reference)) << cell(channels(p.tolerance))
        << cell(allowedBounds(p)) << "</tr>\n";
  out << "</table>\n";
}

std::string totalMs(const results::TestRecord& test) {
  return test.timingsMs ? formatNumber(test.timingsMs->total, 6) : "-";
}

void attentionSection(std::ostream& out, const Page& page, const results::TestRecord& test) {
  const std::string verdict = test.verdictWord();
  out << "<section class=\"test " << escapeText(verdict) << "\" id=\"" << escapeText(testAnchor(test.name)) << "\">\n<h3>"
      << escapeText(test.name) << ' ' << verdictBadge(verdict) << "</h3>\n";
  if (!test.description.empty()) out << "<p>" << escapeText(test.description) << "</p>\n";
  out << "<dl class=\"meta\">\n";
  const auto row = [&](std::string_view term, const std::string& value) {
    out << "<dt>" << escapeText(term) << "</dt><dd>" << escapeText(value.empty() ? "-" : value) << "</dd>\n";
  };
  row("scene file", test.sceneFile);
  row("verdict (before expected failures)", std::string(comparison::verdictName(test.rawVerdict)));
  if (!test.expectedReason.empty()) row("expected failure", test.expectedReason);
  if (const auto& m = test.metrics) {  // none after a crash or timeout
    row("failing pixels", std::to_string(m->failingPixels) + " of " + std::to_string(m->comparedPixels) +
                              " compared (" + std::to_string(m->maskedPixels) + " masked, " +
                              std::to_string(m->maxFailingPixels) + " allowed)");
    if (m->nonFinitePixels > 0) row("non-finite pixels", std::to_string(m->nonFinitePixels));
    row("max error", formatMeasured(m->maxAbsError, 6));
    row("rmse", formatMeasured(m->rmse, 6));
    row("tightness (max error / tolerance)", formatMeasured(m->tightness, 6));
  }
  if (test.poppingScore) row("popping score", formatNumber(*test.poppingScore, 6));
  row("total time", totalMs(test) + " ms");
  out << "</dl>\n";
  if (!test.message.empty()) out << "<pre>" << escapeText(test.message) << "</pre>\n";

  const results::EvidenceRecord evidence = test.evidence.value_or(results::EvidenceRecord{});
  const std::string frame = std::to_string(evidence.frame);
  // The viewer (reports/viewer/README.md): swipe, zoom and probe the float
  // images of the failing frame, in the page itself.
  if (!evidence.viewer.empty()) {
    const std::string href = escapeText(imageHref(evidence.viewer, page.runDir, page.reportDir));
    out << "<p>Evidence viewer of frame " << escapeText(frame) << " (keys 1-4 switch "
        << "result, reference, tolerance and error mask; s swipes; the pointer probes a pixel's floats): <a href=\""
        << href << "\">open it alone</a></p>\n<iframe class=\"viewer\" src=\"" << href
        << "\" title=\"evidence viewer of " << escapeText(test.name) << "\" loading=\"lazy\"></iframe>\n";
  }
  const bool imagesDropped = test.evidence && !evidence.imagesKept;
  if (imagesDropped)
    out << "<p>No images: this failure came after the first --evidence-limit "
        << escapeText(page.run.evidenceLimit ? std::to_string(*page.run.evidenceLimit) : "-")
        << " with evidence; its numbers are below.</p>\n";
  bool anyImage = false;
  for (const auto& [path, label] : {std::pair{&evidence.resultPng, "result"}, std::pair{&evidence.referencePng, "reference"},
                                    std::pair{&evidence.errorMaskPng, "error mask"}})
    if (!path->empty()) {
      if (!anyImage) out << "<div>\n<p>Evidence of frame " << escapeText(frame) << ":</p>\n";
      anyImage = true;
      figure(out, page, *path, label);
    }
  // A CI error (Crash, Timeout) is a test that did not run to its end.
  const bool ended = test.ciOutcome() == Outcome::Error;
  if (anyImage) out << "</div>\n";
  else if (!imagesDropped) out << "<p>No images: " << (ended ? "the test ended before a comparison." : "the run wrote none.") << "</p>\n";
  if (!evidence.summaryJson.empty())
    out << "<p>Comparison summary: <a href=\""
        << escapeText(imageHref(evidence.summaryJson, page.runDir, page.reportDir)) << "\">"
        << escapeText(evidence.summaryJson) << "</a></p>\n";
  if (test.metrics) worstPixels(out, *test.metrics);
  std::string frames;
  if (test.frames)
    for (const results::FrameRecord& f : *test.frames)
      if (f.verdict != comparison::Verdict::Pass)
        frames += (frames.empty() ? "" : ", ") + std::to_string(f.frame) + " " +
                  std::string(comparison::verdictName(f.verdict));
  if (!frames.empty()) out << "<p>Frames that did not pass: " << escapeText(frames) << "</p>\n";
  out << "</section>\n";
}

bool animated(const results::TestRecord& test) {
  return (test.frames && test.frames->size() > 1) || test.poppingScore.has_value();
}

}  // namespace

void figure(std::ostream& out, const Page& page, const std::string& runRelative, std::string_view label) {
  const std::string href = escapeText(imageHref(runRelative, page.runDir, page.reportDir));
  out << "<figure><a href=\"" << href << "\"><img src=\"" << href << "\" alt=\"" << escapeText(label) << ": "
      << escapeText(runRelative) << "\"></a><figcaption>" << escapeText(label) << "<br>" << escapeText(runRelative);
  if (!imageExists(runRelative, page.runDir)) out << " <span class=\"missing\">(missing when the report was written)</span>";
  out << "</figcaption></figure>\n";
}

void attentionSections(std::ostream& out, const Page& page) {
  std::vector<const results::TestRecord*> tests;
  for (const results::TestRecord& test : page.run.tests)
    if (test.needsAttention()) tests.push_back(&test);
  out << "<h2 id=\"attention\">Tests that need attention (" << tests.size() << ")</h2>\n";
  if (tests.empty()) out << "<p>None: no Fail, Crash, Timeout, UnexpectedPass or QualityWarning.</p>\n";
  for (const results::TestRecord* test : tests) attentionSection(out, page, *test);
}

void detectedMismatchSections(std::ostream& out, const Page& page) {
  // expect_fail scenes (SPEC 7) pass by failing: their evidence shows how far
  // the known mismatch (e.g. legacy baked falloff against real time) is off.
  std::vector<const results::TestRecord*> tests;
  for (const results::TestRecord& test : page.run.tests)
    if (test.metrics && test.metrics->expectFail && test.knownVerdict() == comparison::Verdict::Pass)
      tests.push_back(&test);
  if (tests.empty()) return;
  out << "<h2 id=\"expected-mismatches\">Known mismatches detected (" << tests.size() << ")</h2>\n"
      << "<p>These scenes are marked <code>expect_fail</code>: a correct implementation must fail their "
         "comparison. They pass because it did; below is by how much.</p>\n";
  for (const results::TestRecord* test : tests) attentionSection(out, page, *test);
}

void allTestsTable(std::ostream& out, const Page& page) {
  const std::vector<results::TestRecord>& tests = page.run.tests;
  out << "<h2 id=\"tests\">All tests (" << tests.size() << ")</h2>\n<table>\n<tr><th>test</th><th>verdict</th>"
         "<th>tightness</th><th>max error</th><th>failing pixels</th><th>popping score</th><th>total ms</th></tr>\n";
  for (const results::TestRecord& test : tests) {
    const auto& m = test.metrics;
    out << "<tr" << (test.needsAttention() ? " class=\"bad\"" : "") << "><td>" << testLink(test) << "</td><td>"
        << verdictBadge(test.verdictWord()) << "</td>" << numberCell(m ? formatMeasured(m->tightness) : "-")
        << numberCell(m ? formatMeasured(m->maxAbsError) : "-")
        << numberCell(m ? std::to_string(m->failingPixels) : "-") << numberCell(formatOptional(test.poppingScore))
        << numberCell(totalMs(test)) << "</tr>\n";
  }
  out << "</table>\n";
}

void poppingTables(std::ostream& out, const Page& page) {
  // Scene "group.scene" -> its animated tests, in order of first appearance.
  // A scene is animated when any of its tests shows it: a test that timed out
  // after one frame still belongs in its table.
  const auto sceneOf = [](const results::TestRecord& test) { return test.group + "." + test.scene; };
  std::set<std::string> animatedScenes;
  for (const results::TestRecord& test : page.run.tests)
    if (animated(test)) animatedScenes.insert(sceneOf(test));
  std::vector<std::pair<std::string, std::vector<const results::TestRecord*>>> scenes;
  for (const results::TestRecord& test : page.run.tests) {
    const std::string scene = sceneOf(test);
    if (!animatedScenes.count(scene)) continue;
    auto it = std::find_if(scenes.begin(), scenes.end(), [&](const auto& s) { return s.first == scene; });
    if (it == scenes.end()) it = scenes.insert(scenes.end(), {scene, {}});
    it->second.push_back(&test);
  }
  out << "<h2 id=\"popping\">Popping (animated scenes)</h2>\n";
  if (scenes.empty()) {
    out << "<p>No animated scenes in this run.</p>\n";
    return;
  }
  out << "<p>Per frame: the verdict, the largest error against the <code>--ideal</code> reference, and the "
         "popping jump <code>max over pixels |e_f - e_(f-1)|</code> (SPEC 6). The score is the largest jump.</p>\n";
  for (const auto& [scene, tests] : scenes) {
    std::set<long long> frameNumbers;
    for (const results::TestRecord* test : tests)
      if (test->frames)
        for (const results::FrameRecord& frame : *test->frames) frameNumbers.insert(frame.frame);
    out << "<h3>" << escapeText(scene) << "</h3>\n<table>\n<tr><th rowspan=\"2\">frame</th>";
    for (const results::TestRecord* test : tests) out << "<th colspan=\"3\">" << escapeText(test->backend) << "</th>";
    out << "</tr>\n<tr>";
    for (std::size_t i = 0; i < tests.size(); ++i) out << "<th>verdict</th><th>error vs ideal</th><th>jump</th>";
    out << "</tr>\n";
    for (const long long number : frameNumbers) {
      out << "<tr>" << numberCell(std::to_string(number));
      for (const results::TestRecord* test : tests) {
        const results::FrameRecord* found = nullptr;
        if (test->frames)
          for (const results::FrameRecord& frame : *test->frames)
            if (frame.frame == number) found = &frame;
        if (!found) {
          out << "<td></td><td></td><td></td>";
          continue;
        }
        out << "<td>" << verdictBadge(comparison::verdictName(found->verdict)) << "</td>"
            << numberCell(formatOptional(found->idealError)) << numberCell(formatOptional(found->poppingJump));
      }
      out << "</tr>\n";
    }
    out << "<tr><th>score</th>";
    for (const results::TestRecord* test : tests)
      out << "<td>" << verdictBadge(test->verdictWord()) << "</td><td></td>"
          << numberCell(formatOptional(test->poppingScore));
    out << "</tr>\n</table>\n";
  }
}

}  // namespace reports::html
