// The frame every HTML page of reports/ is written in: the conformance report
// (html_report.h) and the benchmark pages (bench_report.h) share the
// document head and one base stylesheet (body, headings, tables, number
// cells, metadata lists); each page adds only the rules of its own parts.
#pragma once

#include <ostream>
#include <string_view>

namespace reports::html {

// <!DOCTYPE html> ... <title>title</title><style>base + pageStyle</style> ... <body>
// `pageStyle`: the page's own CSS rules, one per line, each line ending in "\n".
void pageStart(std::ostream& out, std::string_view title, std::string_view pageStyle);
// </body></html>
void pageEnd(std::ostream& out);

}  // namespace reports::html
