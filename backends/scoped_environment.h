// Environment variables set for a scope and put back when it ends. A driver
// or loader that reads its settings from the environment (the Vulkan
// loader's driver list, read when an instance is created) reads them while
// the object lives; what the process does afterwards sees the environment as
// it was. setenv is not thread-safe: hold one only where no other thread
// reads the environment.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace backends {

class ScopedEnvironment {
 public:
  // Each pair is a variable and the value it holds while this object lives.
  explicit ScopedEnvironment(const std::vector<std::pair<std::string, std::string>>& settings);
  ~ScopedEnvironment();
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  struct Saved {
    std::string name;
    std::optional<std::string> value;  // none: it was unset
  };
  std::vector<Saved> saved_;
};

}  // namespace backends
