// Little-endian byte encoding for the bake cache: the key's canonical
// serialisation and the cache file share it, so a value always has the same
// bytes whatever the host. Doubles and floats go in as their bit patterns.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace baking {

class ByteWriter {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes_.push_back(std::uint8_t(v >> (8 * i)));
  }
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes_.push_back(std::uint8_t(v >> (8 * i)));
  }
  void i32(std::int32_t v) { u32(std::uint32_t(v)); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void boolean(bool v) { u8(v ? 1 : 0); }
  // Length-prefixed, so "ab" + "c" and "a" + "bc" differ.
  void text(const std::string& s) {
    u64(s.size());
    raw(s.data(), s.size());
  }
  void raw(const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  void floats(const std::vector<float>& values) {
    if constexpr (std::endian::native == std::endian::little) {
      raw(values.data(), values.size() * sizeof(float));
    } else {
      for (float v : values) u32(std::bit_cast<std::uint32_t>(v));
    }
  }

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  void reserve(std::size_t n) { bytes_.reserve(n); }

 private:
  std::vector<std::uint8_t> bytes_;
};

// Reads what ByteWriter wrote. Running past the end sets failed() and
// returns zeros, so a parser checks once at the end instead of at every read.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t u8() { return take(1) ? data_[at_ - 1] : 0; }
  std::uint32_t u32() {
    if (!take(4)) return 0;
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(data_[at_ - 4 + std::size_t(i)]) << (8 * i);
    return v;
  }
  std::uint64_t u64() {
    if (!take(8)) return 0;
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t(data_[at_ - 8 + std::size_t(i)]) << (8 * i);
    return v;
  }
  double f64() { return std::bit_cast<double>(u64()); }
  std::string text(std::size_t maxLength) {
    const std::uint64_t n = u64();
    if (n > maxLength || !take(std::size_t(n))) {
      failed_ = true;
      return {};
    }
    return std::string(reinterpret_cast<const char*>(data_ + at_ - n), std::size_t(n));
  }
  bool floats(std::vector<float>& values, std::size_t count) {
    if (count > (size_ - at_) / sizeof(float) || !take(count * sizeof(float))) {
      failed_ = true;
      return false;
    }
    values.resize(count);
    const std::uint8_t* p = data_ + at_ - count * sizeof(float);
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(values.data(), p, count * sizeof(float));
    } else {
      for (std::size_t k = 0; k < count; ++k) {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(p[4 * k + std::size_t(i)]) << (8 * i);
        values[k] = std::bit_cast<float>(v);
      }
    }
    return true;
  }

  std::size_t position() const { return at_; }
  std::size_t remaining() const { return size_ - at_; }
  bool failed() const { return failed_; }

 private:
  bool take(std::size_t n) {
    if (failed_ || n > size_ - at_) {
      failed_ = true;
      return false;
    }
    at_ += n;
    return true;
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
  bool failed_ = false;
};

}  // namespace baking
