// The on-disk cache of references (docs/cli.md): a reference and
// its tolerance are a function of the scene, the frame, the reference options
// and the code that computes them, so one computed for lavapipe is the same
// for llvmpipe, softpipe and every later run. Each is computed once, by
// whichever worker needs it first, and read by every other.
//
// One file per (scene, frame, options), named by a SHA-256 of the scene's
// content (its file and the texels of every cookie it reads), the frame, the
// options and a fingerprint of every source the reference depends on
// (generated at build time, like the bake cache's), so a fix in the model or
// the tolerance never meets a stale reference. A reader checks the magic,
// the version, the key and an XXH3 checksum, and treats any mismatch as a
// miss; a file that cannot be written costs a re-render, never an error.
// Concurrent workers take an exclusive lock on the key before rendering, so
// the second one waits and reads instead of rendering the same image twice.
#pragma once

#include "lighting/scene.h"
#include "reference/reference_renderer.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace conformance {

// $LIGHTCTS_CACHE_DIR/references, else $XDG_CACHE_HOME/lightcts/references,
// else ~/.cache/lightcts/references; empty when none is known (no caching).
std::filesystem::path defaultReferenceCacheDirectory();

// Hex SHA-256 of everything in a scene that the reference reads: the scene
// file's bytes and every cookie image's texels (cookie files live beside it).
std::string sceneContentDigest(const std::filesystem::path& sceneFile, const lighting::Scene& scene);

// The cache key of one reference: the scene's digest, the frame, the options
// that change the images, and the reference sources' fingerprint.
std::string referenceCacheKey(const std::string& sceneDigest, int frame, const reference::ReferenceOptions& options);

// Whether a reference rendered with `options` can be kept: the extra images
// of keepExactValues and keepToleranceTerms (tests and `lightcts reference`)
// are not stored, so such a reference is always rendered.
bool cacheable(const reference::ReferenceOptions& options);

// The cached reference of `key` in `directory`, else `render()`'s, which is
// then stored. Holds an exclusive lock on the key while it renders, so
// another process asking for the same key waits and then reads the file.
// `hit` (when given) says whether it came from the cache.
reference::ReferenceImages cachedReference(const std::filesystem::path& directory, const std::string& key,
                                           const std::function<reference::ReferenceImages()>& render,
                                           bool* hit = nullptr);

}  // namespace conformance
