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

// A count as the tables show it.
std::string count(long long n) { return std::to_string(n); }

// A scene's verdicts, "vulkan Pass, gl-egl Pass, ...", from the tests table.
std::string verdictsOf(const Page& page, const std::string& scene) {
  std::string text;
  for (const results::TestRecord& test : page.run.tests) {
    if (test.group + "." + test.scene != scene) continue;
    if (!text.empty()) text += " ";
    text += escapeText(test.backend) + " " + verdictBadge(test.verdictWord());
  }
  return text.empty() ? "no test of this scene ran" : text;
}

void sceneWithCuts(std::ostream& out, const Page& page, const results::SceneBudgetRecord& budget) {
  const std::string& scene = budget.scene;
  out << "<h3 id=\"budget-" << escapeText(scene) << "\">" << escapeText(scene) << "</h3>\n<p>" << verdictsOf(page, scene)
      << "</p>\n";
  out << "<table>\n<tr><th>frame</th><th>pixels cut</th><th>largest loss</th><th>summed loss</th>"
         "<th>largest relative loss</th><th>popping score</th></tr>\n";
  for (const results::BudgetFrameRecord& frame : budget.frames) {
    out << "<tr>" << numberCell(count(frame.frame)) << numberCell(count(frame.pixelsCut))
        << numberCell(formatOptional(frame.largestLoss)) << numberCell(formatOptional(frame.summedLoss))
        << numberCell(formatOptional(frame.largestRelativeLoss)) << numberCell(formatOptional(frame.poppingScore))
        << "</tr>\n";
  }
  out << "</table>\n";
  const std::string mapsFrame = count(budget.mapsFrame);
  out << "<div>\n";
  for (const auto& [image, label] : std::vector<std::pair<const std::string*, std::string>>{
           {&budget.reachImage, "reach (frame " + mapsFrame + ")"},
           {&budget.keptImage, "kept (frame " + mapsFrame + ")"},
           {&budget.lossImage, "loss (frame " + mapsFrame + ")"},
           {&budget.keptStripImage, "kept, every frame"}})
    if (!image->empty()) figure(out, page, *image, label);
  out << "</div>\n";
  if (budget.lightsNotKept.empty()) return;
  out << "<table>\n<tr><th>light (frame " << escapeText(mapsFrame)
      << ")</th><th>reaches</th><th>kept</th><th>not kept</th><th>cut by the frame (SPEC 5.1)</th>"
         "<th>left out of the object's list (SPEC 5.2)</th></tr>\n";
  for (const results::BudgetLightRecord& light : budget.lightsNotKept) {
    out << "<tr>" << cell(light.name) << numberCell(count(light.reachPixels)) << numberCell(count(light.keptPixels))
        << numberCell(count(light.notKeptPixels)) << numberCell(count(light.cutByFrame))
        << numberCell(count(light.cutByObject)) << "</tr>\n";
  }
  out << "</table>\n";
}

}  // namespace

void budgetSections(std::ostream& out, const Page& page) {
  out << "<h2 id=\"budgets\">Light budgets</h2>\n";
  if (page.run.budgets.empty()) {
    out << "<p>No light budgets in this run (<code>--no-budgets</code>, a run of mutants only, or a run "
           "interrupted before them).</p>\n";
    return;
  }
  out << "<p>Where the budgets of SPEC 4-5.2 drop light, on the reference's visible surface (SPEC 5.5): "
         "<em>reach</em> counts the lights whose ideal contribution is non-zero at a pixel, <em>kept</em> those the "
         "model evaluates there, <em>loss</em> is luminance(ideal - model). Maps of the frame that cuts at the most "
         "pixels; <code>lightcts budget --scene S --all-frames</code> writes every frame's.</p>\n";
  std::vector<std::string> uncut;
  for (const results::SceneBudgetRecord& budget : page.run.budgets) {
    if (!budget.error.empty()) {
      out << "<p>" << escapeText(budget.scene) << ": budgets not computed: " << escapeText(budget.error) << "</p>\n";
    } else if (budget.cuts) {
      sceneWithCuts(out, page, budget);
    } else {
      uncut.push_back(budget.scene);
    }
  }
  if (uncut.empty()) return;
  out << "<h3>Scenes whose budgets cut nothing</h3>\n<ul class=\"uncut\">\n";
  for (const std::string& scene : uncut)
    out << "<li>" << escapeText(scene) << ": the budgets cut no light that reaches a pixel</li>\n";
  out << "</ul>\n";
}

}  // namespace reports::html
