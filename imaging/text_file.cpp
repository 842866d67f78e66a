#include "imaging/text_file.h"

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace imaging {

namespace fs = std::filesystem;

void writeFileAtomically(const fs::path& target, std::string_view text) {
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  std::string name = ".";  // appended, not `"." + ...`: GCC 12's false -Wrestrict (bug 105329)
  name += target.stem().string();
  name += ".partial";
  name += target.extension().string();
  const fs::path temporary = target.parent_path() / name;
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(text.data(), std::streamsize(text.size()));
    file.close();
    if (!file) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error("cannot write " + target.string());
    }
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error("cannot write " + target.string() + ": " + ec.message());
  }
}

}  // namespace imaging
