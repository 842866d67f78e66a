// JUnit XML of a run (its records, results/run_records.h), for CI tools.
#pragma once

#include "results/run_records.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace reports {

// One <testsuite> per backend (name = the test-name suffix, e.g. "vulkan"),
// one <testcase classname="BACKEND.GROUP" name="GROUP.SCENE.BACKEND"
// time="SECONDS"> per test, and a "mutants" <testsuite> (classname
// "BACKEND.mutants"; killed passes, survived fails):
//   Fail, UnexpectedPass, unknown verdicts   <failure message type>
//   Crash, Timeout, NotRun                   <error message type>
//   NotSupported                             <skipped message>
//   ExpectedFail                             <skipped message="ExpectedFail: reason">
//                                            (pytest's xfail convention: a known
//                                            failure is not a pass, and must not block)
//   QualityWarning                           <skipped message="QualityWarning: reason">
//                                            (a comparison that checked nothing, SPEC 7:
//                                            no pass, and no failure of the driver)
//   Flake, Pass                              pass; Flake with <system-out>
// (the classification is comparison::ciOutcome, comparison/verdict.h).
// A test with evidence names its page (the viewer, evidence/<test>/viewer.html,
// relative to the run folder, or results.json's "evidence_url" with {test}
// replaced) in the first line of its details and, on a failure or error
// (UnexpectedPass included), at the end of the message attribute.
// A backend that did not run ("NotSupported" or "error") and has no tests
// still shows, as one testcase "backend.BACKEND" of classname "BACKEND.backend"
// (skipped or error).
// The XML validates against the JUnit schema Jenkins uses (reports/tests/junit.xsd):
// the counts of skips are on each <testsuite>, never on <testsuites>.
std::string junitXml(const results::RunRecord& run);

// A testcase's classname, "BACKEND.GROUP" ("vulkan.attenuation"): Jenkins
// splits it at its last dot into package and class, GitLab lists it beside
// each test, so the tests of one backend show together. Either part alone
// when the other is empty.
std::string junitClassname(std::string_view backend, std::string_view group);

// junitXml, written atomically (temporary file, then rename).
void writeJunit(const results::RunRecord& run, const std::filesystem::path& file);

}  // namespace reports
