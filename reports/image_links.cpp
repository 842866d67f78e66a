#include "reports/image_links.h"

#include "reports/html_escape.h"

namespace reports {
namespace {

namespace fs = std::filesystem;

fs::path folder(const fs::path& dir) {
  fs::path normal = fs::absolute(dir).lexically_normal();
  if (!normal.has_filename() && normal.has_parent_path() && normal != normal.root_path()) normal = normal.parent_path();
  return normal;
}

fs::path target(std::string_view runRelative, const fs::path& runDir) {
  const fs::path path{std::string(runRelative)};
  return (path.is_absolute() ? path : folder(runDir) / path).lexically_normal();
}

}  // namespace

std::string imageHref(std::string_view runRelative, const fs::path& runDir, const fs::path& reportDir) {
  if (runRelative.empty()) return "";
  const fs::path file = target(runRelative, runDir);
  const fs::path relative = file.lexically_relative(folder(reportDir));
  if (relative.empty()) return "file://" + percentEncodePath(file.generic_string());
  return percentEncodePath(relative.generic_string());
}

bool imageExists(std::string_view runRelative, const fs::path& runDir) {
  if (runRelative.empty()) return false;
  std::error_code ec;
  return fs::is_regular_file(target(runRelative, runDir), ec);
}

}  // namespace reports
