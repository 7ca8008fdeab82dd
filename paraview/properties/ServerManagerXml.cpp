#include "paraview/properties/ServerManagerXml.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "fieldviz/core/XmlText.h"

namespace fluidviz::paraview {

using scene::json;
using scene::ParamKind;
using scene::ParamRow;

namespace {

// Round-trips every double (ParaView reads default_values with strtod).
std::string exactNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string labelOf(const ParamRow& row) {
  std::string label;
  bool upper = true;
  for (char c : row.key) {
    if (c == '_' || c == '.') {
      label += ' ';
      upper = true;
      continue;
    }
    label += upper ? char(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  // No unit here: paraview.simple names a property after its label without spaces, and that
  // name must be propertyName(key). The unit is in the documentation (the GUI's tooltip).
  return label;
}

std::string documentation(const ParamRow& row, const std::string& sceneSection) {
  std::string text = row.info.description;
  if (!row.info.unit.empty()) text += ". Unit: " + row.info.unit;
  const std::string range = describeRange(row.info);
  if (!range.empty()) text += ". Allowed: " + range;
  // A filter whose keys are no scene section of their own (resample's are spread over
  // output.grids[] and its kin, some only in the CLI) names the declared key alone.
  text += sceneSection.empty() ? ". Key: " + row.key + "."
                               : ". Scene key: " + sceneSection + "." + row.key + ".";
  return "        <Documentation>" + xmlEscaped(text) + "</Documentation>\n";
}

std::string rangeDomain(const char* domain, const ParamInfo& info) {
  std::string attributes;
  if (std::isfinite(info.min)) attributes += " min=\"" + exactNumber(info.min) + "\"";
  if (std::isfinite(info.max)) attributes += " max=\"" + exactNumber(info.max) + "\"";
  if (attributes.empty()) return "";
  return std::string("        <") + domain + " name=\"range\"" + attributes + "/>\n";
}

std::string property(const char* type, const std::string& name, const std::string& label,
                     const std::string& command, const std::string& key,
                     const std::string& defaults, const std::string& body, int elements = 1) {
  return std::string("      <") + type + " name=\"" + name + "\" label=\"" + xmlEscaped(label) +
         "\" command=\"" + command + "\" initial_string=\"" + xmlEscaped(key) +
         "\" number_of_elements=\"" + std::to_string(elements) + "\" default_values=\"" +
         xmlEscaped(defaults) + "\">\n" + body + "      </" + type + ">\n";
}

// "1 2 3": the elements of an array default.
std::string exactNumbers(const json& values) {
  std::string text;
  for (const json& v : values) text += (text.empty() ? "" : " ") + exactNumber(v.get<double>());
  return text;
}

int choiceIndex(const ParamRow& row) {
  for (std::size_t i = 0; i < row.info.choices.size(); ++i)
    if (row.defaultValue == row.info.choices[i]) return int(i);
  return 0;
}

std::string choiceDomain(const ParamRow& row) {
  std::string entries = "        <EnumerationDomain name=\"enum\">\n";
  for (std::size_t i = 0; i < row.info.choices.size(); ++i)
    entries += "          <Entry value=\"" + std::to_string(i) + "\" text=\"" +
               xmlEscaped(row.info.choices[i]) + "\"/>\n";
  return entries + "        </EnumerationDomain>\n";
}

std::string parameterProperty(const ParamRow& row, const std::string& sceneSection) {
  const std::string name = propertyName(row.key);
  const std::string doc = documentation(row, sceneSection);
  switch (row.kind) {
    case ParamKind::number:
      return property("DoubleVectorProperty", name, labelOf(row), "SetNumberParameter", row.key,
                      exactNumber(row.defaultValue.get<double>()),
                      rangeDomain("DoubleRangeDomain", row.info) + doc);
    case ParamKind::optional_number: {
      const double shown = row.defaultValue.is_number() ? row.defaultValue.get<double>() : 0.0;
      return property("IntVectorProperty", name + "Given", "Set " + labelOf(row),
                      "SetParameterGiven", row.key, row.defaultValue.is_number() ? "1" : "0",
                      "        <BooleanDomain name=\"bool\"/>\n" + doc) +
             property("DoubleVectorProperty", name, labelOf(row), "SetNumberParameter", row.key,
                      exactNumber(shown), rangeDomain("DoubleRangeDomain", row.info) + doc);
    }
    case ParamKind::integer:
      return property("IntVectorProperty", name, labelOf(row), "SetIntegerParameter", row.key,
                      std::to_string(row.defaultValue.get<int>()),
                      rangeDomain("IntRangeDomain", row.info) + doc);
    case ParamKind::flag:
      return property("IntVectorProperty", name, labelOf(row), "SetFlagParameter", row.key,
                      row.defaultValue.get<bool>() ? "1" : "0",
                      "        <BooleanDomain name=\"bool\"/>\n" + doc);
    case ParamKind::choice:
      return property("IntVectorProperty", name, labelOf(row), "SetChoiceParameter", row.key,
                      std::to_string(choiceIndex(row)), choiceDomain(row) + doc);
    case ParamKind::text:
      return property("StringVectorProperty", name, labelOf(row), "SetTextParameter", row.key,
                      row.defaultValue.get<std::string>(), doc);
    case ParamKind::numbers: {
      if (!offeredArraySize(int(row.defaultValue.size()))) break;
      // One call with all elements: SetNumbers<N>Parameter(key, x0, ..., xN-1).
      const int n = int(row.defaultValue.size());
      return property("DoubleVectorProperty", name, labelOf(row), numbersCommand(n), row.key,
                      exactNumbers(row.defaultValue),
                      rangeDomain("DoubleRangeDomain", row.info) + doc, n);
    }
    case ParamKind::list:
      break;
  }
  return "";
}

std::string inputProperties(const ProxyInput& input) {
  if (input.dataType.empty()) return "";
  std::string xml =
      "      <InputProperty name=\"Input\" command=\"SetInputConnection\">\n"
      "        <ProxyGroupDomain name=\"groups\">\n"
      "          <Group name=\"sources\"/>\n"
      "          <Group name=\"filters\"/>\n"
      "        </ProxyGroupDomain>\n"
      "        <DataTypeDomain name=\"input_type\">\n"
      "          <DataType value=\"" + input.dataType + "\"/>\n"
      "        </DataTypeDomain>\n";
  if (!input.arrayAttribute.empty())
    xml += "        <InputArrayDomain name=\"input_array\" attribute_type=\"point\"/>\n";
  xml += "      </InputProperty>\n";
  if (input.arrayAttribute.empty()) return xml;
  return xml +
         "      <StringVectorProperty name=\"SelectInput" + input.arrayAttribute +
         "\" label=\"Input " + input.arrayAttribute + "\" command=\"SetInputArrayToProcess\" number_of_elements=\"5\" "
         "element_types=\"0 0 0 0 2\" animateable=\"0\">\n"
         "        <ArrayListDomain name=\"array_list\" attribute_type=\"" + input.arrayAttribute +
         "\" input_domain_name=\"input_array\">\n"
         "          <RequiredProperties>\n"
         "            <Property name=\"Input\" function=\"Input\"/>\n"
         "          </RequiredProperties>\n"
         "        </ArrayListDomain>\n"
         "        <Documentation>The point array the filter reads.</Documentation>\n"
         "      </StringVectorProperty>\n";
}

std::string notOffered(const std::vector<ParamRow>& rows) {
  std::string keys;
  for (const ParamRow& row : rows)
    if (row.kind == ParamKind::list || (row.kind == ParamKind::numbers &&
                                        !offeredArraySize(int(row.defaultValue.size()))))
      keys += (keys.empty() ? "" : ", ") + row.key;
  return keys.empty() ? "" : " Scene keys without a property here (lists): " + keys + ".";
}

std::string proxyXml(const ProxyDescription& p) {
  std::string xml = "    <SourceProxy name=\"" + p.name + "\" class=\"" + p.vtkClass +
                    "\" label=\"" + xmlEscaped(p.label) + "\">\n" +
                    "      <Documentation short_help=\"" + xmlEscaped(p.label) + "\">" +
                    xmlEscaped(p.help + notOffered(p.params)) + "</Documentation>\n" +
                    inputProperties(p.input);
  for (const ParamRow& row : p.params) xml += parameterProperty(row, p.sceneSection);
  for (std::size_t i = 0; i < p.outputPorts.size(); ++i)
    xml += "      <OutputPort name=\"" + xmlEscaped(p.outputPorts[i]) + "\" index=\"" +
           std::to_string(i) + "\"/>\n";
  return xml +
         "      <Hints>\n"
         "        <ShowInMenu category=\"fluidviz\"/>\n"
         "      </Hints>\n"
         "    </SourceProxy>\n";
}

}  // namespace

std::string numbersCommand(int elements) {
  return "SetNumbers" + std::to_string(elements) + "Parameter";
}

std::string propertyName(const std::string& key) {
  std::string name;
  bool upper = true;
  for (char c : key) {
    if (c == '_' || c == '.') {
      upper = true;
      continue;
    }
    name += upper ? char(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return name;
}

std::string serverManagerXml(const std::vector<ProxyDescription>& proxies) {
  std::string filters, sources;
  for (const ProxyDescription& p : proxies)
    (p.input.dataType.empty() ? sources : filters) += proxyXml(p);
  std::string xml = "<ServerManagerConfiguration>\n";
  if (!filters.empty()) xml += "  <ProxyGroup name=\"filters\">\n" + filters + "  </ProxyGroup>\n";
  if (!sources.empty()) xml += "  <ProxyGroup name=\"sources\">\n" + sources + "  </ProxyGroup>\n";
  return xml + "</ServerManagerConfiguration>\n";
}

}  // namespace fluidviz::paraview
