// The report's light budgets (SPEC 5.5; results.json `budgets`, written by
// runner/run_budgets.cpp): each scene whose budgets cut a light shows its
// maps and figures beside its verdicts on every backend; each scene whose
// budgets cut nothing says so in one line.
#include "reports/html_escape.h"
#include "reports/html_sections.h"

#include <map>
#include <string>
#include <vector>

namespace reports::html {
namespace {

// A scene's verdicts, "vulkan Pass, gl-egl Pass, ...", from the tests table.
std::string verdictsOf(const Page& page, const std::string& scene) {
  std::string text;
  for (const Json& test : arrayField(page.results, "tests")) {
    if (textField(test, "group") + "." + textField(test, "scene") != scene) continue;
    if (!text.empty()) text += " ";
    text += escapeText(textField(test, "backend")) + " " + verdictBadge(textField(test, "verdict"));
  }
  return text.empty() ? "no test of this scene ran" : text;
}

void sceneWithCuts(std::ostream& out, const Page& page, const std::string& scene, const Json& budget) {
  out << "<h3 id=\"budget-" << escapeText(scene) << "\">" << escapeText(scene) << "</h3>\n<p>" << verdictsOf(page, scene)
      << "</p>\n";
  const Json& frames = arrayField(budget, "frames");
  out << "<table>\n<tr><th>frame</th><th>pixels cut</th><th>largest loss</th><th>summed loss</th>"
         "<th>largest relative loss</th><th>popping score</th></tr>\n";
  for (const Json& frame : frames) {
    out << "<tr>" << numberCell(formatField(frame, "frame")) << numberCell(formatField(frame, "pixels_cut"))
        << numberCell(formatField(frame, "largest_loss")) << numberCell(formatField(frame, "summed_loss"))
        << numberCell(formatField(frame, "largest_relative_loss")) << numberCell(formatField(frame, "popping_score"))
        << "</tr>\n";
  }
  out << "</table>\n";
  const Json& images = objectField(budget, "images");
  const std::string mapsFrame = formatField(budget, "maps_frame");
  out << "<div>\n";
  for (const auto& [key, label] : std::vector<std::pair<std::string, std::string>>{
           {"reach", "reach (frame " + mapsFrame + ")"},
           {"kept", "kept (frame " + mapsFrame + ")"},
           {"loss", "loss (frame " + mapsFrame + ")"},
           {"kept_strip", "kept, every frame"}})
    if (images.contains(key)) figure(out, page, textField(images, key), label);
  out << "</div>\n";
  const Json& lights = arrayField(budget, "lights_not_kept");
  if (lights.empty()) return;
  out << "<table>\n<tr><th>light (frame " << escapeText(mapsFrame)
      << ")</th><th>reaches</th><th>kept</th><th>not kept</th><th>cut by the frame (SPEC 5.1)</th>"
         "<th>left out of the object's list (SPEC 5.2)</th></tr>\n";
  for (const Json& light : lights) {
    const Json& because = objectField(light, "not_kept_because");
    out << "<tr>" << cell(textField(light, "name")) << numberCell(formatField(light, "reach_pixels"))
        << numberCell(formatField(light, "kept_pixels")) << numberCell(formatField(light, "not_kept_pixels"))
        << numberCell(formatField(because, "frame")) << numberCell(formatField(because, "object")) << "</tr>\n";
  }
  out << "</table>\n";
}

}  // namespace

void budgetSections(std::ostream& out, const Page& page) {
  const Json& budgets = objectField(page.results, "budgets");
  out << "<h2 id=\"budgets\">Light budgets</h2>\n";
  if (budgets.empty()) {
    out << "<p>No light budgets in this run (<code>--no-budgets</code>, or a run of mutants only).</p>\n";
    return;
  }
  out << "<p>Where the budgets of SPEC 4-5.2 drop light, on the reference's visible surface (SPEC 5.5): "
         "<em>reach</em> counts the lights whose ideal contribution is non-zero at a pixel, <em>kept</em> those the "
         "model evaluates there, <em>loss</em> is luminance(ideal - model). Maps of the frame that cuts at the most "
         "pixels; <code>lightcts budget --scene S --all-frames</code> writes every frame's.</p>\n";
  std::vector<std::string> uncut;
  for (const auto& [scene, budget] : budgets.items()) {
    if (budget.contains("error")) {
      out << "<p>" << escapeText(scene) << ": budgets not computed: " << escapeText(textField(budget, "error"))
          << "</p>\n";
    } else if (budget.value("cuts", false)) {
      sceneWithCuts(out, page, scene, budget);
    } else {
      uncut.push_back(scene);
    }
  }
  if (uncut.empty()) return;
  out << "<h3>Scenes whose budgets cut nothing</h3>\n<ul class=\"uncut\">\n";
  for (const std::string& scene : uncut)
    out << "<li>" << escapeText(scene) << ": the budgets cut no light that reaches a pixel</li>\n";
  out << "</ul>\n";
}

}  // namespace reports::html
