#pragma once
/// @file
/// JSON text written by hand: an object of strings and numbers needs no JSON library, only correct
/// string escaping and numbers that read back exactly (summary.json of 2D and 3D runs).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace soilsph::sph {

/// A JSON string literal (RFC 8259 §7): quote, backslash and control characters escaped.
inline std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
          out += escape;
        } else {
          out += c;  // UTF-8 bytes pass through unchanged, as JSON allows
        }
    }
  }
  return out + "\"";
}

/// Shortest decimal text that reads back to the same double; JSON has no NaN or infinity: null.
inline std::string number(double value) {
  if (!std::isfinite(value)) return "null";
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

}  // namespace soilsph::sph
