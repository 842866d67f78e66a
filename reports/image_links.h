// Links from report/index.html to the images that results.json names. Those
// paths are relative to the run's --out folder; the report lives in a folder
// of its own (<out>/report), so "evidence/x/result.png" becomes
// "../evidence/x/result.png" there.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace reports {

// The URL (percent-encoded, not yet HTML-escaped) of `runRelative` as seen
// from `reportDir`. Both folders may be relative to the working directory; an
// absolute `runRelative` is kept as the file it names. "" for "".
std::string imageHref(std::string_view runRelative, const std::filesystem::path& runDir,
                      const std::filesystem::path& reportDir);

// Whether the file exists now (the report marks missing ones in its text too).
bool imageExists(std::string_view runRelative, const std::filesystem::path& runDir);

}  // namespace reports
