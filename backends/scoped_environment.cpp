#include "backends/scoped_environment.h"

#include <cstdlib>

namespace backends {

ScopedEnvironment::ScopedEnvironment(const std::vector<std::pair<std::string, std::string>>& settings) {
  for (const auto& [name, value] : settings) {
    const char* old = std::getenv(name.c_str());
    saved_.push_back({name, old ? std::optional<std::string>(old) : std::nullopt});
    ::setenv(name.c_str(), value.c_str(), 1);
  }
}

ScopedEnvironment::~ScopedEnvironment() {
  // In reverse, so a variable named twice gets its first saved value back.
  for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) {
    if (it->value) ::setenv(it->name.c_str(), it->value->c_str(), 1);
    else ::unsetenv(it->name.c_str());
  }
}

}  // namespace backends
