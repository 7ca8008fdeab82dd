#include "fieldviz/core/TextTemplate.h"

#include <stdexcept>

namespace fluidviz {

namespace {

// Walks `text` once: literal runs go to `literal`, placeholder names to `placeholder`.
template <class Literal, class Placeholder>
void scanTemplate(std::string_view text, Literal&& literal, Placeholder&& placeholder) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool doubled = i + 1 < text.size() && text[i + 1] == c;
    if ((c == '{' || c == '}') && doubled) {
      literal(c);
      ++i;
    } else if (c == '}') {
      throw std::invalid_argument("a \"}\" without its \"{\" at character " +
                                  std::to_string(i + 1) + " (write \"}}\" for a literal brace)");
    } else if (c == '{') {
      const std::size_t close = text.find('}', i + 1);
      if (close == std::string_view::npos)
        throw std::invalid_argument("a \"{\" at character " + std::to_string(i + 1) +
                                    " is not closed (write \"{{\" for a literal brace)");
      const std::string_view name = text.substr(i + 1, close - i - 1);
      if (name.empty() || name.find('{') != std::string_view::npos)
        throw std::invalid_argument("an empty or nested placeholder at character " +
                                    std::to_string(i + 1));
      placeholder(name);
      i = close;
    } else {
      literal(c);
    }
  }
}

}  // namespace

std::vector<std::string> placeholderNames(std::string_view text) {
  std::vector<std::string> names;
  scanTemplate(text, [](char) {}, [&](std::string_view name) { names.emplace_back(name); });
  return names;
}

std::string expandPlaceholders(std::string_view text, const PlaceholderLookup& lookup) {
  std::string out;
  scanTemplate(
      text, [&](char c) { out += c; },
      [&](std::string_view name) {
        const std::optional<std::string> value = lookup(name);
        if (!value) throw std::invalid_argument("unknown placeholder {" + std::string(name) + "}");
        out += *value;
      });
  return out;
}

}  // namespace fluidviz
