// Escaping text for XML (JUnit) and HTML, and paths for URLs. Text from a run
// (crash output, scene descriptions) is not trusted to be valid UTF-8 or free
// of control characters, which XML 1.0 forbids even as character references.
#pragma once

#include <string>
#include <string_view>

namespace reports {

// Valid UTF-8 with every character XML 1.0 allows: each byte of an invalid
// sequence becomes U+FFFD, a forbidden control character C becomes the
// visible text "\xNN". Tab, newline and carriage return are kept.
std::string sanitizeText(std::string_view text);

// sanitizeText, then & < > " ' as entities: safe in element content and in
// quoted attributes of both XML and HTML.
std::string escapeText(std::string_view text);

// escapeText, and tab, newline and carriage return as character references,
// so an XML attribute keeps them (a parser would turn them into spaces).
std::string escapeXmlAttribute(std::string_view text);

// Percent-encodes every byte of a relative URL path except unreserved
// characters and "/" (so "a b#1.png" -> "a%20b%231.png"). The result still
// needs escapeText before it goes into an attribute (it never changes it).
std::string percentEncodePath(std::string_view path);

}  // namespace reports
