#include "reports/junit_writer.h"
#include "reports/tests/sample_results.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace reports {
namespace {

namespace fs = std::filesystem;

std::string suiteTag(const std::string& xml, const std::string& name) {
  const std::regex tag("<testsuite name=\"" + name + "\"[^>]*>");
  std::smatch match;
  return std::regex_search(xml, match, tag) ? match.str() : "";
}

std::string attribute(const std::string& tag, const std::string& name) {
  const std::regex value(" " + name + "=\"([^\"]*)\"");
  std::smatch match;
  return std::regex_search(tag, match, value) ? match[1].str() : "<none>";
}

long long count(const std::string& text, const std::string& what) {
  long long n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

struct Counts {
  std::string tests, failures, errors, skipped;
};

void expectCounts(const std::string& tag, Counts expected) {
  ASSERT_FALSE(tag.empty());
  EXPECT_EQ(attribute(tag, "tests"), expected.tests) << tag;
  EXPECT_EQ(attribute(tag, "failures"), expected.failures) << tag;
  EXPECT_EQ(attribute(tag, "errors"), expected.errors) << tag;
  EXPECT_EQ(attribute(tag, "skipped"), expected.skipped) << tag;
}

TEST(Junit, CountsPerBackendMutantsAndTotal) {
  const std::string xml = junitXml(testing::records(testing::sampleResults()));
  expectCounts(suiteTag(xml, "vulkan"), {"4", "1", "1", "1"});  // the QualityWarning is skipped
  expectCounts(suiteTag(xml, "gl-egl-softpipe"), {"6", "2", "1", "2"});
  expectCounts(suiteTag(xml, "gl-osmesa"), {"1", "0", "0", "1"});
  expectCounts(suiteTag(xml, "mutants"), {"4", "1", "1", "0"});
  std::smatch root;
  ASSERT_TRUE(std::regex_search(xml, root, std::regex("<testsuites [^>]*>")));
  // The schema Jenkins validates with (junit.xsd) allows `skipped` on <testsuite> only.
  expectCounts(root.str(), {"15", "4", "3", "<none>"});
  EXPECT_EQ(attribute(root.str(), "time"), "93.250");
  EXPECT_EQ(count(xml, "<testcase "), 15);
  EXPECT_EQ(count(xml, "<failure "), 4);
  EXPECT_EQ(count(xml, "<error "), 3);
  EXPECT_EQ(count(xml, "<skipped "), 4);
  EXPECT_EQ(attribute(suiteTag(xml, "vulkan"), "time"), "20.500");
  EXPECT_EQ(attribute(suiteTag(xml, "vulkan"), "hostname"), "ci-1");
}

TEST(Junit, TestCasesNameGroupBackendAndTime) {
  const std::string xml = junitXml(testing::records(testing::sampleResults()));
  EXPECT_NE(xml.find("<testcase classname=\"vulkan.attenuation\" name=\"attenuation.point-d-half-range.vulkan\" "
                     "time=\"1.500\">\n      <failure message=\"Fail: 37 failing of 4096 compared pixels"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"backend.gl-osmesa\" time=\"0.000\">\n      <skipped message=\"NotSupported: "
                     "libOSMesa.so.8 not found\""),
            std::string::npos);
  EXPECT_NE(xml.find("name=\"stability.far-1e6.vulkan\" time=\"0.040\">\n      <error message=\"Crash: "),
            std::string::npos);
  EXPECT_NE(xml.find("name=\"mutants.distance-clamp-1e-4.vulkan\" time=\"0.000\">\n      <failure "
                     "message=\"survived: "),
            std::string::npos);
  EXPECT_NE(xml.find("name=\"mutants.unsquared-range.vulkan\" time=\"0.000\">\n      <system-out>"),
            std::string::npos);
}

// BACKEND.GROUP: a CI page splits the classname at its last dot into package
// and class, so each backend's tests show together.
TEST(Junit, ClassnameIsBackendDotGroup) {
  EXPECT_EQ(junitClassname("vulkan", "attenuation"), "vulkan.attenuation");
  EXPECT_EQ(junitClassname("gl-egl-softpipe", "per-object"), "gl-egl-softpipe.per-object");
  EXPECT_EQ(junitClassname("", "attenuation"), "attenuation");
  EXPECT_EQ(junitClassname("vulkan", ""), "vulkan");
  const std::string xml = junitXml(testing::records(testing::sampleResults()));
  const std::regex testcase("<testcase classname=\"([^\"]*)\" name=\"([^\"]*)\"");
  long long cases = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), testcase); it != std::sregex_iterator(); ++it) {
    const std::string classname = (*it)[1].str(), name = (*it)[2].str();
    ++cases;
    // Every test name ends in its backend, every classname starts with it.
    const std::string backend = name.substr(name.rfind('.') + 1);
    EXPECT_EQ(classname.substr(0, classname.find('.')), backend) << name;
    EXPECT_EQ(classname.find('.', backend.size() + 1), std::string::npos) << classname;
  }
  EXPECT_EQ(cases, 15);
  EXPECT_NE(xml.find("classname=\"gl-egl-softpipe.per-object\" name=\"per-object.eleven lights#1.gl-egl-softpipe\""),
            std::string::npos);
  EXPECT_NE(xml.find("classname=\"vulkan.mutants\" name=\"mutants.distance-clamp-1e-4.vulkan\""), std::string::npos);
  EXPECT_NE(xml.find("classname=\"gl-osmesa.backend\" name=\"backend.gl-osmesa\""), std::string::npos);
}

TEST(Junit, ExpectedFailAndQualityWarningAreSkippedWithTheirReasons) {
  const std::string xml = junitXml(testing::records(testing::sampleResults()));
  EXPECT_NE(xml.find("<skipped message=\"ExpectedFail: softpipe rounds &lt;pow&gt; &amp; &quot;exp2&quot;\" "
                     "type=\"ExpectedFail\"/>"),
            std::string::npos)
      << xml;
  const std::size_t warning = xml.find("name=\"limits.popping-64.vulkan\"");
  ASSERT_NE(warning, std::string::npos);
  const std::string body = xml.substr(warning, xml.find("</testcase>", warning) - warning);
  EXPECT_EQ(body.find("<failure"), std::string::npos);
  EXPECT_NE(body.find("<skipped message=\"QualityWarning: popping score 0.4 above 0.25"), std::string::npos) << body;
}

TEST(Junit, EscapesTextAndAttributes) {
  const std::string xml = junitXml(testing::records(testing::sampleResults()));
  // Crash message: the first line in the attribute, all of it in the element.
  EXPECT_NE(xml.find("message=\"Crash: worker crashed: signal 11 &lt;SIGSEGV&gt; &amp; &quot;core&quot;\""),
            std::string::npos);
  EXPECT_NE(xml.find("message: worker crashed: signal 11 &lt;SIGSEGV&gt; &amp; &quot;core&quot;\nsecond line"),
            std::string::npos);
  EXPECT_NE(xml.find("d &lt; r &amp; &quot;half&quot; range"), std::string::npos);
  EXPECT_EQ(xml.find("<SIGSEGV>"), std::string::npos);
  EXPECT_EQ(xml.find("<pow>"), std::string::npos);
  EXPECT_EQ(xml.find("& "), std::string::npos);
  EXPECT_EQ(xml.find("\"half\""), std::string::npos);
}

TEST(Junit, UnknownVerdictFailsAndControlCharactersAreReplaced) {
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "Maybe";
  results["tests"][0]["message"] = std::string("bell\x07 and \xFF");
  const std::string xml = junitXml(testing::records(results));
  expectCounts(suiteTag(xml, "vulkan"), {"4", "2", "1", "1"});
  EXPECT_NE(xml.find("type=\"Maybe\""), std::string::npos);
  EXPECT_NE(xml.find("bell\\x07 and \xEF\xBF\xBD"), std::string::npos);
  EXPECT_EQ(xml.find('\x07'), std::string::npos);
}

// results.json is not trusted: a word that comparison/verdict.h or
// run_status.h does not know, a wrongly cased one included, is never a pass:
// a test's is a failure under its own word, a mutant's reads as Crash, a
// backend's as error (results/run_records.h).
TEST(Junit, WronglyCasedVerdictAndUnknownStatusesCountAgainstTheRun) {
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "pass";
  results["mutants"][0]["status"] = "Killed";
  results["backends"][2]["status"] = "Skipped";  // gl-osmesa, which has no tests
  const std::string xml = junitXml(testing::records(results));
  expectCounts(suiteTag(xml, "vulkan"), {"4", "2", "1", "1"});
  expectCounts(suiteTag(xml, "mutants"), {"4", "1", "2", "0"});
  expectCounts(suiteTag(xml, "gl-osmesa"), {"1", "0", "1", "0"});
  EXPECT_NE(xml.find("type=\"pass\""), std::string::npos) << xml;  // the test's own word, as a failure
}

// The reports read the records, and the records read results.json's keys:
// a key renamed in the file (or in the records' writer alone) changes what
// the report says, so a report cannot drift from the format unnoticed.
TEST(Junit, ARenamedKeyChangesTheReport) {
  nlohmann::ordered_json written = testing::sampleRun().toJson();
  EXPECT_NE(junitXml(testing::records(written)).find("Fail: 37 failing of 4096"), std::string::npos);
  nlohmann::ordered_json& metrics = written["tests"][1]["metrics"];
  metrics["failing_pixel"] = metrics["failing_pixels"];
  metrics.erase("failing_pixels");
  EXPECT_EQ(junitXml(testing::records(written)).find("Fail: 37 failing of 4096"), std::string::npos);
}

TEST(Junit, FlakePassesWithOutput) {
  auto results = testing::sampleResults();
  results["tests"][0]["verdict"] = "Flake";
  const std::string xml = junitXml(testing::records(results));
  expectCounts(suiteTag(xml, "vulkan"), {"4", "1", "1", "1"});  // the QualityWarning is skipped
  const std::size_t flake = xml.find("name=\"attenuation.point-d-0.vulkan\"");
  ASSERT_NE(flake, std::string::npos);
  const std::string body = xml.substr(flake, xml.find("</testcase>", flake) - flake);
  EXPECT_NE(body.find("<system-out>Flake: failed, then passed on a retry"), std::string::npos) << body;
}

std::string caseBody(const std::string& xml, const std::string& test) {
  const std::size_t at = xml.find("name=\"" + test + "\"");
  return at == std::string::npos ? "" : xml.substr(at, xml.find("</testcase>", at) - at);
}

TEST(Junit, AFailureNamesItsEvidencePage) {
  const std::string page = "evidence/attenuation.point-d-half-range.vulkan/viewer.html";
  const std::string body = caseBody(junitXml(testing::records(testing::sampleResults())), "attenuation.point-d-half-range.vulkan");
  EXPECT_NE(body.find("<failure message=\"Fail: 37 failing of 4096 compared pixels, max error 0.25, tightness 812.5 "
                      "(evidence: " + page + ")\""),
            std::string::npos)
      << body;
  EXPECT_NE(body.find("\">evidence: " + page + "\n"), std::string::npos) << body;
}

TEST(Junit, EvidenceUrlTemplateReplacesEveryTestMark) {
  auto results = testing::sampleResults();
  results["evidence_url"] = "https://ci.example/{test}/artifacts/{test}.html";
  const std::string body = caseBody(junitXml(testing::records(results)), "attenuation.point-d-half-range.vulkan");
  const std::string url =
      "https://ci.example/attenuation.point-d-half-range.vulkan/artifacts/attenuation.point-d-half-range.vulkan.html";
  EXPECT_NE(body.find("(evidence: " + url + ")"), std::string::npos) << body;
  EXPECT_NE(body.find("evidence: " + url + "\n"), std::string::npos) << body;
}

TEST(Junit, AFailurePastTheEvidenceLimitNamesItsNumbers) {
  auto results = testing::sampleResults();
  results["evidence_url"] = "https://ci.example/{test}/viewer.html";
  results["tests"][1]["evidence"] = {{"frame", 0},
                                     {"summary_json", "evidence/attenuation.point-d-half-range.vulkan/summary.json"},
                                     {"images_kept", false}};
  const std::string body = caseBody(junitXml(testing::records(results)), "attenuation.point-d-half-range.vulkan");
  EXPECT_NE(body.find("(evidence: evidence/attenuation.point-d-half-range.vulkan/summary.json)"), std::string::npos)
      << body;
  EXPECT_EQ(body.find("ci.example"), std::string::npos) << body;
}

TEST(Junit, ASurvivorOfItsKillersNamesThem) {
  auto results = testing::sampleResults();
  results["mutant_check"] = "killers";
  results["mutants"][2]["killers"] = {"attenuation.point-5mm-above-floor", "attenuation.point-d-zero"};
  const std::string body = caseBody(junitXml(testing::records(results)), "mutants.distance-clamp-1e-4.vulkan");
  EXPECT_NE(body.find("<failure message=\"survived: its killers (attenuation.point-5mm-above-floor, "
                      "attenuation.point-d-zero) did not catch"),
            std::string::npos)
      << body;
}

TEST(Junit, AnEmptyRunIsAnEmptyReport) {
  const std::string empty = junitXml(results::RunRecord{});
  EXPECT_NE(empty.find("<testsuites name=\"lightcts\" tests=\"0\""), std::string::npos);
}

TEST(Junit, WritesTheFileAtomically) {
  const fs::path dir = fs::path(::testing::TempDir()) / "reports_junit_test";
  fs::remove_all(dir);
  writeJunit(testing::records(testing::sampleResults()), dir / "junit.xml");
  std::ifstream file(dir / "junit.xml");
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_EQ(text.str(), junitXml(testing::records(testing::sampleResults())));
  long long entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1) << "no temporary file is left behind";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace reports
