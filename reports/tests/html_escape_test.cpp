#include "reports/html_escape.h"

#include <gtest/gtest.h>

namespace reports {
namespace {

TEST(HtmlEscape, EscapesMarkupCharacters) {
  EXPECT_EQ(escapeText("<&\"'>"), "&lt;&amp;&quot;&#39;&gt;");
  EXPECT_EQ(escapeText("a < b && c"), "a &lt; b &amp;&amp; c");
  EXPECT_EQ(escapeText("]]>"), "]]&gt;");
}

TEST(HtmlEscape, KeepsValidUtf8AndLineBreaks) {
  EXPECT_EQ(escapeText("caf\xC3\xA9 \xE2\x88\x9E\t\n"), "caf\xC3\xA9 \xE2\x88\x9E\t\n");
  EXPECT_EQ(escapeText("\xF0\x9F\x92\xA1"), "\xF0\x9F\x92\xA1");
}

TEST(HtmlEscape, ReplacesWhatXmlForbids) {
  EXPECT_EQ(sanitizeText(std::string("a\x01" "b\x7F", 4)), "a\\x01b\\x7F");
  EXPECT_EQ(sanitizeText(std::string("nul\0", 4)), "nul\\x00");
  EXPECT_EQ(sanitizeText("\xFF"), "\xEF\xBF\xBD");
  EXPECT_EQ(sanitizeText("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // overlong "/"
  EXPECT_EQ(sanitizeText("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // a surrogate
  EXPECT_EQ(sanitizeText("cut \xE2\x88"), "cut \xEF\xBF\xBD\xEF\xBF\xBD");
}

TEST(HtmlEscape, AttributesKeepLineBreaksAsReferences) {
  EXPECT_EQ(escapeXmlAttribute("a\nb\t\"c\""), "a&#10;b&#9;&quot;c&quot;");
}

TEST(HtmlEscape, PercentEncodesPaths) {
  EXPECT_EQ(percentEncodePath("../evidence/a.b-c_d~/result.png"), "../evidence/a.b-c_d~/result.png");
  EXPECT_EQ(percentEncodePath("x y#1?%&\".png"), "x%20y%231%3F%25%26%22.png");
  EXPECT_EQ(percentEncodePath("\xC3\xA9"), "%C3%A9");
}

}  // namespace
}  // namespace reports
