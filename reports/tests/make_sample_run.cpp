// Writes a sample run folder, as `lightcts run --out DIR` would leave it:
// DIR/results.json (sample_results.h), the PNG images it names (real
// images, through imaging/), DIR/junit.xml and DIR/report/index.html.
//
//   make_sample_run DIR [--missing-image]
//
// --missing-image deletes one evidence image after the report is written,
// for the test that the Chromium check notices.
#include "imaging/image_files.h"
#include "imaging/atomic_file.h"
#include "reports/html_report.h"
#include "reports/junit_writer.h"
#include "reports/tests/sample_results.h"

#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>

namespace {

namespace fs = std::filesystem;

imaging::Image sampleImage(std::size_t seed, bool mask) {
  imaging::Image image(32, 24, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = mask ? float((x / 4 + y / 4 + seed) % 5 == 0)
                                 : float(0.2 + 0.8 * std::sin(0.2 * x + 0.3 * y + double(seed + c)) *
                                                   std::sin(0.2 * x + 0.3 * y + double(seed + c)));
  return image;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3 || (argc == 3 && std::strcmp(argv[2], "--missing-image") != 0)) {
    std::cerr << "usage: make_sample_run DIR [--missing-image]\n";
    return 2;
  }
  try {
    const fs::path run(argv[1]);
    fs::remove_all(run);
    fs::create_directories(run);
    const auto results = reports::testing::sampleResults();
    std::size_t seed = 0;
    for (const std::string& path : reports::testing::samplePngPaths(results)) {
      const fs::path file = run / path;
      fs::create_directories(file.parent_path());
      imaging::writePngPreview(file.string(), sampleImage(seed++, path.find("error-mask") != std::string::npos));
    }
    const results::RunRecord records = reports::testing::records(results);
    imaging::writeFileAtomically(run / "results.json", records.toJson().dump(2) + "\n");
    reports::writeJunit(records, run / "junit.xml");
    reports::writeHtmlReport(records, run / "report");
    if (argc == 3) fs::remove(run / records.tests[1].evidence->errorMaskPng);
    std::cout << "wrote " << (run / "report" / "index.html").string() << '\n';
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "make_sample_run: " << e.what() << '\n';
    return 4;
  }
}
