#include "reports/html_page.h"

#include "reports/html_escape.h"

namespace reports::html {
namespace {

constexpr std::string_view kBaseStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.5em; } h2 { border-bottom: 1px solid #ccc; margin-top: 2em; } h3 { margin-bottom: .3em; }
table { border-collapse: collapse; margin: .5em 0; }
th, td { border: 1px solid #ccc; padding: 2px 6px; text-align: left; vertical-align: top; }
th { background: #f3f3f3; } td.n { text-align: right; font-variant-numeric: tabular-nums; }
dl.meta { display: grid; grid-template-columns: max-content auto; gap: 2px 1em; }
dl.meta dt { font-weight: bold; } dl.meta dd { margin: 0; }
)";

}  // namespace

void pageStart(std::ostream& out, std::string_view title, std::string_view pageStyle) {
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escapeText(title)
      << "</title>\n<style>" << kBaseStyle << pageStyle << "</style>\n</head>\n<body>\n";
}

void pageEnd(std::ostream& out) { out << "</body>\n</html>\n"; }

}  // namespace reports::html
