// Writing a whole file so that a reader never sees half of it: the content
// goes to a hidden temporary beside the target, which is then renamed over it
// (a rename within one folder replaces the target in one step on POSIX).
// Every file the project writes goes through here: images (image_files.h),
// text (evidence summaries, reports, results.json), the bake cache and the
// Vulkan pipeline cache.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace imaging {

// The temporary beside `target`: ".NAME.<pid>.<n>.partial.EXT", where n counts
// the calls of this process. The pid and the counter make it unique to one
// call, so two processes or threads writing the same target never write into
// one temporary; the extension stays last because OpenImageIO picks the
// format from it.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Calls `writeTemporary` with a fresh temporary path (temporaryPathFor), then
// renames that file over `target`. When `writeTemporary` throws, its exception
// goes on; when the rename fails, throws std::runtime_error("cannot write
// TARGET: reason"). Either way the temporary is removed, and the target is
// either untouched or the whole new file. Creates no folders.
void writeThroughTemporary(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& temporary)>& writeTemporary);

// `bytes` (text or binary) as the whole of `target`, through
// writeThroughTemporary. Creates the parent folder when missing. Throws
// std::runtime_error on failure.
void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

}  // namespace imaging
