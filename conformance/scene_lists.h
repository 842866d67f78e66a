// The suite's two tables of scenes per shader variant (SPEC 7), each read
// from its one .def file, which ctest reads too:
// - each mutant's killers, the scenes meant to catch it
//   (suite/mutant_killers.def; `lightcts run` checks a mutant against them
//   unless --mutants-all-scenes);
// - each admissible variant's witnesses, the scenes it brings closest to
//   their tolerance (suite/admissible_witnesses.def; `lightcts run
//   --admissible-witnesses` and ctest's admissible.* tests check a variant
//   against them, the full sweep against every selected scene).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace conformance {

struct SceneList {
  std::string variant;              // the --mutant or --admissible spelling (shaders::mutantNames(), admissibleNames())
  std::vector<std::string> scenes;  // <group>.<name>, in the table's order
};

// Each table in its order.
const std::vector<SceneList>& mutantKillers();
const std::vector<SceneList>& admissibleWitnesses();

// The scenes of `mutant` or `variant`, or null when its table has no line for it.
const std::vector<std::string>* killersOf(std::string_view mutant);
const std::vector<std::string>* witnessesOf(std::string_view variant);

}  // namespace conformance
