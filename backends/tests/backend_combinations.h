// Every backend and Mesa driver pair of SPEC 10's test names (the one table
// of backends/backend_combinations.def), for tests that run on each. gtest_discover_tests runs every test in its own process, so a
// test parameterised by combination gets the driver it asks for (Mesa loads
// one driver per process).
#pragma once

#include "backends/backend.h"
#include "backends/backend_combinations.h"

#include <gtest/gtest.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace backends {

// How gtest prints a combination in messages and in the names ctest lists
// ("# GetParam() = vulkan"). In the type's own namespace, where gtest's
// argument-dependent lookup finds it (in backends::testing it is not found,
// and gtest prints the struct's bytes).
inline void PrintTo(const BackendCombination& c, std::ostream* out) { *out << c.suffix; }

}  // namespace backends

namespace backends::testing {

using Combination = backends::BackendCombination;

// How gtest names a combination's test: its suffix as an identifier.
inline std::string combinationTestName(const ::testing::TestParamInfo<Combination>& info) {
  return info.param.identifier();
}

// Every combination of the one table (backends/backend_combinations.def).
inline const std::vector<Combination>& allCombinations() { return backends::backendCombinations(); }

// The backend with validation on, or null with `whyNot` set when it is not
// supported here (a skip). Other failures throw.
inline std::unique_ptr<Backend> createOrNull(const Combination& c, std::string& whyNot) {
  const BackendEntry* entry = findBuiltBackendEntry(c.backend);
  if (!entry) {
    whyNot = c.backend + " is not built";
    return nullptr;
  }
  BackendOptions options;
  options.driver = c.driver;
  options.validation = true;
  try {
    return entry->create(options);
  } catch (const NotSupportedError& e) {
    whyNot = c.suffix + ": " + e.what();
    return nullptr;
  }
}

}  // namespace backends::testing
