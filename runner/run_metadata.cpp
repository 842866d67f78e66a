#include "runner/run_metadata.h"

#include "baking/sha256.h"
#include "runner/git_revision.h"  // generated at every build (cmake/git_revision.cmake)

#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace runner {
namespace {

// The value of `key` in a "key : value" or key="value" line of `file`.
std::string fieldOf(const char* file, const std::string& key, char separator) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    const auto at = line.find(separator);
    if (at == std::string::npos) continue;
    std::string value = line.substr(at + 1);
    value.erase(0, value.find_first_not_of(" \t\""));
    while (!value.empty() && (value.back() == '"' || value.back() == ' ')) value.pop_back();
    return value;
  }
  return "unknown";
}

}  // namespace

std::string revision() { return LIGHTCTS_REVISION; }

std::string utcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

results::MachineRecord thisMachine() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  return {host, fieldOf("/proc/cpuinfo", "model name", ':'), (long long)std::thread::hardware_concurrency(),
          fieldOf("/etc/os-release", "PRETTY_NAME", '=')};
}

results::BaselineFile baselineFile(const std::string& kind, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("cannot read " + path);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  const std::string data = bytes.str();
  return {kind, path, baking::toHex(baking::sha256(data.data(), data.size()))};
}

}  // namespace runner
