#include "pipeline/PictureText.h"

#include <map>
#include <optional>
#include <stdexcept>

#include "fieldviz/core/TextTemplate.h"
#include "pipeline/SolverFactory.h"

namespace fluidviz {

namespace {

const std::map<std::string, std::string, std::less<>>& unitsByField() {
  static const std::map<std::string, std::string, std::less<>> units{
      {"speed", "m/s"},           {"velocity", "m/s"},       {"velocity_x", "m/s"},     {"velocity_y", "m/s"},
      {"velocity_z", "m/s"},      {"in_plane_speed", "m/s"}, {"density", "kg/m^3"},
      {"pressure", "Pa"},         {"vorticity", "1/s"},      {"stream_function", "m^2/s"},
      {"q_criterion", "1/s^2"},   {"mass", "kg"},            {"smoothing_length", "m"},
      {"colour", "1"},            {"color", "1"}};
  return units;
}

std::string valueText(const scene::json& v) {
  if (v.is_number()) return formatNumber(v.get<double>(), 6);
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + valueText(v[i]);
    return text + "]";
  }
  return "";
}

// The value at a dotted path ("lbm.reynolds", "lbm.walls.x_min.type").
const scene::json* atPath(const scene::json& root, std::string_view path) {
  const scene::json* node = &root;
  while (!path.empty()) {
    const std::size_t dot = path.find('.');
    const std::string part(path.substr(0, dot));
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &(*node)[part];
    path = dot == std::string_view::npos ? std::string_view{} : path.substr(dot + 1);
  }
  return node;
}

// The dotted paths under `node` whose last part is `leaf`.
void findLeaf(const scene::json& node, const std::string& path, std::string_view leaf,
              std::vector<std::string>& found) {
  if (!node.is_object()) return;
  for (const auto& [k, v] : node.items()) {
    const std::string p = path + "." + k;
    if (k == leaf) found.push_back(p);
    findLeaf(v, p, leaf, found);
  }
}

std::optional<std::string> sceneKeyValue(const scene::json& effective, const SceneParams& scene,
                                         std::string_view name, const std::string& key) {
  const scene::json* v = atPath(effective, name);
  if (!v && name.find('.') == std::string_view::npos) {
    const std::string section = choiceName(scene.solver);
    std::vector<std::string> found;
    if (effective.contains(section)) findLeaf(effective[section], section, name, found);
    if (found.size() > 1) {
      std::string list;
      for (const std::string& f : found) list += (list.empty() ? "" : ", ") + f;
      throw ParamError(key, "{" + std::string(name) + "} names several keys (" + list +
                                "): give the dotted path, e.g. {" + found.front() + "}");
    }
    if (found.size() == 1) v = atPath(effective, found.front());
  }
  if (!v) return std::nullopt;
  if (v->is_null())
    throw ParamError(key, "{" + std::string(name) + "} has no value in this scene (the key is "
                          "not set); set it or leave it out of the title");
  if (v->is_object()) return std::nullopt;
  return valueText(*v);
}

}  // namespace

std::string fieldUnits(std::string_view field) {
  const auto it = unitsByField().find(field);
  return it == unitsByField().end() ? "1" : it->second;
}

std::string legendTitleOf(std::string_view field) { return legendTitleOf(field, field); }

std::string legendTitleOf(std::string_view shown, std::string_view field) {
  return std::string(shown) + " (" + fieldUnits(field) + ")";
}

std::string pictureTitle(const SceneParams& scene, const std::string& key,
                         const std::string& titleTemplate, const PictureSubject& subject) {
  if (titleTemplate.empty()) return "";
  const scene::json effective = effectiveScene(scene);
  const PlaceholderLookup lookup = [&](std::string_view name) -> std::optional<std::string> {
    if (name == "name") return scene.name;
    if (name == "field") return subject.field;
    if (name == "units") return fieldUnits(subject.field);
    if (name == "time") return formatNumber(withoutRoundOff(subject.time), 4);
    if (name == "solver") return choiceName(scene.solver);
    return sceneKeyValue(effective, scene, name, key);
  };
  try {
    return expandPlaceholders(titleTemplate, lookup);
  } catch (const std::invalid_argument& e) {
    throw ParamError(key, "is \"" + titleTemplate + "\": " + e.what() + "; " +
                              kTitlePlaceholderHelp);
  }
}

void validatePictureTitles(const SceneParams& scene) {
  const auto& images = scene.output.images;
  for (std::size_t i = 0; i < images.size(); ++i)
    pictureTitle(scene, "output.images[" + std::to_string(i) + "].title", images[i].title,
                 {choiceName(images[i].field), 0.0});
  const auto& views = scene.output.views;
  for (std::size_t i = 0; i < views.size(); ++i)
    pictureTitle(scene, "output.views[" + std::to_string(i) + "].title", views[i].title,
                 {views[i].particles.color_by, 0.0});
  const auto& probes = scene.output.probes;
  for (std::size_t i = 0; i < probes.size(); ++i)
    pictureTitle(scene, "output.probes[" + std::to_string(i) + "].title", probes[i].title,
                 {choiceName(probes[i].field), 0.0});
  const auto& lic = scene.output.lic;
  for (std::size_t i = 0; i < lic.size(); ++i)
    pictureTitle(scene, "output.lic[" + std::to_string(i) + "].title", lic[i].title,
                 {lic[i].color_by, 0.0});
}

}  // namespace fluidviz
