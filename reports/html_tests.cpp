#include "reports/html_escape.h"
#include "reports/html_sections.h"
#include "reports/image_links.h"

#include <algorithm>
#include <set>
#include <vector>

namespace reports::html {
namespace {

// Frame verdicts are Pass or Fail; an unknown one is shown as not passing.
bool framePassed(const Json& frame) {
  return comparison::parseVerdict(textField(frame, "verdict")) == comparison::Verdict::Pass;
}


// Null in a result means NaN or infinity (results.json has neither).
std::string channels(const Json& values, bool nullIsNonFinite = false) {
  std::string text;
  for (const Json& v : values)
    text += (text.empty() ? "" : ", ") + (v.is_null() && nullIsNonFinite ? "non-finite" : formatValue(v, 6));
  return "(" + text + ")";
}

// The allowed interval per channel: reference +- tolerance * tolerance_scale
// (the pixel's, as the runner writes it, else the metrics', else 1).
std::string allowedBounds(const Json& pixel, double metricsScale) {
  const double scale = numberField(pixel, "tolerance_scale").value_or(metricsScale);
  const Json& reference = arrayField(pixel, "reference");
  const Json& tolerance = arrayField(pixel, "tolerance");
  std::string text;
  for (std::size_t c = 0; c < std::min(reference.size(), tolerance.size()); ++c) {
    std::string low = "-", high = "-";
    if (reference[c].is_number() && tolerance[c].is_number()) {
      low = formatValue(Json(reference[c].get<double>() - tolerance[c].get<double>() * scale), 6);
      high = formatValue(Json(reference[c].get<double>() + tolerance[c].get<double>() * scale), 6);
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

void worstPixels(std::ostream& out, const Json& metrics) {
  const Json& worst = arrayField(metrics, "worst");
  if (worst.empty()) return;
  const double scale = numberField(metrics, "tolerance_scale").value_or(1.0);
  out << "<table>\n<tr><th>x</th><th>y</th><th>result</th><th>reference</th><th>tolerance</th>"
         "<th>allowed per channel</th></tr>\n";
  for (const Json& p : worst)
    out << "<tr>" << numberCell(formatField(p, "x")) << numberCell(formatField(p, "y"))
        << cell(channels(arrayField(p, "result"), true)) << cell(channels(arrayField(p, "reference")))
        << cell(channels(arrayField(p, "tolerance"))) << cell(allowedBounds(p, scale)) << "</tr>\n";
  out << "</table>\n";
}

void attentionSection(std::ostream& out, const Page& page, const Json& test) {
  const std::string name = textField(test, "name");
  const std::string verdict = textField(test, "verdict");
  const Json& metrics = objectField(test, "metrics");
  out << "<section class=\"test " << escapeText(verdict) << "\" id=\"" << escapeText(testAnchor(name)) << "\">\n<h3>"
      << escapeText(name) << ' ' << verdictBadge(verdict) << "</h3>\n";
  if (!textField(test, "description").empty()) out << "<p>" << escapeText(textField(test, "description")) << "</p>\n";
  out << "<dl class=\"meta\">\n";
  const auto row = [&](std::string_view term, const std::string& value) {
    out << "<dt>" << escapeText(term) << "</dt><dd>" << escapeText(value.empty() ? "-" : value) << "</dd>\n";
  };
  row("scene file", textField(test, "scene_file"));
  row("verdict (before expected failures)", textField(test, "raw_verdict"));
  if (!textField(test, "expected_reason").empty()) row("expected failure", textField(test, "expected_reason"));
  if (!metrics.empty()) {  // none after a crash or timeout
    std::string failing = formatField(metrics, "failing_pixels") + " of " + formatField(metrics, "compared_pixels") +
                          " compared (" + formatField(metrics, "masked_pixels") + " masked, " +
                          formatField(metrics, "max_failing_pixels") + " allowed)";
    row("failing pixels", failing);
    if (numberField(metrics, "non_finite_pixels").value_or(0) > 0)
      row("non-finite pixels", formatField(metrics, "non_finite_pixels"));
    row("max error", formatMetric(metrics, "max_abs_error", 6));
    row("rmse", formatMetric(metrics, "rmse", 6));
    row("tightness (max error / tolerance)", formatMetric(metrics, "tightness", 6));
  }
  if (!test.is_object() || !test.contains("popping_score") || !test["popping_score"].is_null())
    row("popping score", formatField(test, "popping_score", 6));
  row("total time", formatField(objectField(test, "timings_ms"), "total", 6) + " ms");
  out << "</dl>\n";
  if (!textField(test, "message").empty()) out << "<pre>" << escapeText(textField(test, "message")) << "</pre>\n";

  const Json& evidence = objectField(test, "evidence");
  // The viewer (reports/viewer/README.md): swipe, zoom and probe the float
  // images of the failing frame, in the page itself.
  if (const std::string viewer = textField(evidence, "viewer"); !viewer.empty()) {
    const std::string href = escapeText(imageHref(viewer, page.runDir, page.reportDir));
    out << "<p>Evidence viewer of frame " << escapeText(formatField(evidence, "frame")) << " (keys 1-4 switch "
        << "result, reference, tolerance and error mask; s swipes; the pointer probes a pixel's floats): <a href=\""
        << href << "\">open it alone</a></p>\n<iframe class=\"viewer\" src=\"" << href
        << "\" title=\"evidence viewer of " << escapeText(name) << "\" loading=\"lazy\"></iframe>\n";
  }
  // results.json is read without trusting it: only a boolean false means it.
  const bool imagesDropped = evidence.contains("images_kept") && evidence["images_kept"].is_boolean() &&
                             !evidence["images_kept"].get<bool>();
  if (imagesDropped)
    out << "<p>No images: this failure came after the first --evidence-limit "
        << escapeText(formatField(page.results, "evidence_limit")) << " with evidence; its numbers are below.</p>\n";
  bool anyImage = false;
  for (const auto& [key, label] : {std::pair{"result_png", "result"}, std::pair{"reference_png", "reference"},
                                   std::pair{"error_mask_png", "error mask"}})
    if (!textField(evidence, key).empty()) {
      if (!anyImage) out << "<div>\n<p>Evidence of frame " << escapeText(formatField(evidence, "frame")) << ":</p>\n";
      anyImage = true;
      figure(out, page, textField(evidence, key), label);
    }
  // A CI error (Crash, Timeout) is a test that did not run to its end.
  const bool ended = outcomeOf(verdict) == Outcome::Error;
  if (anyImage) out << "</div>\n";
  else if (!imagesDropped) out << "<p>No images: " << (ended ? "the test ended before a comparison." : "the run wrote none.") << "</p>\n";
  if (!textField(evidence, "summary_json").empty())
    out << "<p>Comparison summary: <a href=\""
        << escapeText(imageHref(textField(evidence, "summary_json"), page.runDir, page.reportDir)) << "\">"
        << escapeText(textField(evidence, "summary_json")) << "</a></p>\n";
  worstPixels(out, metrics);
  std::string frames;
  for (const Json& frame : arrayField(test, "frames"))
    if (!framePassed(frame))
      frames += (frames.empty() ? "" : ", ") + formatField(frame, "frame") + " " + textField(frame, "verdict");
  if (!frames.empty()) out << "<p>Frames that did not pass: " << escapeText(frames) << "</p>\n";
  out << "</section>\n";
}

bool animated(const Json& test) {
  return arrayField(test, "frames").size() > 1 || numberField(test, "popping_score").has_value();
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
  std::vector<const Json*> tests;
  for (const Json& test : arrayField(page.results, "tests"))
    if (needsAttention(textField(test, "verdict"))) tests.push_back(&test);
  out << "<h2 id=\"attention\">Tests that need attention (" << tests.size() << ")</h2>\n";
  if (tests.empty()) out << "<p>None: no Fail, Crash, Timeout, UnexpectedPass or QualityWarning.</p>\n";
  for (const Json* test : tests) attentionSection(out, page, *test);
}

void detectedMismatchSections(std::ostream& out, const Page& page) {
  // expect_fail scenes (SPEC 7) pass by failing: their evidence shows how far
  // the known mismatch (e.g. legacy baked falloff against real time) is off.
  std::vector<const Json*> tests;
  for (const Json& test : arrayField(page.results, "tests")) {
    const Json& metrics = objectField(test, "metrics");
    const bool passed = comparison::parseVerdict(textField(test, "verdict")) == comparison::Verdict::Pass;
    if (metrics.is_object() && metrics.value("expect_fail", false) && passed)
      tests.push_back(&test);
  }
  if (tests.empty()) return;
  out << "<h2 id=\"expected-mismatches\">Known mismatches detected (" << tests.size() << ")</h2>\n"
      << "<p>These scenes are marked <code>expect_fail</code>: a correct implementation must fail their "
         "comparison. They pass because it did; below is by how much.</p>\n";
  for (const Json* test : tests) attentionSection(out, page, *test);
}

void allTestsTable(std::ostream& out, const Page& page) {
  const Json& tests = arrayField(page.results, "tests");
  out << "<h2 id=\"tests\">All tests (" << tests.size() << ")</h2>\n<table>\n<tr><th>test</th><th>verdict</th>"
         "<th>tightness</th><th>max error</th><th>failing pixels</th><th>popping score</th><th>total ms</th></tr>\n";
  for (const Json& test : tests) {
    const Json& metrics = objectField(test, "metrics");
    const std::string verdict = textField(test, "verdict");
    out << "<tr" << (needsAttention(verdict) ? " class=\"bad\"" : "") << "><td>" << testLink(test) << "</td><td>"
        << verdictBadge(verdict) << "</td>" << numberCell(formatMetric(metrics, "tightness"))
        << numberCell(formatMetric(metrics, "max_abs_error")) << numberCell(formatField(metrics, "failing_pixels"))
        << numberCell(formatField(test, "popping_score")) << numberCell(formatField(objectField(test, "timings_ms"), "total", 6))
        << "</tr>\n";
  }
  out << "</table>\n";
}

void poppingTables(std::ostream& out, const Page& page) {
  // Scene "group.scene" -> its animated tests, in order of first appearance.
  // A scene is animated when any of its tests shows it: a test that timed out
  // after one frame still belongs in its table.
  const auto sceneOf = [](const Json& test) { return textField(test, "group") + "." + textField(test, "scene"); };
  std::set<std::string> animatedScenes;
  for (const Json& test : arrayField(page.results, "tests"))
    if (animated(test)) animatedScenes.insert(sceneOf(test));
  std::vector<std::pair<std::string, std::vector<const Json*>>> scenes;
  for (const Json& test : arrayField(page.results, "tests")) {
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
    for (const Json* test : tests)
      for (const Json& frame : arrayField(*test, "frames"))
        if (numberField(frame, "frame")) frameNumbers.insert((long long)*numberField(frame, "frame"));
    out << "<h3>" << escapeText(scene) << "</h3>\n<table>\n<tr><th rowspan=\"2\">frame</th>";
    for (const Json* test : tests) out << "<th colspan=\"3\">" << escapeText(textField(*test, "backend")) << "</th>";
    out << "</tr>\n<tr>";
    for (std::size_t i = 0; i < tests.size(); ++i) out << "<th>verdict</th><th>error vs ideal</th><th>jump</th>";
    out << "</tr>\n";
    for (const long long number : frameNumbers) {
      out << "<tr>" << numberCell(std::to_string(number));
      for (const Json* test : tests) {
        const Json* found = nullptr;
        for (const Json& frame : arrayField(*test, "frames"))
          if (numberField(frame, "frame") == double(number)) found = &frame;
        if (!found) {
          out << "<td></td><td></td><td></td>";
          continue;
        }
        out << "<td>" << verdictBadge(textField(*found, "verdict")) << "</td>"
            << numberCell(formatField(*found, "ideal_error")) << numberCell(formatField(*found, "popping_jump"));
      }
      out << "</tr>\n";
    }
    out << "<tr><th>score</th>";
    for (const Json* test : tests)
      out << "<td>" << verdictBadge(textField(*test, "verdict")) << "</td><td></td>"
          << numberCell(formatField(*test, "popping_score"));
    out << "</tr>\n</table>\n";
  }
}

}  // namespace reports::html
