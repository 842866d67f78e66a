// The benchmark pages and comparison from the command line, for tests and
// reviews:
//   bench_tool sample DIR [--broken-svg | --overlapping-labels]
//                                          DIR/bench.json (bench_sample.h) and its pages;
//                                          --broken-svg empties the first plot of index.html,
//                                          --overlapping-labels draws its first point label twice
//   bench_tool crowded DIR                 the same for crowdedBench(), the plot's worst cases
//   bench_tool report BENCH.json DIR       the pages of a bench.json
//   bench_tool compare BEFORE.json AFTER.json   exit 1 on a significant regression
// Exit 2 on bad usage or input.
#include "imaging/atomic_file.h"
#include "reports/bench_compare.h"
#include "reports/bench_report.h"
#include "reports/tests/bench_sample.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

template <typename Json>
Json load(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::string("cannot read ") + path);
  return Json::parse(in);
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int usage() {
  std::cerr << "usage: bench_tool sample DIR [--broken-svg | --overlapping-labels] | crowded DIR | report BENCH.json DIR "
               "| compare BEFORE AFTER\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc >= 3 && (std::strcmp(argv[1], "sample") == 0 || std::strcmp(argv[1], "crowded") == 0)) {
      const fs::path dir = argv[2];
      const bool crowded = std::strcmp(argv[1], "crowded") == 0;
      const bool broken = !crowded && argc == 4 && std::strcmp(argv[3], "--broken-svg") == 0;
      const bool overlapping = !crowded && argc == 4 && std::strcmp(argv[3], "--overlapping-labels") == 0;
      if (argc > 4 || (argc == 4 && !broken && !overlapping)) return usage();
      const auto bench = crowded ? reports::testing::crowdedBench() : reports::testing::sampleBench();
      imaging::writeFileAtomically(dir / "bench.json", bench.dump(2) + "\n");
      reports::writeBenchReport(bench, dir);
      if (broken) {  // the first plot keeps its <svg> element but loses everything it draws
        std::string html = readText(dir / "index.html");
        const std::size_t open = html.find("<svg ");
        const std::size_t inside = html.find('>', open) + 1;
        const std::size_t close = html.find("</svg>", inside);
        html.erase(inside, close - inside);
        imaging::writeFileAtomically(dir / "index.html", html);
      }
      if (overlapping) {  // the first point label drawn a second time, on top of itself
        std::string html = readText(dir / "index.html");
        const std::size_t group = html.find("<g class=\"labels\"");
        const std::size_t open = html.find("<text ", group);
        const std::size_t close = html.find("</text>", open);
        if (group == std::string::npos || open == std::string::npos || close == std::string::npos)
          throw std::runtime_error("index.html has no point label to repeat");
        const std::string label = html.substr(open, close + 7 - open);
        html.insert(close + 7, "\n" + label);
        imaging::writeFileAtomically(dir / "index.html", html);
      }
      std::cout << "wrote " << (dir / "index.html").string() << "\n";
      return 0;
    }
    if (argc == 4 && std::strcmp(argv[1], "report") == 0) {
      reports::writeBenchReport(load<nlohmann::ordered_json>(argv[2]), argv[3]);
      std::cout << "wrote " << (fs::path(argv[3]) / "index.html").string() << "\n";
      return 0;
    }
    if (argc == 4 && std::strcmp(argv[1], "compare") == 0)
      return reports::compareBench(load<nlohmann::json>(argv[2]), load<nlohmann::json>(argv[3]), std::cout);
    return usage();
  } catch (const std::exception& e) {
    std::cerr << "bench_tool: " << e.what() << "\n";
    return 2;
  }
}
