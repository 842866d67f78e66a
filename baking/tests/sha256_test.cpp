// SHA-256 against the test vectors of FIPS 180-2 (appendix B) and the empty string.
#include "baking/sha256.h"

#include <gtest/gtest.h>

#include <string>

namespace baking {
namespace {

std::string hexOf(const std::string& text) { return toHex(sha256(text.data(), text.size())); }

TEST(Sha256, KnownVectors) {
  EXPECT_EQ(hexOf(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(hexOf("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(hexOf("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(hexOf(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PiecewiseUpdatesEqualOneUpdate) {
  const std::string text(1000, 'x');
  Sha256 h;
  for (std::size_t at = 0, step = 1; at < text.size(); at += step, step = step % 97 + 13)
    h.update(text.data() + at, std::min(step, text.size() - at));
  EXPECT_EQ(toHex(h.finish()), hexOf(text));
}

}  // namespace
}  // namespace baking
