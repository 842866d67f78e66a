#include "reports/html_report.h"

#include "imaging/atomic_file.h"
#include "reports/html_page.h"
#include "reports/html_sections.h"

#include <sstream>

namespace reports {
namespace {

namespace fs = std::filesystem;

// The report's own rules; the base stylesheet is html_page's.
constexpr const char* kReportStyle = R"(table.summary { font-size: .9em; }
.v { padding: 0 4px; border-radius: 3px; font-weight: bold; white-space: nowrap; }
.v-Pass, .v-killed { background: #d4f4d4; } .v-ExpectedFail, .v-NotSupported { background: #e8e8e8; }
.v-QualityWarning { background: #fff0b3; }
.v-Fail, .v-Crash, .v-Timeout, .v-UnexpectedPass, .v-NotRun, .v-survived, .v-unknown { background: #f8c8c8; }
.zero { color: #bbb; } .bad { background: #fbe3e3; }
figure { display: inline-block; margin: 0 1em 1em 0; vertical-align: top; }
figure img { width: 256px; image-rendering: pixelated; border: 1px solid #999; background: #000; }
figcaption { font-size: .9em; word-break: break-all; max-width: 256px; }
pre { background: #f6f6f6; padding: .5em; white-space: pre-wrap; }
img.thumb { width: 64px; image-rendering: pixelated; border: 1px solid #999; background: #000; }
iframe.viewer { width: 100%; height: 640px; border: 1px solid #999; }
.missing { color: #b00; font-weight: bold; }
section.test { border-left: 4px solid #e66; padding-left: 1em; margin-bottom: 2em; }
section.test.QualityWarning { border-color: #db3; }
)";

fs::path defaultRunDir(const fs::path& outDir) {
  fs::path normal = fs::absolute(outDir).lexically_normal();
  if (!normal.has_filename()) normal = normal.parent_path();
  return normal.parent_path();
}

}  // namespace

std::string htmlReport(const results::RunRecord& run, const fs::path& runDir, const fs::path& reportDir) {
  const html::Page page{run, runDir, reportDir};
  std::ostringstream out;
  std::string title = "lightcts report ";  // appended: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&
  title.append(run.lightctsRevision).append(" ").append(run.startedUtc);
  html::pageStart(out, title, kReportStyle);
  html::header(out, page);
  html::backendSummary(out, page);
  html::mutantTable(out, page);
  html::attentionSections(out, page);
  html::detectedMismatchSections(out, page);
  html::allTestsTable(out, page);
  html::poppingTables(out, page);
  html::budgetSections(out, page);
  html::slowestTests(out, page);
  html::pageEnd(out);
  return out.str();
}

void writeHtmlReport(const results::RunRecord& run, const fs::path& outDir, const fs::path& runDir) {
  const fs::path runFolder = runDir.empty() ? defaultRunDir(outDir) : runDir;
  imaging::writeFileAtomically(outDir / "index.html", htmlReport(run, runFolder, outDir));
}

}  // namespace reports
