#include "conformance/mutant_killers.h"

#include <sstream>

namespace conformance {
namespace {

std::vector<std::string> words(std::string_view text) {
  std::vector<std::string> list;
  std::istringstream in{std::string(text)};
  for (std::string word; in >> word;) list.push_back(word);
  return list;
}

}  // namespace

const std::vector<MutantKillers>& mutantKillers() {
  static const std::vector<MutantKillers> table = [] {
    std::vector<MutantKillers> rows;
#define LIGHTCTS_MUTANT_KILLERS(mutant, killers) rows.push_back({mutant, words(killers)});
#include "suite/mutant_killers.def"
#undef LIGHTCTS_MUTANT_KILLERS
    return rows;
  }();
  return table;
}

const std::vector<std::string>* killersOf(std::string_view mutant) {
  for (const MutantKillers& row : mutantKillers())
    if (row.mutant == mutant) return &row.killers;
  return nullptr;
}

}  // namespace conformance
