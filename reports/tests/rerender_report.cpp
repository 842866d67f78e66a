// Rewrites RUN_DIR/report/index.html and RUN_DIR/junit.xml from
// RUN_DIR/results.json, e.g. to check the writers against a real
// `lightcts run` output:
//
//   rerender_report RUN_DIR && check_images_load.sh RUN_DIR
#include "reports/html_report.h"
#include "reports/junit_writer.h"
#include "results/results_file.h"

#include <exception>
#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: rerender_report RUN_DIR\n";
    return 2;
  }
  try {
    const std::filesystem::path run(argv[1]);
    const results::RunRecord records = results::readResultsFile(run / "results.json");
    reports::writeJunit(records, run / "junit.xml");
    reports::writeHtmlReport(records, run / "report");
    std::cout << "wrote " << (run / "report" / "index.html").string() << " and " << (run / "junit.xml").string()
              << '\n';
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rerender_report: " << e.what() << '\n';
    return 4;
  }
}
