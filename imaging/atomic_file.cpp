#include "imaging/atomic_file.h"

#include <atomic>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unistd.h>

namespace imaging {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned long long> calls{0};
  // Appended piece by piece, not `"." + ...`: GCC 12's false -Wrestrict (bug 105329).
  std::string name(1, '.');
  name += target.stem().string();
  name += '.';
  name += std::to_string(::getpid());  // read on every call: a forked child has its own
  name += '.';
  name += std::to_string(calls.fetch_add(1, std::memory_order_relaxed));
  name += ".partial";
  name += target.extension().string();
  return target.parent_path() / name;
}

void writeThroughTemporary(const fs::path& target, const std::function<void(const fs::path& temporary)>& writeTemporary) {
  const fs::path temporary = temporaryPathFor(target);
  try {
    writeTemporary(temporary);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error("cannot write " + target.string() + ": " + ec.message());
  }
}

void writeFileAtomically(const fs::path& target, std::string_view bytes) {
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  writeThroughTemporary(target, [&](const fs::path& temporary) {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), std::streamsize(bytes.size()));
    file.close();
    if (!file) throw std::runtime_error("cannot write " + target.string());
  });
}

}  // namespace imaging
