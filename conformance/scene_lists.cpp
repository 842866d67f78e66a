#include "conformance/scene_lists.h"

#include <sstream>

namespace conformance {
namespace {

std::vector<std::string> words(std::string_view text) {
  std::vector<std::string> list;
  std::istringstream in{std::string(text)};
  for (std::string word; in >> word;) list.push_back(word);
  return list;
}

const std::vector<std::string>* scenesOf(const std::vector<SceneList>& table, std::string_view variant) {
  for (const SceneList& row : table)
    if (row.variant == variant) return &row.scenes;
  return nullptr;
}

}  // namespace

const std::vector<SceneList>& mutantKillers() {
  static const std::vector<SceneList> table = [] {
    std::vector<SceneList> rows;
#define LIGHTCTS_MUTANT_KILLERS(mutant, killers) rows.push_back({mutant, words(killers)});
#include "suite/mutant_killers.def"
#undef LIGHTCTS_MUTANT_KILLERS
    return rows;
  }();
  return table;
}

const std::vector<SceneList>& admissibleWitnesses() {
  static const std::vector<SceneList> table = [] {
    std::vector<SceneList> rows;
#define LIGHTCTS_ADMISSIBLE_WITNESSES(variant, witnesses) rows.push_back({variant, words(witnesses)});
#include "suite/admissible_witnesses.def"
#undef LIGHTCTS_ADMISSIBLE_WITNESSES
    return rows;
  }();
  return table;
}

const std::vector<std::string>* killersOf(std::string_view mutant) { return scenesOf(mutantKillers(), mutant); }

const std::vector<std::string>* witnessesOf(std::string_view variant) {
  return scenesOf(admissibleWitnesses(), variant);
}

}  // namespace conformance
