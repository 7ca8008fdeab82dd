#include "apps/fluidviz/KeyOptions.h"

#include <cmath>
#include <ostream>

namespace fluidviz::app {

namespace {

bool isSwitch(const scene::DocRow& row) { return row.type == "bool"; }
bool isNumber(const scene::DocRow& row) {
  return row.type.rfind("number", 0) == 0 || row.type == "integer";
}

// The docs cell without its Markdown code quotes: `20` -> 20.
std::string plainDefault(const std::string& cell) {
  if (cell.size() >= 2 && cell.front() == '`' && cell.back() == '`')
    return cell.substr(1, cell.size() - 2);
  return cell;
}

std::string typeName(const scene::DocRow& row) {
  if (row.type == "integer") return "INT";
  if (isNumber(row)) return "NUMBER";
  const std::string prefix = "one of {";
  if (row.allowed.rfind(prefix, 0) == 0) {
    std::string names = row.allowed.substr(prefix.size(), row.allowed.size() - prefix.size() - 1);
    std::string compact;
    for (char c : names)
      if (c != ' ') compact += c == ',' ? '|' : c;
    return compact;
  }
  return "TEXT";
}

// The JSON object at the parent of a dotted key, and the key's last part.
std::pair<scene::json*, std::string> slot(scene::json& json, std::string key) {
  scene::json* target = &json;
  for (std::size_t dot; (dot = key.find('.')) != std::string::npos; key = key.substr(dot + 1))
    target = &(*target)[key.substr(0, dot)];
  return {target, key};
}

}  // namespace

double parseFlagNumber(const std::string& flag, const std::string& value) {
  std::size_t used = 0;
  double x = NAN;
  try {
    x = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size())
    throw UsageError(flag + " is '" + value + "'; expected a number");
  return x;
}

std::string flagFromKey(const std::string& key) {
  std::string flag = "--";
  for (char c : key) flag += c == '_' ? '-' : c;
  return flag;
}

std::string optionFlag(const scene::DocRow& row, const std::string& flag) {
  const std::string name = !flag.empty()       ? flag
                           : !row.flag.empty() ? row.flag
                                               : flagFromKey(row.key);
  // A switch turns the default around: --enhance (default false), --no-contrast (true).
  return isSwitch(row) && row.defaultValue == "`true`" ? "--no-" + name.substr(2) : name;
}

std::string keyHelp(const scene::DocRow& row) {
  std::string help = row.description;
  if (!row.unit.empty()) help += " (" + row.unit + ")";
  help += "; default " + plainDefault(row.defaultValue);
  if (row.allowed != "any") help += "; allowed " + row.allowed;
  return help;
}

const scene::DocRow& KeyOptions::findRow(const std::vector<scene::DocRow>& rows,
                                         const std::string& key) {
  for (const scene::DocRow& row : rows)
    if (row.key == key) return row;
  throw std::logic_error("KeyOptions: the struct declares no key '" + key + "'");
}

void KeyOptions::addRow(CLI::App& app, const scene::DocRow& row, const std::string& flag,
                        const std::string& group) {
  Entry& e = entries_.emplace_back();
  e.row = row;
  e.flag = optionFlag(row, flag);
  if (isSwitch(row)) {
    e.option = app.add_flag(e.flag, e.on, keyHelp(row))->group(group);
  } else {
    e.option =
        app.add_option(e.flag, e.value, keyHelp(row))->type_name(typeName(row))->group(group);
  }
}

void KeyOptions::putGivenValues(scene::json& json) const {
  for (const Entry& e : entries_) {
    if (e.option->count() == 0) continue;
    auto [target, key] = slot(json, e.row.key);
    if (isSwitch(e.row))
      (*target)[key] = e.row.defaultValue != "`true`";
    else if (isNumber(e.row))
      (*target)[key] = parseFlagNumber(e.flag, e.value);
    else
      (*target)[key] = e.value;
  }
}

std::string KeyOptions::flagForKey(const std::string& key) const {
  const std::size_t bracket = key.find('[');
  const std::string base = key.substr(0, bracket);
  for (const Entry& e : entries_)
    if (e.row.key == base)
      return e.flag + (bracket == std::string::npos ? "" : key.substr(bracket));
  return key;
}

bool KeyOptions::given(const std::string& key) const {
  for (const Entry& e : entries_)
    if (e.row.key == key) return e.option->count() > 0;
  return false;
}

bool parseCommandLine(CLI::App& app, const std::vector<std::string>& args, std::ostream& out) {
  app.allow_extras();  // unknown options are reported below, naming the command's --help
  std::vector<std::string> reversed(args.rbegin(), args.rend() - 1);  // CLI11 pops from the back
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return false;
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  for (const std::string& extra : app.remaining())
    throw UsageError(
        (extra.size() > 1 && extra[0] == '-' ? "unknown option '" : "unexpected argument '") +
        extra + "' (see fluidviz " + args[0] + " --help)");
  return true;
}

}  // namespace fluidviz::app
