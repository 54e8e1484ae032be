#pragma once
// Text for hand-written XML, SVG and XHTML: anything that comes from outside (file names, command
// lines, device names) goes through here so the documents stay well-formed whatever it contains.
#include <string>
#include <string_view>

namespace globe {

// Escapes & < > " ' as entities, so the result is safe both as element text and inside a quoted
// attribute. Bytes XML 1.0 forbids (control characters other than tab/newline/return) and bytes
// that are not valid UTF-8 become '?': an XML parser rejects the whole document otherwise.
std::string escapeMarkup(std::string_view text);

// Percent-encodes everything but RFC 3986 unreserved characters and '/', for a relative URL such
// as an <img src>; the result still needs escapeMarkup (it has no characters that need it).
std::string percentEncodePath(std::string_view path);

}  // namespace globe
