// The on-disk cache of bakes (docs/baking.md): one file per bake, named by a
// SHA-256 of every input that changes the maps (the baker's version, the
// profile, every object's mesh and transform, every light, the shadow-mask
// assignment, the options that alter the bake), written to a temporary name
// and renamed into place so a reader never sees half a file. A reader checks
// everything (magic, format version, key, resolutions, size, checksum) and
// treats any mismatch as a miss. Nothing here throws: a cache that cannot be
// read or written costs a re-bake, never an error.
#pragma once

#include "baking/bake.h"

#include <filesystem>
#include <memory>
#include <string>

namespace baking {

// Hex SHA-256 of the canonical serialisation of every input of the bake.
std::string bakeCacheKey(const lighting::PreparedScene& prepared, const BakeOptions& options);

// options.cacheDirectory, else $LIGHTCTS_CACHE_DIR/bakes, else
// $XDG_CACHE_HOME/lightcts/bakes, else ~/.cache/lightcts/bakes; empty when
// none of those is known (no caching).
std::filesystem::path bakeCacheDirectory(const BakeOptions& options);
// The file that holds the bake of `key` (empty when there is no cache folder).
std::filesystem::path bakeCacheFile(const std::string& key, const BakeOptions& options);

// The cached bake for `key`, with fromCache set; null when absent,
// unreadable, damaged or not matching the scene.
std::shared_ptr<const lighting::BakedLighting> readCachedBake(const std::string& key,
                                                               const lighting::PreparedScene& prepared,
                                                               const BakeOptions& options);
// Best effort: returns false when the file could not be written.
bool writeCachedBake(const lighting::BakedLighting& baked, const BakeOptions& options);

}  // namespace baking
