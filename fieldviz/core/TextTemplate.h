#pragma once
// Text with {placeholders}, e.g. picture titles "{name} Re {reynolds}, t = {time} s": each
// {word} is replaced by the value a lookup gives for it; "{{" and "}}" are literal braces.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fluidviz {

/// The value of a placeholder, or nothing if the name is unknown.
using PlaceholderLookup = std::function<std::optional<std::string>(std::string_view name)>;

/// The names of the placeholders in `text`, in order of appearance (repeats kept). Throws
/// std::invalid_argument for an unclosed "{", an empty "{}" or a lone "}".
std::vector<std::string> placeholderNames(std::string_view text);

/// `text` with every placeholder replaced. Throws std::invalid_argument naming the first unknown
/// placeholder (and for the syntax errors of placeholderNames).
std::string expandPlaceholders(std::string_view text, const PlaceholderLookup& lookup);

}  // namespace fluidviz
