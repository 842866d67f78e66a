// The sections of the HTML report (html_report.h), each written to a stream.
// Internal to reports/: html_report.cpp puts them together.
#pragma once

#include "reports/result_fields.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>

namespace reports::html {

struct Page {
  const results::RunRecord& run;
  std::filesystem::path runDir;     // where results.json's paths start
  std::filesystem::path reportDir;  // where index.html lives
};

// Small pieces shared by the sections.
std::string verdictBadge(std::string_view verdict);  // <span class="v v-Fail">Fail</span>
std::string testAnchor(std::string_view testName);   // the id of a test's section
std::string testLink(const results::TestRecord& test);  // the name, linked to its section when it has one
std::string cell(std::string_view text);             // <td>escaped</td>
std::string numberCell(std::string_view text);       // <td class="n">escaped</td>
// An image of the run (its path relative to the run folder), linked, with a caption.
void figure(std::ostream& out, const Page& page, const std::string& runRelative, std::string_view label);

// html_sections.cpp
void header(std::ostream& out, const Page& page);
void backendSummary(std::ostream& out, const Page& page);
void mutantTable(std::ostream& out, const Page& page);
void slowestTests(std::ostream& out, const Page& page);

// html_tests.cpp
void attentionSections(std::ostream& out, const Page& page);
// expect_fail scenes whose mismatch was detected, with their evidence.
void detectedMismatchSections(std::ostream& out, const Page& page);
void allTestsTable(std::ostream& out, const Page& page);
void poppingTables(std::ostream& out, const Page& page);

// html_budgets.cpp: each scene's light budgets (SPEC 5.5) beside its verdicts.
void budgetSections(std::ostream& out, const Page& page);

}  // namespace reports::html
