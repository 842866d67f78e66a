// Each mutant's killers: the scenes meant to catch it (SPEC 7), from the one
// table suite/mutant_killers.def that ctest's mutants.* tests read too.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace conformance {

struct MutantKillers {
  std::string mutant;               // the --mutant spelling (shaders::mutantNames())
  std::vector<std::string> killers;  // <group>.<name>, in the table's order
};

// In the table's order.
const std::vector<MutantKillers>& mutantKillers();

// The killers of `mutant`, or null when the table has no line for it.
const std::vector<std::string>* killersOf(std::string_view mutant);

}  // namespace conformance
