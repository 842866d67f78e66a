// SHA-256 (FIPS 180-4), for the bake cache's keys and file checksums. Written
// here rather than pulled from a crypto library: the project needs only a
// strong, stable digest of bytes it produces itself, not security.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace baking {

using Sha256Digest = std::array<std::uint8_t, 32>;

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  // The digest of everything passed to update(); the object is spent after.
  Sha256Digest finish();

 private:
  void compress(const std::uint8_t* block);

  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t totalBytes_ = 0;
};

Sha256Digest sha256(const void* data, std::size_t size);
std::string toHex(const Sha256Digest& digest);

}  // namespace baking
