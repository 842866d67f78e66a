// Writes a whole text file (evidence summaries, reports, results.json) so
// that a reader never sees half of it: the text goes to a hidden
// ".NAME.partial.EXT" beside the target, which is then renamed over it, as
// image_files.h does for images.
#pragma once

#include <filesystem>
#include <string_view>

namespace imaging {

// Creates the parent folder when missing. Throws std::runtime_error on failure
// and leaves neither the temporary file nor a partial target behind.
void writeFileAtomically(const std::filesystem::path& target, std::string_view text);

}  // namespace imaging
