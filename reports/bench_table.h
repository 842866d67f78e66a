// The tables of the benchmark pages, each described by its list of columns
// ({header, how to get the cell}) and written by one writer: the Pareto
// table, the lightmap table, the backends table and the table of every
// benchmark with its counters. Internal to reports/.
#pragma once

#include "reports/bench_page_model.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace reports::benchpages {

template <class Row>
struct Column {
  std::string header;
  std::function<std::string(const Row&)> cell;  // the row's whole <td> element
};

template <class Row>
struct Table {
  std::string cssClass;  // of the <table>
  std::vector<Column<Row>> columns;
  // Rows with a class (the Pareto front's "front"); "" for none.
  std::function<std::string(const Row&)> rowClass;
  // A row that failed: its first `keyColumns` cells, then "error: <message>"
  // across the others. nullopt: the row has its cells.
  std::function<std::optional<std::string>(const Row&)> failure;
  std::size_t keyColumns = 1;
};

// <td class="n">fmt(value)</td>; text cells are html::cell's (html_sections.h).
std::string valueCell(const std::optional<double>& value, int digits = 4);

// Columns of tables whose rows are benchmarks.
using EntryColumn = Column<const BenchEntry*>;
using EntryValue = std::function<std::optional<double>(const BenchEntry&)>;
EntryColumn textColumn(std::string header, std::function<std::string(const BenchEntry&)> text);
EntryColumn numberColumn(std::string header, EntryValue value, int digits = 4);
EntryColumn counterColumn(std::string header, std::string_view key);  // numberColumn of counter(e, key)
// textColumn, with " broken: N non-finite pixels" in red after the text of a
// broken benchmark (isBroken).
EntryColumn markedTextColumn(std::string header, std::function<std::string(const BenchEntry&)> text);
// That mark: "" unless `e` is broken.
std::string brokenMark(const BenchEntry& e);
// The spread columns every table of benchmarks has: "CPU ms" (median
// cpu_time) and "CV %" (coefficient of variation of the real time, in
// percent; "-" with one repetition).
EntryColumn cpuColumn();
EntryColumn cvColumn();
// The error of a benchmark that has no time (it failed), else nullopt.
std::optional<std::string> failureOf(const BenchEntry& e);

std::string tableHead(std::string_view cssClass, const std::vector<std::string>& headers);
std::string failureCells(std::size_t span, const std::string& message);

template <class Row>
void writeTable(std::ostream& out, const Table<Row>& table, const std::vector<Row>& rows) {
  std::vector<std::string> headers;
  for (const Column<Row>& c : table.columns) headers.push_back(c.header);
  out << tableHead(table.cssClass, headers);
  for (const Row& row : rows) {
    const std::string rowClass = table.rowClass ? table.rowClass(row) : "";
    out << (rowClass.empty() ? "<tr>" : "<tr class=\"" + rowClass + "\">");
    const std::optional<std::string> failed = table.failure ? table.failure(row) : std::nullopt;
    const std::size_t cells = failed ? table.keyColumns : table.columns.size();
    for (std::size_t i = 0; i < cells; ++i) out << table.columns[i].cell(row);
    if (failed) out << failureCells(table.columns.size() - table.keyColumns, *failed);
    out << "</tr>\n";
  }
  out << "</table>\n";
}

// Every benchmark of `entries` with its times and every counter some row has
// (known counters first, in a fixed order); nothing when `entries` is empty.
void benchTable(std::ostream& out, const Entries& entries);
// benchTable per kind (frame, frame_readback, pipeline, ...), each under an <h3>.
void tablesByKind(std::ostream& out, const Entries& entries);

}  // namespace reports::benchpages
