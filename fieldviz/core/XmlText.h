#pragma once
// Text inside an XML attribute or element, for the files fluidviz writes by hand (the .pvd series,
// ParaView's server-manager XML): the five characters XML gives a meaning, escaped.
#include <string>

namespace fluidviz {

inline std::string xmlEscaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace fluidviz
